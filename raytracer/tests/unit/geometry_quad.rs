//! Unit tests of `geometry/quad.rs`.

use raytracer::geometry::quad::*;
use raytracer::math::{Ray, Vec3A};

#[test]
fn hit_parameters_and_normal() {
    let q = Quad {
        origin: Vec3A::new(-1.0, -1.0, 0.0),
        e1: Vec3A::new(2.0, 0.0, 0.0),
        e2: Vec3A::new(0.0, 2.0, 0.0),
    };
    assert_eq!(q.normal(), Vec3A::Z);
    assert_eq!(q.area(), 4.0);
    let r = Ray::new(Vec3A::new(0.5, -0.5, 2.0), -Vec3A::Z);
    let (t, a, b) = q.intersect(&r).unwrap();
    assert!((t - 2.0).abs() < 1e-6 && (a - 0.75).abs() < 1e-6 && (b - 0.25).abs() < 1e-6);
    assert!((q.point(a, b) - r.at(t)).length() < 1e-6);
    // Both sides are hit; outside the edges or behind the origin is not.
    assert!(
        q.intersect(&Ray::new(Vec3A::new(0.0, 0.0, -2.0), Vec3A::Z))
            .is_some()
    );
    assert!(
        q.intersect(&Ray::new(Vec3A::new(1.1, 0.0, 2.0), -Vec3A::Z))
            .is_none()
    );
    assert!(
        q.intersect(&Ray::new(Vec3A::new(0.0, 0.0, 2.0), Vec3A::Z))
            .is_none()
    );
    assert!(
        q.intersect(&Ray::new(Vec3A::new(0.0, 0.0, 2.0), Vec3A::X))
            .is_none()
    );
}
