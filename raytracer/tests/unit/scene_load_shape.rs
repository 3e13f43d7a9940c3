//! Unit tests of `scene/load/shape.rs`.

use raytracer::geometry::Shape;
use raytracer::math::Mat4;
use raytracer::math::{Color, Vec3, Vec3A};
use raytracer::scene::Emitter;
use raytracer::scene::format::ShapeDesc;
use raytracer::scene::load::{Context, SceneOrigin};
use raytracer::scene::load::{load_file, load_str};

fn origin() -> SceneOrigin {
    SceneOrigin::Dir {
        name: "test.toml".into(),
        dir: ".".into(),
    }
}

const CAMERA: &str = "[camera]\nposition = [0, 0, 5]\nlook_at = [0, 0, 1]\nfov = 40\n";

/// The transform of a shape given as TOML (only its placement fields).
fn transform_of(fields: &str) -> Mat4 {
    let desc: ShapeDesc =
        toml::from_str(&format!("type = \"cube\"\nmaterial = \"m\"\n{fields}")).unwrap();
    let o = origin();
    let cx = Context {
        text: "",
        origin: &o,
        name: String::new(),
    };
    cx.transform(&desc).unwrap().matrix
}

fn assert_mat(m: Mat4, rows: [[f32; 4]; 3]) {
    for (r, row) in rows.iter().enumerate() {
        for (c, &want) in row.iter().enumerate() {
            let got = m.col(c)[r];
            assert!(
                (got - want).abs() < 1e-6,
                "m[{r}][{c}] = {got}, want {want}"
            );
        }
    }
}

/// Scale, then rotate, then translate, exactly as Mitsuba's `to_world`
/// of the Cornell box's boxes (matrices from
/// raytracer/tests/data/cornell_box_mitsuba.txt).
#[test]
fn transforms_compose_as_mitsuba() {
    let small =
        transform_of("translate = [0.335, -0.7, 0.38]\nrotate = [0, 1, 0, -17]\nscale = 0.3");
    assert_mat(
        small,
        [
            [0.286_891, 0.0, -0.087_711_5, 0.335],
            [0.0, 0.3, 0.0, -0.7],
            [0.087_711_5, 0.0, 0.286_891, 0.38],
        ],
    );
    let large = transform_of(
        "translate = [-0.33, -0.4, -0.28]\nrotate = [0, 1, 0, 18.25]\nscale = [0.3, 0.61, 0.3]",
    );
    assert_mat(
        large,
        [
            [0.284_91, 0.0, 0.093_949_1, -0.33],
            [0.0, 0.61, 0.0, -0.4],
            [-0.093_949_1, 0.0, 0.284_91, -0.28],
        ],
    );
}

/// `rotate = [R1, R2]` applies R1 to the shape first: R = R2 · R1.
#[test]
fn rotations_apply_in_the_order_listed() {
    let m = transform_of("rotate = [[0, 0, 1, 90], [1, 0, 0, 90]]");
    // x → (z-rotation) y → (x-rotation) z.
    let p = m.transform_point3(Vec3::X);
    assert!((p - Vec3::Z).length() < 1e-6, "{p}");
    let one = transform_of("rotate = [0, 0, 1, 90]");
    assert!((one.transform_point3(Vec3::X) - Vec3::Y).length() < 1e-6);
}

/// Mitsuba's light rectangle of the Cornell box becomes the quad with its
/// world corners and normal −y.
#[test]
fn rectangle_becomes_a_quad_with_mitsubas_corners() {
    let text = format!(
        "{CAMERA}[materials.m]\ntype = \"lambert\"\nalbedo = 0.5\n\
         [[shapes]]\ntype = \"rectangle\"\nmaterial = \"m\"\nemission = 2\n\
         translate = [0, 0.99, 0.01]\nrotate = [1, 0, 0, 90]\nscale = [0.23, 0.19, 0.19]\n"
    );
    let parts = load_str(&text, &origin()).unwrap();
    let Shape::Quad(q) = parts.objects[0].shape else {
        panic!("a rectangle is a quad")
    };
    let close = |a: Vec3A, b: Vec3A| (a - b).length() < 1e-6;
    assert!(
        close(q.origin, Vec3A::new(-0.23, 0.99, -0.18)),
        "{}",
        q.origin
    );
    assert!(close(q.e1, Vec3A::new(0.46, 0.0, 0.0)), "{}", q.e1);
    assert!(close(q.e2, Vec3A::new(0.0, 0.0, 0.38)), "{}", q.e2);
    assert!(close(q.e1.cross(q.e2).normalize(), -Vec3A::Y));
    assert_eq!(
        parts.objects[0].emitter,
        Some(Emitter {
            radiance: Color::splat(2.0),
            two_sided: false
        })
    );
}

#[test]
fn a_mesh_next_to_the_scene_file_is_loaded_and_placed() {
    let dir = std::env::temp_dir().join(format!("scenefmt-mesh-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("tri.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").unwrap();
    let path = dir.join("s.toml");
    std::fs::write(
        &path,
        format!(
            "{CAMERA}[materials.m]\ntype = \"lambert\"\nalbedo = 0.5\n\
             [[shapes]]\ntype = \"mesh\"\nfile = \"tri.obj\"\nmaterial = \"m\"\ntranslate = [0, 0, 2]\n"
        ),
    )
    .unwrap();
    let parts = load_file(&path).unwrap();
    let Shape::Mesh(mesh) = &parts.objects[0].shape else {
        panic!("a mesh")
    };
    assert_eq!(mesh.indices.len(), 1);
    assert_eq!(mesh.positions[1], Vec3::new(1.0, 0.0, 2.0));
    std::fs::remove_dir_all(&dir).unwrap();
}
