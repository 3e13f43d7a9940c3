//! Unit tests of `scene/builtin.rs`.

use raytracer::brdf::{Brdf, Lambert, Texture};
use raytracer::geometry::Shape;
use raytracer::light::Light;
use raytracer::math::{Color, Vec3A};
use raytracer::scene::SceneParts;
use raytracer::scene::builtin::*;
use raytracer::scene::load::SceneOrigin;
use raytracer::scene::load::{build, parse};

/// Loads a built-in scene without its cubes and meshes, for the tests
/// that only look at the rest (their quads, spheres, materials and lights;
/// [`every_builtin_loads`] loads everything).
fn load_without_meshes(name: &str) -> SceneParts {
    let scene = builtin(name).unwrap();
    let origin = SceneOrigin::Builtin(scene);
    let mut file = parse(scene.toml, &origin).unwrap();
    file.shapes
        .retain(|s| !matches!(s.get_ref().kind.get_ref().as_str(), "cube" | "mesh"));
    build(scene.toml, &origin, &file).unwrap()
}

#[test]
fn names_are_unique_and_every_scene_parses() {
    for (i, s) in BUILTIN_SCENES.iter().enumerate() {
        assert!(!s.description.is_empty());
        assert!(BUILTIN_SCENES[..i].iter().all(|o| o.name != s.name));
        assert_eq!(builtin(s.name).unwrap().toml, s.toml);
        parse(s.toml, &SceneOrigin::Builtin(s)).unwrap_or_else(|e| panic!("{e}"));
        // Everything except the meshes also passes the semantic checks.
        load_without_meshes(s.name);
    }
    for name in [
        "cornell",
        "furnace",
        "white-furnace",
        "caustic",
        "door",
        "stereo",
        "brdf-gallery",
        "veach-mis",
    ] {
        assert!(builtin(name).is_some(), "{name}");
    }
}

#[test]
fn every_builtin_loads() {
    for s in BUILTIN_SCENES {
        let parts = load_builtin(s.name).unwrap_or_else(|e| panic!("{e}"));
        assert!(!parts.objects.is_empty(), "{}", s.name);
    }
}

#[test]
fn unknown_builtin_lists_the_available_ones() {
    let e = load_builtin("cornel").unwrap_err();
    assert!(e.message.contains("unknown built-in scene `cornel`"), "{e}");
    assert!(e.message.contains("cornell, furnace, white-furnace"), "{e}");
    assert!(write_builtin("cornel", &std::env::temp_dir()).is_err());
}

/// The five walls and the light of `cornell` have Mitsuba's world
/// corners v0, v1, v2 (as origin, origin + e1, origin + e2) and normals
/// pointing into the box; the light also reflects (material white).
#[test]
fn cornell_quads_are_mitsubas() {
    let parts = load_without_meshes("cornell");
    let expected = [
        (
            "floor",
            [-1.0, -1.0, 1.0],
            [1.0, -1.0, 1.0],
            [-1.0, -1.0, -1.0],
            Vec3A::Y,
        ),
        (
            "ceiling",
            [-1.0, 1.0, -1.0],
            [1.0, 1.0, -1.0],
            [-1.0, 1.0, 1.0],
            -Vec3A::Y,
        ),
        (
            "back",
            [-1.0, -1.0, -1.0],
            [1.0, -1.0, -1.0],
            [-1.0, 1.0, -1.0],
            Vec3A::Z,
        ),
        (
            "green-wall",
            [1.0, -1.0, -1.0],
            [1.0, -1.0, 1.0],
            [1.0, 1.0, -1.0],
            -Vec3A::X,
        ),
        (
            "red-wall",
            [-1.0, -1.0, 1.0],
            [-1.0, -1.0, -1.0],
            [-1.0, 1.0, 1.0],
            Vec3A::X,
        ),
        (
            "light",
            [-0.23, 0.99, -0.18],
            [0.23, 0.99, -0.18],
            [-0.23, 0.99, 0.2],
            -Vec3A::Y,
        ),
    ];
    assert_eq!(parts.objects.len(), expected.len());
    for (object, (name, v0, v1, v2, normal)) in parts.objects.iter().zip(expected) {
        assert_eq!(object.name, name);
        let Shape::Quad(q) = object.shape else {
            panic!("{name} is a quad")
        };
        let close = |a: Vec3A, b: [f32; 3]| (a - Vec3A::from(b)).length() < 1e-6;
        assert!(close(q.origin, v0), "{name}: {}", q.origin);
        assert!(close(q.origin + q.e1, v1), "{name}: {}", q.origin + q.e1);
        assert!(close(q.origin + q.e2, v2), "{name}: {}", q.origin + q.e2);
        assert!(
            (q.e1.cross(q.e2).normalize() - normal).length() < 1e-6,
            "{name}"
        );
        let material = &parts.brdf_names[object.brdf as usize];
        let want = match name {
            "green-wall" => "green",
            "red-wall" => "red",
            _ => "white",
        };
        assert_eq!(material, want, "{name}");
    }
    let light = parts.objects.iter().find(|o| o.name == "light").unwrap();
    let emitter = light.emitter.unwrap();
    assert_eq!(emitter.radiance, Color::new(18.387, 13.9873, 6.75357));
    assert!(!emitter.two_sided);
    let Shape::Quad(q) = light.shape else {
        unreachable!()
    };
    assert!((q.e1.cross(q.e2).length() - 0.1748).abs() < 1e-6, "area");
    assert!(parts.objects.iter().filter(|o| o.emitter.is_some()).count() == 1);
}

