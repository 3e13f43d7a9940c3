//! Unit tests of `geometry/sphere.rs`.

use raytracer::geometry::sphere::*;
use raytracer::math::{PI, Ray, Vec3A};

#[test]
fn hits_front_then_back() {
    let s = Sphere {
        center: Vec3A::new(0.0, 0.0, -5.0),
        radius: 1.0,
    };
    let r = Ray::new(Vec3A::ZERO, -Vec3A::Z);
    assert!((s.intersect(&r).unwrap() - 4.0).abs() < 1e-6);
    // From inside: the far side.
    let r = Ray::new(Vec3A::new(0.0, 0.0, -5.0), -Vec3A::Z);
    assert!((s.intersect(&r).unwrap() - 1.0).abs() < 1e-6);
    // Too short, pointing away, passing beside.
    let r = Ray {
        t_max: 3.9,
        ..Ray::new(Vec3A::ZERO, -Vec3A::Z)
    };
    assert!(s.intersect(&r).is_none());
    assert!(s.intersect(&Ray::new(Vec3A::ZERO, Vec3A::Z)).is_none());
    assert!(
        s.intersect(&Ray::new(Vec3A::new(1.01, 0.0, 0.0), -Vec3A::Z))
            .is_none()
    );
    assert!((s.area() - 4.0 * PI).abs() < 1e-5);
}

#[test]
fn far_small_sphere_is_precise() {
    // |f|² = 1e8 and r² = 1e-4: the naive discriminant loses every digit.
    let s = Sphere {
        center: Vec3A::new(0.0, 0.0, -1e4),
        radius: 0.01,
    };
    let t = s
        .intersect(&Ray::new(Vec3A::new(0.005, 0.0, 0.0), -Vec3A::Z))
        .unwrap();
    let expect = 1e4 - (0.01f64 * 0.01 - 0.005 * 0.005).sqrt();
    assert!((t as f64 - expect).abs() < 2e-3, "{t} vs {expect}");
}

#[test]
fn uv_of_poles_and_equator() {
    assert!(Sphere::uv(Vec3A::Y).y < 1e-6);
    assert!((Sphere::uv(-Vec3A::Y).y - 1.0).abs() < 1e-6);
    let e = Sphere::uv(Vec3A::Z);
    assert!((e.x - 0.25).abs() < 1e-6 && (e.y - 0.5).abs() < 1e-6);
    let w = Sphere::uv(-Vec3A::X);
    assert!((w.x - 0.5).abs() < 1e-6);
}
