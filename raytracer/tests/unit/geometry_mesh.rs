//! Unit tests of `geometry/mesh.rs`.

use raytracer::geometry::Transform;
use raytracer::geometry::mesh::*;
use raytracer::math::{Vec2, Vec3};

const QUAD_OBJ: &str = "\
# a unit square in z = 0, two objects
o first
v 0 0 0
v 1 0 0
v 1 1 0
vt 0 0
vt 1 0
vt 1 1
vn 0 0 1
f 1/1/1 2/2/1 3/3/1
o second
v 0 1 0
vt 0 1
f 1/1/1 3/3/1 4/4/1
";

#[test]
fn parses_obj_with_normals_and_uvs() {
    let m = Mesh::from_obj_str(QUAD_OBJ, "quad.obj").unwrap();
    assert_eq!(m.indices.len(), 2);
    assert_eq!(m.positions.len(), m.normals.len());
    assert_eq!(m.positions.len(), m.uvs.len());
    assert!(m.normals.iter().all(|&n| n == Vec3::Z));
    assert!((m.area() - 1.0).abs() < 1e-6);
    // Every vertex's uv equals its (x, y).
    for (p, t) in m.positions.iter().zip(&m.uvs) {
        assert_eq!(Vec2::new(p.x, p.y), *t);
    }
    // A quad face is triangulated.
    let m = Mesh::from_obj_str("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n", "q").unwrap();
    assert_eq!(m.indices.len(), 2);
    assert!(m.normals.is_empty() && m.uvs.is_empty());
}

#[test]
fn folders_and_devices_are_not_read_as_meshes() {
    let dir = std::env::temp_dir();
    let e = Mesh::load_obj(&dir).unwrap_err();
    assert!(e.message.contains("is a folder"), "{e}");
    let zero = std::path::Path::new("/dev/zero");
    if zero.exists() {
        let e = Mesh::load_obj(zero).unwrap_err();
        assert!(e.message.contains("not a regular file"), "{e}");
    }
}

#[test]
fn errors_name_the_file_and_the_problem() {
    let e = Mesh::load_obj(std::path::Path::new("/no/such/dir/bunny.obj")).unwrap_err();
    assert!(e.to_string().contains("/no/such/dir/bunny.obj"), "{e}");
    assert!(e.message.contains("cannot open"), "{e}");
    let e = Mesh::from_obj_str("this is not\nan obj file at all\n", "garbage.obj").unwrap_err();
    assert!(e.to_string().starts_with("garbage.obj: "), "{e}");
    let e = Mesh::from_obj_str("v 0 0 0\nv 1 0 0\nf 1 2 7\n", "range.obj").unwrap_err();
    assert!(
        e.to_string().contains("range.obj") && e.message.contains("out of"),
        "{e}"
    );
    let e = Mesh::from_obj_str("v 0 0 0\nv 1 0 0\nv 0 1 0\n", "empty.obj").unwrap_err();
    assert!(e.message.contains("no triangles"), "{e}");
    let e = Mesh::from_obj_str("v 0 0 0\nv 1 0 0\nv 0 inf 0\nf 1 2 3\n", "inf.obj").unwrap_err();
    assert!(e.message.contains("non-finite"), "{e}");
}

#[test]
fn cube_is_closed_with_outward_normals() {
    let c = Mesh::cube();
    assert_eq!((c.positions.len(), c.indices.len()), (24, 12));
    assert!((c.area() - 24.0).abs() < 1e-5);
    for &[a, b, d] in &c.indices {
        let (p0, p1, p2) = (
            c.positions[a as usize],
            c.positions[b as usize],
            c.positions[d as usize],
        );
        let n = (p1 - p0).cross(p2 - p0).normalize();
        let centre = (p0 + p1 + p2) / 3.0;
        // Outward: the normal is the face's axis, pointing the way of the centre.
        assert!((n - centre.round()).length() < 1e-6, "{n} at {centre}");
    }
}

#[test]
fn icosphere_counts_and_orientation() {
    for level in [0u32, 1, 3] {
        let m = Mesh::icosphere(level);
        assert_eq!(m.indices.len(), 20 * 4usize.pow(level));
        // Euler: V − E + F = 2 with E = 3F/2.
        assert_eq!(m.positions.len(), 2 + m.indices.len() / 2);
        for &[a, b, c] in &m.indices {
            let (p0, p1, p2) = (
                m.positions[a as usize],
                m.positions[b as usize],
                m.positions[c as usize],
            );
            assert!(
                (p1 - p0).cross(p2 - p0).dot(p0 + p1 + p2) > 0.0,
                "inward triangle"
            );
        }
    }
    let a = Mesh::icosphere(4).area();
    assert!(
        a < 4.0 * raytracer::math::PI && a > 0.99 * 4.0 * raytracer::math::PI,
        "{a}"
    );
}

#[test]
fn obj_round_trip_and_transform() {
    let m = Mesh::icosphere(1);
    let back = Mesh::from_obj_str(&m.to_obj_string(), "ico.obj").unwrap();
    // tobj renumbers vertices in order of first use: compare triangles.
    assert_eq!(back.indices.len(), m.indices.len());
    for (x, y) in back.indices.iter().zip(&m.indices) {
        for k in 0..3 {
            assert_eq!(back.positions[x[k] as usize], m.positions[y[k] as usize]);
            let dn = back.normals[x[k] as usize] - m.normals[y[k] as usize];
            assert!(dn.length() < 1e-6);
        }
    }
    let t = Transform::translate(Vec3::new(1.0, 0.0, 0.0))
        * Transform::scale(Vec3::new(-2.0, 2.0, 2.0));
    let w = m.transformed(&t);
    assert!((w.area() - 4.0 * m.area()).abs() < 1e-4);
    // The mirror keeps triangles facing outwards, like the normals.
    for (k, &[a, b, c]) in w.indices.iter().enumerate() {
        let (p0, p1, p2) = (
            w.positions[a as usize],
            w.positions[b as usize],
            w.positions[c as usize],
        );
        let ng = (p1 - p0).cross(p2 - p0);
        assert!(ng.dot(w.normals[a as usize]) > 0.0, "triangle {k}");
        assert!(ng.dot(p0 - Vec3::X) > 0.0, "triangle {k}");
    }
}