#[test]
fn cornell_materials_camera_and_settings_are_mitsubas() {
    let parts = load_without_meshes("cornell");
    let albedo = |name: &str| {
        let i = parts.brdf_names.iter().position(|n| n == name).unwrap();
        // One-sided, as Mitsuba's `diffuse`: black from behind.
        let Brdf::OneSided(model) = &parts.brdfs[i] else {
            panic!("{name} is not one-sided: {:?}", parts.brdfs[i])
        };
        match model.as_ref() {
            Brdf::Lambert(Lambert {
                albedo: Texture::Constant(c),
            }) => *c,
            other => panic!("{other:?}"),
        }
    };
    assert_eq!(albedo("white"), Color::new(0.885809, 0.698859, 0.666422));
    assert_eq!(albedo("red"), Color::new(0.570068, 0.0430135, 0.0443706));
    assert_eq!(albedo("green"), Color::new(0.105421, 0.37798, 0.076425));
    let c = parts.camera;
    assert_eq!(c.position, Vec3A::new(0.0, 0.0, 3.9));
    assert_eq!(c.look_at, Vec3A::ZERO);
    assert_eq!(c.up, Vec3A::Y);
    assert_eq!(c.vfov_deg, 39.3077);
    assert_eq!(c.aperture_radius, 0.0);
    let s = parts.settings;
    assert_eq!((s.width, s.height, s.spp), (256, 256, 64));
    assert_eq!((s.max_depth, s.rr_depth), (None, 5));
    assert!(parts.lights.is_empty(), "no environment, no point light");
    // Both boxes are cubes with Mitsuba's transforms (checked in
    // unit::scene_load::transforms_compose_as_mitsuba against the matrices).
    let scene = builtin("cornell").unwrap();
    let file = parse(scene.toml, &SceneOrigin::Builtin(scene)).unwrap();
    let cubes: Vec<_> = file
        .shapes
        .iter()
        .filter(|s| s.get_ref().kind.get_ref() == "cube")
        .map(|s| s.get_ref().name.clone().unwrap())
        .collect();
    assert_eq!(cubes, ["small-box", "large-box"]);
}

/// The furnaces have the analytic set-ups their comments promise.
#[test]
fn furnaces_have_known_answers() {
    let parts = load_without_meshes("furnace");
    let [object] = &parts.objects[..] else {
        panic!("one sphere")
    };
    let Shape::Sphere(sphere) = object.shape else {
        panic!("a sphere")
    };
    assert_eq!((sphere.center, sphere.radius), (Vec3A::ZERO, 1.0));
    assert_eq!(parts.camera.position, Vec3A::ZERO, "inside the sphere");
    let e = object.emitter.unwrap();
    assert!(e.two_sided, "emits towards the inside");
    let Brdf::Lambert(Lambert {
        albedo: Texture::Constant(rho),
    }) = parts.brdfs[object.brdf as usize]
    else {
        panic!("lambert")
    };
    // L = Le / (1 − ρ) = 1.
    assert_eq!(e.radiance / (Color::ONE - rho), Color::ONE);
    assert_eq!(parts.settings.max_depth, None);

    let parts = load_without_meshes("white-furnace");
    assert!(matches!(
        parts.brdfs[parts.objects[0].brdf as usize],
        Brdf::Lambert(Lambert { albedo: Texture::Constant(c) }) if c == Color::ONE
    ));
    let [Light::Environment(env)] = &parts.lights[..] else {
        panic!("a constant environment")
    };
    assert_eq!(env.radiance, Color::ONE);
    assert_eq!(parts.settings.max_depth, None);
}

