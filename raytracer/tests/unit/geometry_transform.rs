//! Unit tests of `geometry/transform.rs`.

use raytracer::geometry::transform::*;
use raytracer::math::Vec3;
use raytracer::math::Vec3A;

fn close(a: Vec3A, b: Vec3A) -> bool {
    (a - b).abs().max_element() < 2e-6
}

/// Mitsuba's Cornell box (raytracer/tests/data/cornell_box_mitsuba.txt,
/// section 4): the boxes are `translate · rotate · scale` of `[-1, 1]³`.
#[test]
fn mitsuba_box_corners() {
    let small = Transform::translate(Vec3::new(0.335, -0.7, 0.38))
        * Transform::rotate(Vec3::Y, -17.0)
        * Transform::scale(Vec3::splat(0.3));
    let c = small.apply_point(Vec3A::splat(-1.0));
    assert!(close(c, Vec3A::new(0.13582, -1.0, 0.005397)), "{c}");
    let c = small.apply_point(Vec3A::new(1.0, -1.0, 1.0));
    assert!(close(c, Vec3A::new(0.53418, -1.0, 0.754603)), "{c}");
    // large-box: matrix given by the reference (translate (-0.33,-0.4,-0.28),
    // rotate 18.25° about y, scale (0.3, 0.61, 0.3)).
    let large = Transform::translate(Vec3::new(-0.33, -0.4, -0.28))
        * Transform::rotate(Vec3::Y, 18.25)
        * Transform::scale(Vec3::new(0.3, 0.61, 0.3));
    let c = large.apply_point(Vec3A::new(1.0, 1.0, -1.0));
    assert!(close(c, Vec3A::new(-0.139039, 0.21, -0.658859)), "{c}");
    let c = large.apply_point(Vec3A::splat(-1.0));
    assert!(close(c, Vec3A::new(-0.708859, -1.01, -0.470961)), "{c}");
    // Outward normal of face 2 of the small box (local +x).
    let n = small.apply_normal(Vec3A::X);
    assert!(close(n, Vec3A::new(0.956305, 0.0, 0.292372)), "{n}");
}

#[test]
fn normals_stay_perpendicular_and_inverse_undoes() {
    let t = Transform::translate(Vec3::new(1.0, 2.0, 3.0))
        * Transform::rotate(Vec3::new(1.0, 1.0, 0.0), 30.0)
        * Transform::scale(Vec3::new(2.0, 0.5, 1.0));
    let tangent = Vec3A::new(1.0, -1.0, 0.5);
    let n = Vec3A::new(1.0, 1.0, 0.0).normalize();
    assert!(tangent.dot(n).abs() < 1e-6);
    let (tw, nw) = (t.apply_vector(tangent), t.apply_normal(n));
    assert!(tw.dot(nw).abs() < 1e-5);
    assert!((nw.length() - 1.0).abs() < 1e-6);
    let p = Vec3A::new(0.3, -0.2, 4.0);
    assert!(close(t.inverse().apply_point(t.apply_point(p)), p));
    assert!(!t.flips_handedness());
    assert!(Transform::scale(Vec3::new(-1.0, 1.0, 1.0)).flips_handedness());
}
