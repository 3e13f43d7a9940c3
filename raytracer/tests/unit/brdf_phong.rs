//! Unit tests of `brdf/phong.rs`.

use super::brdf_testing::*;
use raytracer::brdf::BrdfSample;
use raytracer::brdf::phong::*;
use raytracer::brdf::{Brdf, TransportMode};
use raytracer::math::{Color, PI, Vec2, Vec3A};
use raytracer::sampling::chi2::Chi2Test;

const EXPONENTS: [f32; 4] = [1.0, 10.0, 100.0, 1000.0];

fn phong(n: f32, rho: f32) -> Brdf {
    Brdf::Phong(Phong {
        albedo: Color::splat(rho),
        exponent: n,
    })
}

/// Bins for a lobe of exponent n seen from `wo`: a cap around the mirror
/// direction holding all but e^-6 of the lobe (`1 − cos α_max = 6/(n+1)`,
/// since the lobe's mass beyond α is `cos^{n+1} α ≈ e^{−(n+1)(1−cos α)}`),
/// if that cap stays above the horizon; otherwise the whole sphere with
/// finer bins. A narrow lobe in a coarse sphere grid would fall in one or
/// two cells and its shape would go untested.
fn bins_for(n: f32, wo: Vec3A, seed: u64) -> Chi2Test {
    let r = mirror_z(wo);
    let cos_min = 1.0 - 6.0 / (n + 1.0);
    let alpha_max = cos_min.acos();
    let elevation = r.z.abs().asin();
    if cos_min > 0.0 && alpha_max < elevation - 0.02 {
        zoomed(Vec3A::new(r.x, r.y, r.z.abs()), cos_min, seed)
    } else {
        Chi2Test {
            cos_theta_res: 20,
            phi_res: 40,
            ..full_sphere(seed)
        }
    }
}

/// Chi-square of sampling vs pdf for exponent `EXPONENTS[i]` at normal,
/// oblique and grazing incidence, and the pdf and value each sample reports.
fn sampling_matches_pdf(i: usize) {
    let n = EXPONENTS[i];
    let b = phong(n, 0.8);
    for (j, theta) in [0.0f32, 45.0, 80.0].into_iter().enumerate() {
        let wo = dir(theta);
        let r = chi2_brdf(&b, wo, bins_for(n, wo, 200 + 10 * i as u64 + j as u64));
        assert!(r.is_ok(), "n = {n}, θ_o = {theta}°: {}", r.unwrap_err());
        check_pdfs(&b, wo).unwrap();
    }
}

#[test]
fn sampling_matches_pdf_n1() {
    sampling_matches_pdf(0);
}

#[test]
fn sampling_matches_pdf_n10() {
    sampling_matches_pdf(1);
    // Seen from below (two-sided).
    let wo = dir(150.0);
    chi2_brdf(&phong(10.0, 0.8), wo, bins_for(10.0, wo, 299)).unwrap();
}

#[test]
fn sampling_matches_pdf_n100() {
    sampling_matches_pdf(2);
}

#[test]
fn sampling_matches_pdf_n1000() {
    sampling_matches_pdf(3);
}

/// The test has power: a lobe sampled with exponent 1.2 n while the pdf
/// claims n (a typical slip: `u^{1/n}` for `u^{1/(n+1)}` at n = 5, or a
/// wrong exponent) is rejected.
#[test]
fn wrong_sampling_exponent_is_caught() {
    for n in [5.0f32, 100.0] {
        let wrong = Phong {
            albedo: Color::ONE,
            exponent: n * 1.2,
        };
        let right = Phong {
            albedo: Color::ONE,
            exponent: n,
        };
        let wo = dir(30.0);
        let r = bins_for(n, wo, 7).run(
            |u, _| wrong.sample(wo, u).map(|s| s.wi),
            |wi| if wi.z > 0.0 { right.pdf(wo, wi) } else { 0.0 },
        );
        assert!(r.is_err(), "n = {n}: {r:?}");
        eprintln!("{}", r.unwrap_err());
    }
}

#[test]
fn is_reciprocal() {
    for n in [0.0, 1.0, 10.0, 1000.0] {
        check_reciprocity(&phong(n, 0.9));
    }
}

/// Directional albedo ≤ 1 at every angle and = ρ_s at normal incidence,
/// within 1% (asserted to be more than 5 standard errors: false failure
/// < 6e-7; 2^18 samples, as n = 0 has the largest variance, 1/3). It
/// falls with the angle of incidence.
#[test]
fn albedo_is_rho_at_normal_incidence_and_below_elsewhere() {
    for n in [0.0, 1.0, 10.0, 100.0, 1000.0] {
        let b = phong(n, 1.0);
        let mut last = f32::INFINITY;
        for theta in [0.0f32, 30.0, 60.0, 85.0, 89.0] {
            let (mean, se) = directional_albedo(dir(theta), 1 << 18, 3, |wo, ul, u| {
                b.sample(wo, Vec2::ZERO, ul, u, TransportMode::Radiance)
            });
            eprintln!("n {n}, θ_o {theta}°: albedo {:.4} ± {:.4}", mean.x, se.x);
            let analytic = (theta == 0.0).then_some(Color::ONE);
            let r = check_albedo(mean, se, analytic);
            assert!(r.is_ok(), "n {n}, θ {theta}: {}", r.unwrap_err());
            assert!(mean.x < last + 5.0 * se.x, "n {n}, θ {theta}: {mean}");
            last = mean.x;
        }
    }
}

/// The unnormalized lobe `f = ρ_s cos^n α` (without `(n+2)/(2π)`) has
/// albedo `2π/(n+2)·ρ_s` at normal incidence: 2.09 for n = 1 (energy is
/// created) and 0.52 for n = 10 (too dark). The albedo check rejects both.
#[test]
fn unnormalized_phong_is_caught() {
    for (n, expected) in [(1.0f32, 2.094), (10.0, 0.524)] {
        let good = Phong {
            albedo: Color::ONE,
            exponent: n,
        };
        let (mean, se) = directional_albedo(dir(0.0), 1 << 16, 3, |wo, _, u| {
            good.sample(wo, u).map(|s| BrdfSample {
                f: s.f * (2.0 * PI / (n + 2.0)),
                ..s
            })
        });
        assert!((mean.x - expected).abs() < 0.01, "{mean}");
        assert!(check_albedo(mean, se, Some(Color::ONE)).is_err());
    }
}

#[test]
fn values_at_fixed_directions() {
    let b = phong(10.0, 0.5);
    // At the mirror direction cos α = 1: f = 0.5·12/(2π).
    let wo = dir(40.0);
    let f = b.eval(wo, mirror_z(wo), Vec2::ZERO);
    assert!((f.x - 0.5 * 12.0 / (2.0 * PI)).abs() < 1e-5);
    // Below the surface nothing, even inside the lobe.
    assert_eq!(
        b.eval(dir(89.0), Vec3A::new(0.0, 0.0, -1.0), Vec2::ZERO),
        Color::ZERO
    );
    assert!(!b.is_delta());
}