/// In `door`, the lamp is out of the camera's sight: every segment from
/// the camera to a point of the lamp crosses the wall at x = 0 on one of
/// its opaque panels.
#[test]
fn door_lamp_is_hidden_from_the_camera() {
    let parts = load_without_meshes("door");
    let quad = |name: &str| match parts.objects.iter().find(|o| o.name == name).unwrap().shape {
        Shape::Quad(q) => q,
        _ => panic!("{name} is a quad"),
    };
    let lamp = quad("lamp");
    let panels = ["divider-back", "divider-front", "lintel", "door"].map(quad);
    let eye = parts.camera.position;
    assert!(eye.x < 0.0 && lamp.origin.x > 0.0);
    // Does the segment eye → p cross the parallelogram q?
    let crosses = |q: &raytracer::geometry::Quad, p: Vec3A| {
        let d = p - eye;
        let n = q.e1.cross(q.e2);
        let t = (q.origin - eye).dot(n) / d.dot(n);
        if !(0.0..=1.0).contains(&t) {
            return false;
        }
        // Solve x − origin = a e1 + b e2 in the plane.
        let x = eye + t * d - q.origin;
        let (e11, e12, e22) = (q.e1.dot(q.e1), q.e1.dot(q.e2), q.e2.dot(q.e2));
        let (x1, x2) = (x.dot(q.e1), x.dot(q.e2));
        let det = e11 * e22 - e12 * e12;
        let a = (x1 * e22 - x2 * e12) / det;
        let b = (x2 * e11 - x1 * e12) / det;
        (0.0..=1.0).contains(&a) && (0.0..=1.0).contains(&b)
    };
    for i in 0..=10 {
        for j in 0..=10 {
            let p = lamp.origin + (i as f32 / 10.0) * lamp.e1 + (j as f32 / 10.0) * lamp.e2;
            assert!(
                panels.iter().any(|q| crosses(q, p)),
                "lamp point {p} is visible"
            );
        }
    }
}

/// In `veach-mis` every plate mirrors the row of lights towards the
/// camera (its normal bisects the directions from its centre to the
/// camera and to the lights' centre), and the four lights have equal
/// power (radiance × radius² = 1) and rising size.
#[test]
fn veach_plates_mirror_the_lights_and_the_lights_have_equal_power() {
    let parts = load_without_meshes("veach-mis");
    let eye = parts.camera.position;
    let mut exponents = Vec::new();
    let mut radii = Vec::new();
    for object in &parts.objects {
        match (&object.shape, object.emitter) {
            (Shape::Quad(q), None) => {
                let centre = q.origin + 0.5 * (q.e1 + q.e2);
                let half = ((eye - centre).normalize() + (-centre).normalize()).normalize();
                let normal = q.e1.cross(q.e2).normalize();
                assert!((normal - half).length() < 1e-4, "{}", object.name);
                let Brdf::Phong(p) = parts.brdfs[object.brdf as usize] else {
                    panic!("{} is glossy", object.name)
                };
                exponents.push(p.exponent);
            }
            (Shape::Sphere(s), Some(e)) => {
                let power = e.radiance.x * s.radius * s.radius;
                assert!((power - 1.0).abs() < 1e-3, "{}: {power}", object.name);
                radii.push(s.radius);
            }
            _ => panic!("{}: only plates and spherical lights", object.name),
        }
    }
    assert_eq!((exponents.len(), radii.len()), (4, 4));
    assert!(exponents.windows(2).all(|w| w[0] > w[1]), "{exponents:?}");
    assert!(radii.windows(2).all(|w| w[0] < w[1]), "{radii:?}");
}

#[test]
fn written_scene_loads_back_the_same() {
    let dir = std::env::temp_dir().join(format!("scenefmt-write-{}", std::process::id()));
    for name in ["furnace", "caustic", "brdf-gallery"] {
        let path = write_builtin(name, &dir).unwrap();
        assert_eq!(path, dir.join(format!("{name}.toml")));
        let from_disk = raytracer::scene::load_file(&path).unwrap();
        let built_in = load_builtin(name).unwrap();
        assert_eq!(from_disk.objects.len(), built_in.objects.len(), "{name}");
        assert_eq!(from_disk.brdf_names, built_in.brdf_names, "{name}");
        assert_eq!(from_disk.camera, built_in.camera, "{name}");
    }
    // A scene with a mesh writes its OBJ beside the TOML.
    write_builtin("stereo", &dir).unwrap();
    let obj = std::fs::read_to_string(dir.join("torus.obj")).unwrap();
    assert_eq!(obj, builtin("stereo").unwrap().assets[0].text);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn every_written_scene_loads_back_the_same() {
    let dir = std::env::temp_dir().join(format!("scenefmt-write-all-{}", std::process::id()));
    for s in BUILTIN_SCENES {
        let path = write_builtin(s.name, &dir).unwrap();
        let from_disk = raytracer::scene::load_file(&path).unwrap_or_else(|e| panic!("{e}"));
        let built_in = load_builtin(s.name).unwrap();
        assert_eq!(
            from_disk.objects.len(),
            built_in.objects.len(),
            "{}",
            s.name
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
