//! Unit tests of `polygon.rs`.

use grading::polygon::*;
use raytracer::math::Vec3A;

/// Lambert's formula against the quadrature of `L cos θ_x cos θ_y / r²`
/// over the light (a 1000×1000 grid), and against the limit of a small
/// distant light, `E → L A / h²`.
#[test]
fn contour_formula_matches_the_area_integral() {
    let (origin, e1, e2) = (
        Vec3A::new(0.5, 1.0, -0.5),
        Vec3A::new(1.0, 0.0, 0.0),
        Vec3A::new(0.0, 0.0, 1.0),
    );
    for (x, n) in [
        (Vec3A::ZERO, Vec3A::Y),
        (
            Vec3A::new(0.3, 0.2, 0.1),
            Vec3A::new(0.3, 1.0, 0.1).normalize(),
        ),
    ] {
        let exact = irradiance(x, n, &corners(origin, e1, e2), 2.0);
        let ny = d(e1.cross(e2).normalize());
        let quad = integrate_over_quad(origin, e1, e2, 1000, |y| {
            let v = y - d(x);
            let r2 = v.length_squared();
            let w = v / r2.sqrt();
            2.0 * w.dot(d(n)) * (-w).dot(ny).abs() / r2
        });
        assert!((exact - quad).abs() < 1e-5 * exact, "{exact} vs {quad}");
    }
    // A unit square centred above x at height h, in the limit of a
    // distant light: E → L · A / h².
    let far = irradiance(
        Vec3A::ZERO,
        Vec3A::Y,
        &corners(
            Vec3A::new(-0.005, 1.0, -0.005),
            Vec3A::X * 0.01,
            Vec3A::Z * 0.01,
        ),
        1.0,
    );
    assert!((far - 1e-4).abs() < 1e-8, "{far}");
}

#[test]
fn projection_from_a_point_onto_a_plane() {
    let p = project_from(
        Vec3A::ZERO,
        Vec3A::new(0.1, 0.5, 0.2),
        Vec3A::new(0.0, 1.0, 0.0),
        Vec3A::Y,
    );
    assert!((p - Vec3A::new(0.2, 1.0, 0.4)).length() < 1e-6);
}
