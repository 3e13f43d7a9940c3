//! Unit tests of `geometry/triangle.rs`.

use raytracer::geometry::primitive::{KIND_TRIANGLE, PrimRecord};
use raytracer::geometry::triangle::*;
use raytracer::math::Vec2;
use raytracer::math::Vec3A;

#[test]
fn triangle_hit_and_barycentrics() {
    let (v0, v1, v2) = (Vec3A::ZERO, Vec3A::X, Vec3A::Y);
    let o = Vec3A::new(0.25, 0.5, 1.0);
    let (t, b1, b2) = intersect_triangle(v0, v1, v2, o, -Vec3A::Z, 10.0).unwrap();
    assert!((t - 1.0).abs() < 1e-6 && (b1 - 0.25).abs() < 1e-6 && (b2 - 0.5).abs() < 1e-6);
    // Outside the hypotenuse, too far, parallel.
    let o2 = Vec3A::new(0.6, 0.6, 1.0);
    assert!(intersect_triangle(v0, v1, v2, o2, -Vec3A::Z, 10.0).is_none());
    assert!(intersect_triangle(v0, v1, v2, o, -Vec3A::Z, 0.5).is_none());
    assert!(intersect_triangle(v0, v1, v2, o, Vec3A::X, 10.0).is_none());
    let rec = PrimRecord::triangle(v0, v1, v2);
    assert_eq!(rec.kind(), KIND_TRIANGLE);
    let (t2, uv) = rec.intersect(o, -Vec3A::Z, 10.0).unwrap();
    assert_eq!((t2, uv), (t, Vec2::new(b1, b2)));
}

/// A ray through the shared edge of two triangles hits at least one.
#[test]
fn shared_edges_are_watertight() {
    let (p, q) = (Vec3A::new(0.1, 0.2, 0.3), Vec3A::new(0.9, 0.7, 0.35));
    let (l, r) = (Vec3A::new(0.0, 1.0, 0.3), Vec3A::new(1.0, -0.2, 0.31));
    let mut s = raytracer::sampling::Sampler::new(1, 2, 3);
    for _ in 0..20_000 {
        let e = p + s.next_1d() * (q - p);
        let o = Vec3A::new(s.next_1d(), s.next_1d(), 2.0 + s.next_1d());
        let d = (e - o).normalize();
        let left = intersect_triangle(p, q, l, o, d, f32::INFINITY);
        let right = intersect_triangle(q, p, r, o, d, f32::INFINITY);
        assert!(
            left.is_some() || right.is_some(),
            "ray to {e} slipped through"
        );
    }
}
