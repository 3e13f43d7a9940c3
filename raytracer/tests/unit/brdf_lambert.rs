//! Unit tests of `brdf/lambert.rs`.

use super::brdf_testing::*;
use raytracer::brdf::lambert::*;
use raytracer::brdf::{Brdf, TransportMode};
use raytracer::brdf::{BrdfSample, Texture};
use raytracer::math::{Color, INV_PI, Vec2, Vec3A};

fn lambert(rho: Color) -> Brdf {
    Brdf::Lambert(Lambert {
        albedo: Texture::Constant(rho),
    })
}

/// Sampling agrees with the pdf: chi-square at normal, oblique and grazing
/// incidence, and seen from below (two-sided).
#[test]
fn sampling_matches_pdf() {
    let b = lambert(Color::splat(0.7));
    for (k, wo) in [dir(0.0), dir(45.0), dir(89.0), dir(120.0)]
        .into_iter()
        .enumerate()
    {
        chi2_brdf(&b, wo, full_sphere(100 + k as u64)).unwrap();
        check_pdfs(&b, wo).unwrap();
    }
}

#[test]
fn is_reciprocal_and_two_sided() {
    check_reciprocity(&lambert(Color::new(0.2, 0.5, 0.9)));
    let b = lambert(Color::splat(0.5));
    let (wo, wi) = (dir(30.0), dir(70.0));
    let flip = |w: Vec3A| Vec3A::new(w.x, w.y, -w.z);
    assert!((b.eval(wo, wi, Vec2::ZERO) - Color::splat(0.5 * INV_PI)).length() < 1e-7);
    assert_eq!(
        b.eval(wo, wi, Vec2::ZERO),
        b.eval(flip(wo), flip(wi), Vec2::ZERO)
    );
    assert_eq!(
        b.eval(wo, flip(wi), Vec2::ZERO),
        Color::ZERO,
        "no transmission"
    );
    assert_eq!(b.pdf(wo, flip(wi), Vec2::ZERO), 0.0);
}

/// Directional albedo = ρ at every angle (within 1%, far more than 5
/// standard errors; here the estimator even has zero variance).
#[test]
fn albedo_is_rho() {
    let rho = Color::new(0.9, 0.5, 0.1);
    let b = lambert(rho);
    for theta in [0.0f32, 30.0, 60.0, 85.0, 150.0] {
        let (mean, se) = directional_albedo(dir(theta), 1 << 14, 7, |wo, ul, u| {
            b.sample(wo, Vec2::ZERO, ul, u, TransportMode::Radiance)
        });
        check_albedo(mean, se, Some(rho)).unwrap();
    }
}

/// A Lambert without the 1/π (f = ρ) reflects π times too much: the
/// albedo check must reject it.
#[test]
fn lambert_without_one_over_pi_is_caught() {
    let rho = Color::splat(0.5);
    let good = Lambert {
        albedo: Texture::Constant(rho),
    };
    let (mean, se) = directional_albedo(dir(0.0), 1 << 14, 7, |wo, _, u| {
        good.sample(wo, Vec2::ZERO, u).map(|s| BrdfSample {
            f: s.f * raytracer::math::PI,
            ..s
        })
    });
    let err = check_albedo(mean, se, Some(rho)).unwrap_err();
    assert!(err.contains("1.57"), "{err}");
    // Even without knowing ρ, energy conservation alone rejects it.
    assert!(check_albedo(mean, se, None).is_err());
}

#[test]
fn textured_albedo_is_looked_up_at_uv() {
    let b = Brdf::Lambert(Lambert {
        albedo: Texture::Checker {
            a: Color::X,
            b: Color::Y,
            scale: 2.0,
        },
    });
    let (wo, wi) = (dir(10.0), dir(20.0));
    assert_eq!(b.eval(wo, wi, Vec2::new(0.1, 0.1)), Color::X * INV_PI);
    assert_eq!(b.eval(wo, wi, Vec2::new(0.6, 0.1)), Color::Y * INV_PI);
}
