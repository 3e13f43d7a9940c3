//! Unit tests of `brdf/glass.rs`.

use super::brdf_testing::{CHI2_TESTS, directional_albedo};
use raytracer::brdf::Brdf;
use raytracer::brdf::TransportMode;
use raytracer::brdf::fresnel::fresnel_dielectric;
use raytracer::brdf::glass::*;
use raytracer::math::Vec2;
use raytracer::math::{Color, Vec3A};
use raytracer::sampling::Sampler;
use raytracer::sampling::chi2::chi2_frequencies;

fn glass() -> Glass {
    Glass {
        ior: 1.5,
        tint: Color::ONE,
    }
}

fn dir(theta_deg: f32) -> Vec3A {
    let t = theta_deg.to_radians();
    Vec3A::new(t.sin() * 0.6, t.sin() * 0.8, t.cos())
}

/// The lobe choice: over 2^17 samples the number of reflections must follow
/// F, tested by a chi-square test on the two outcomes (α = 0.01 over the
/// whole brdf suite, see `testing::CHI2_TESTS`).
#[test]
fn reflection_is_chosen_with_probability_fresnel() {
    let g = glass();
    let n = 1 << 17;
    for theta in [0.0f32, 45.0, 80.0, 180.0 - 20.0, 180.0 - 40.0, 180.0 - 60.0] {
        let wo = dir(theta);
        let f = fresnel_dielectric(wo.z, g.ior) as f64;
        let mut counts = [0u64; 2];
        for i in 0..n {
            let mut s = Sampler::new(11, i, 0);
            let ul = s.next_1d();
            let bs = g.sample(wo, ul, TransportMode::Radiance).unwrap();
            counts[if bs.wi.z * wo.z > 0.0 { 0 } else { 1 }] += 1;
        }
        let r = chi2_frequencies(&counts, &[f, 1.0 - f], 0.01, CHI2_TESTS);
        assert!(r.is_ok(), "θ_o = {theta}°: {}", r.unwrap_err());
    }
    // A wrong choice (refraction taken with probability F) is caught.
    let wo = dir(80.0);
    let f = fresnel_dielectric(wo.z, g.ior) as f64;
    let mut counts = [0u64; 2];
    for i in 0..n {
        let ul = Sampler::new(11, i, 0).next_1d();
        counts[if (ul as f64) < f { 1 } else { 0 }] += 1;
    }
    assert!(chi2_frequencies(&counts, &[f, 1.0 - f], 0.01, CHI2_TESTS).is_err());
}

/// In importance mode reflection and refraction together carry exactly the
/// energy that arrives: `f_R |cos| + f_T |cos| = F + (1 − F) = 1`, and each
/// sample's weight `f |cos| / pdf` is the tint. In radiance mode the
/// refracted weight is `1/η²`.
#[test]
fn energy_is_preserved() {
    let g = Glass {
        ior: 1.5,
        tint: Color::new(1.0, 0.9, 0.5),
    };
    for theta in [0.0f32, 30.0, 60.0, 89.0, 150.0, 170.0] {
        let wo = dir(theta);
        let r = g.sample(wo, 0.0, TransportMode::Importance).unwrap();
        let t = g.sample(wo, 0.999_999, TransportMode::Importance).unwrap();
        assert!(r.wi.z * wo.z > 0.0 && t.wi.z * wo.z < 0.0);
        let sum = r.f * r.wi.z.abs() + t.f * t.wi.z.abs();
        assert!(
            (sum - g.tint).abs().max_element() < 1e-5,
            "θ {theta}: {sum}"
        );
        for s in [r, t] {
            assert!((s.f * s.wi.z.abs() / s.pdf_w - g.tint).abs().max_element() < 1e-5);
            assert!(s.is_delta);
        }
        let tr = g.sample(wo, 0.999_999, TransportMode::Radiance).unwrap();
        let w = tr.f * tr.wi.z.abs() / tr.pdf_w;
        let expect = g.tint / (tr.eta * tr.eta);
        assert!((w - expect).abs().max_element() < 1e-5, "θ {theta}: {w}");
        assert_eq!(tr.eta, if wo.z > 0.0 { 1.5 } else { 1.0 / 1.5 });
    }
    // The Monte Carlo albedo through the enum: every sample weighs the tint.
    let brdf = Brdf::Glass(g);
    for theta in [0.0f32, 70.0, 135.0] {
        let (mean, se) = directional_albedo(dir(theta), 4096, 5, |wo, ul, u| {
            brdf.sample(wo, Vec2::ZERO, ul, u, TransportMode::Importance)
        });
        assert!((mean - g.tint).abs().max_element() < 1e-5 && se.max_element() < 1e-5);
    }
}

#[test]
fn refraction_follows_snell_and_tir_reflects_everything() {
    let g = glass();
    for theta in [10.0f32, 50.0, 85.0, 180.0 - 30.0] {
        let wo = dir(theta);
        let t = g.sample(wo, 0.999_999, TransportMode::Radiance).unwrap();
        let sin_o = (wo.x * wo.x + wo.y * wo.y).sqrt();
        let sin_i = (t.wi.x * t.wi.x + t.wi.y * t.wi.y).sqrt();
        // η_o sin θ_o = η_i sin θ_i, with eta = η_i/η_o.
        assert!((sin_o - t.eta * sin_i).abs() < 1e-5, "θ {theta}");
        assert!((t.wi.length() - 1.0).abs() < 1e-5);
    }
    // From inside beyond the critical angle (41.8°): F = 1, always reflected.
    let wo = dir(180.0 - 50.0);
    assert_eq!(fresnel_dielectric(wo.z, 1.5), 1.0);
    for ul in [0.0f32, 0.5, 0.999_999] {
        let s = g.sample(wo, ul, TransportMode::Radiance).unwrap();
        assert_eq!(s.pdf_w, 1.0);
        assert_eq!(s.eta, 1.0);
        assert!((s.wi - Vec3A::new(-wo.x, -wo.y, wo.z)).length() < 1e-6);
        assert!((s.f * s.wi.z.abs() - Color::ONE).abs().max_element() < 1e-6);
    }
}

#[test]
fn delta_lobes_have_zero_eval_and_pdf() {
    let b = Brdf::Glass(glass());
    let wo = dir(30.0);
    let s = b
        .sample(wo, Vec2::ZERO, 0.0, Vec2::ZERO, TransportMode::Radiance)
        .unwrap();
    assert_eq!(b.eval(wo, s.wi, Vec2::ZERO), Color::ZERO);
    assert_eq!(b.pdf(wo, s.wi, Vec2::ZERO), 0.0);
    assert!(b.is_delta());
    assert!(
        b.sample(
            Vec3A::X,
            Vec2::ZERO,
            0.5,
            Vec2::ZERO,
            TransportMode::Radiance
        )
        .is_none()
    );
}
