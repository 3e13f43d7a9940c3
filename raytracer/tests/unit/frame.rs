//! Unit tests of `frame.rs`.

use raytracer::frame::*;
use raytracer::math::Vec3A;

#[test]
fn round_trip_and_orthonormality() {
    for n in [
        Vec3A::Z,
        -Vec3A::Z,
        Vec3A::new(0.3, -0.4, 0.866).normalize(),
        Vec3A::X,
    ] {
        let f = Frame::from_normal(n);
        assert!((f.s.dot(f.t)).abs() < 1e-6 && (f.s.dot(f.n)).abs() < 1e-6);
        assert!((f.s.cross(f.t) - f.n).length() < 1e-5, "right-handed");
        let v = Vec3A::new(0.2, 0.5, -0.7);
        assert!((f.to_world(f.to_local(v)) - v).length() < 1e-6);
        assert!((f.to_local(n) - Vec3A::Z).length() < 1e-6);
        let g = f.flipped();
        assert!((g.s.cross(g.t) - g.n).length() < 1e-5);
    }
}
