//! Unit tests of `geometry/aabb.rs`.

use raytracer::geometry::aabb::*;
use raytracer::math::Vec3A;

#[test]
fn union_grow_area_centroid() {
    let mut b = Aabb::EMPTY;
    assert!(b.is_empty());
    assert_eq!(b.surface_area(), 0.0);
    b.grow(Vec3A::new(0.0, 0.0, 0.0));
    b.grow(Vec3A::new(1.0, 2.0, 3.0));
    assert_eq!(b.surface_area(), 2.0 * (2.0 + 6.0 + 3.0));
    assert_eq!(b.centroid(), Vec3A::new(0.5, 1.0, 1.5));
    assert_eq!(b.largest_axis(), 2);
    let u = b.union(Aabb::from_point(Vec3A::new(-1.0, 5.0, 0.0)));
    assert_eq!(u.min, Vec3A::new(-1.0, 0.0, 0.0));
    assert_eq!(u.max, Vec3A::new(1.0, 5.0, 3.0));
    assert_eq!(Aabb::EMPTY.union(b), b);
    assert!(u.contains(Vec3A::new(0.0, 4.0, 1.0)));
    assert!(!u.contains(Vec3A::new(0.0, 6.0, 1.0)));
}

#[test]
fn slab_test() {
    let b = Aabb::new(Vec3A::splat(-1.0), Vec3A::splat(1.0));
    let o = Vec3A::new(0.0, 0.0, 5.0);
    let d = Vec3A::new(0.0, 0.0, -1.0);
    let (near, far) = b.intersect_ray(o, d.recip(), 0.0, f32::INFINITY).unwrap();
    assert!((near - 4.0).abs() < 1e-6 && (far - 6.0).abs() < 1e-6);
    // Too short a ray, a ray pointing away and a ray passing beside miss.
    assert!(b.intersect_ray(o, d.recip(), 0.0, 3.9).is_none());
    assert!(
        b.intersect_ray(o, (-d).recip(), 0.0, f32::INFINITY)
            .is_none()
    );
    let beside = Vec3A::new(1.5, 0.0, 5.0);
    assert!(
        b.intersect_ray(beside, d.recip(), 0.0, f32::INFINITY)
            .is_none()
    );
    // From inside, the interval starts at t_min.
    let (near, _) = b
        .intersect_ray(Vec3A::ZERO, d.recip(), 0.0, f32::INFINITY)
        .unwrap();
    assert_eq!(near, 0.0);
}

/// Zero components give ±1e30 with the sign of the zero, and the entry
/// side follows that sign; a ray along an axis, starting inside the
/// other slabs, enters the box.
#[test]
fn inverse_direction_keeps_the_sign_of_zero() {
    let down = InverseDirection::new(-Vec3A::Y);
    assert_eq!(down.inv_d, Vec3A::new(-1e30, -1.0, -1e30));
    assert_eq!(down.negative, [1, 1, 1]);
    let up = InverseDirection::new(Vec3A::Y);
    assert_eq!(up.inv_d, Vec3A::new(1e30, 1.0, 1e30));
    assert_eq!(up.negative, [0, 0, 0]);
    let b = Aabb::new(Vec3A::splat(-1.0), Vec3A::splat(1.0));
    let o = Vec3A::new(0.3, 5.0, 0.2);
    let (near, far) = b.intersect_ray(o, down.inv_d, 0.0, f32::INFINITY).unwrap();
    assert_eq!((near, far), (4.0, 6.0));
}
