//! Unit tests of `brdf/fresnel.rs`.

use raytracer::brdf::fresnel::*;
use raytracer::math::Vec3A;

#[test]
fn fresnel_known_values() {
    // Normal incidence: ((1.5 − 1)/(1.5 + 1))² = 0.04, from either side.
    assert!((fresnel_dielectric(1.0, 1.5) - 0.04).abs() < 1e-6);
    assert!((fresnel_dielectric(-1.0, 1.5) - 0.04).abs() < 1e-6);
    // Grazing incidence reflects everything.
    assert!(fresnel_dielectric(1e-4, 1.5) > 0.99);
    // Brewster's angle tan θ_B = η: r_∥ = 0, so F = r_⊥²/2.
    let theta_b = 1.5f32.atan();
    let c = theta_b.cos();
    let cos_t = (1.0 - theta_b.sin().powi(2) / 2.25).sqrt();
    let r_perp = (c - 1.5 * cos_t) / (c + 1.5 * cos_t);
    assert!((fresnel_dielectric(c, 1.5) - 0.5 * r_perp * r_perp).abs() < 1e-6);
    // Total internal reflection beyond the critical angle asin(1/1.5) ≈ 41.8°.
    let critical = (1.0f32 / 1.5).asin();
    assert_eq!(fresnel_dielectric(-(critical + 0.01).cos(), 1.5), 1.0);
    assert!(fresnel_dielectric(-(critical - 0.01).cos(), 1.5) < 1.0);
    // An index-matched interface reflects nothing.
    assert!(fresnel_dielectric(0.3, 1.0).abs() < 1e-7);
}

/// Reciprocity: F seen from outside at θ_i equals F seen from inside at θ_t.
#[test]
fn fresnel_is_the_same_from_both_sides() {
    for k in 1..50 {
        let cos_i = k as f32 / 50.0;
        let w = Vec3A::new((1.0 - cos_i * cos_i).sqrt(), 0.0, cos_i);
        let t = refract(w, 1.5).unwrap();
        let a = fresnel_dielectric(cos_i, 1.5);
        let b = fresnel_dielectric(t.z, 1.5);
        assert!((a - b).abs() < 1e-5, "cos {cos_i}: {a} vs {b}");
    }
}

#[test]
fn refraction_obeys_snell() {
    for &(z, eta) in &[
        (0.9f32, 1.5f32),
        (0.2, 1.5),
        (-0.95, 1.0 / 1.5),
        (0.5, 1.33),
    ] {
        let w = Vec3A::new(0.6, -0.8, 0.0) * (1.0 - z * z).sqrt() + Vec3A::new(0.0, 0.0, z);
        let t = refract(w, eta).unwrap();
        assert!((t.length() - 1.0).abs() < 1e-5);
        assert!(t.z * w.z < 0.0, "the refracted ray crosses the surface");
        let sin_i = (w.x * w.x + w.y * w.y).sqrt();
        let sin_t = (t.x * t.x + t.y * t.y).sqrt();
        assert!(
            (sin_i - eta * sin_t).abs() < 1e-5,
            "η_i sin θ_i = η_t sin θ_t"
        );
        // In the plane of w and the normal, on the other side of the normal.
        assert!((w.x * t.y - w.y * t.x).abs() < 1e-6);
        assert!(w.x * t.x + w.y * t.y <= 0.0);
    }
    // Beyond the critical angle from inside there is no refracted ray.
    assert!(refract(Vec3A::new(0.8, 0.0, -0.6), 1.0 / 1.5).is_none());
}
