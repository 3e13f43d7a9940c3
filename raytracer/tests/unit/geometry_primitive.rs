//! Unit tests of `geometry/primitive.rs`.

use raytracer::geometry::primitive::*;
use raytracer::math::Vec3A;

#[test]
fn record_is_three_aligned_vectors() {
    assert_eq!(std::mem::size_of::<PrimRecord>(), 48);
    assert_eq!(std::mem::align_of::<PrimRecord>(), 16);
    assert_eq!(
        PrimRecord::quad(Vec3A::ZERO, Vec3A::X, Vec3A::Y).kind(),
        KIND_QUAD
    );
    let sphere = PrimRecord::sphere(Vec3A::new(0.0, 0.0, -3.0), 1.0);
    assert_eq!(sphere.kind(), KIND_SPHERE);
    let (t, _) = sphere
        .intersect(Vec3A::ZERO, -Vec3A::Z, f32::INFINITY)
        .unwrap();
    assert!((t - 2.0).abs() < 1e-6);
}
