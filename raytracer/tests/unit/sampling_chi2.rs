//! Unit tests of `sampling/chi2.rs`.

use raytracer::frame::Frame;
use raytracer::math::{INV_PI, PI};
use raytracer::math::{Vec2, Vec3A};
use raytracer::sampling::chi2::*;
use raytracer::sampling::warp;

/// Tests in this file that run a correct sampler (Šidák family).
const FAMILY: usize = 4;

fn settings(seed: u64) -> Chi2Test {
    Chi2Test {
        samples: 1 << 18,
        seed,
        tests: FAMILY,
        ..Chi2Test::default()
    }
}

#[test]
fn special_functions_match_tables() {
    // ln Γ(1/2) = ln √π, Γ(10) = 9!, Γ(1) = Γ(2) = 1.
    assert!((ln_gamma(0.5) - PI.sqrt().ln() as f64).abs() < 1e-6);
    assert!((ln_gamma(10.0) - 362_880f64.ln()).abs() < 1e-10);
    assert!(ln_gamma(1.0).abs() < 1e-12 && ln_gamma(2.0).abs() < 1e-12);
    // 95% quantiles of the chi-square tables.
    for &(x, k) in &[
        (3.841_459, 1),
        (18.307_038, 10),
        (124.342_113, 100),
        (43.772_972, 30),
    ] {
        let p = chi2_survival(x, k);
        assert!((p - 0.05).abs() < 1e-6, "k = {k}: {p}");
    }
    // Even k = 2m: P(χ² ≥ x) = e^{−x/2} Σ_{j<m} (x/2)^j / j! exactly.
    for &(k, x) in &[
        (4usize, 2.0f64),
        (20, 15.0),
        (20, 40.0),
        (200, 180.0),
        (200, 250.0),
    ] {
        let (mut term, mut sum) = (1.0f64, 0.0f64);
        for j in 0..k / 2 {
            if j > 0 {
                term *= x / 2.0 / j as f64;
            }
            sum += term;
        }
        let exact = (-x / 2.0).exp() * sum;
        let p = chi2_survival(x, k);
        assert!(
            (p - exact).abs() < 1e-9 * exact.max(1e-3),
            "k {k}, x {x}: {p} vs {exact}"
        );
    }
    // Two degrees of freedom: an exponential, P(χ² ≥ x) = e^{−x/2}, on
    // both sides of the series / continued fraction switch at x/2 = a + 1.
    for x in [0.1f64, 1.0, 3.9, 4.1, 10.0, 60.0] {
        assert!(
            (chi2_survival(x, 2) - (-x / 2.0).exp()).abs() < 1e-12,
            "x = {x}"
        );
    }
    assert!((sidak(0.01, 1) - 0.01).abs() < 1e-15);
    assert!((1.0 - (1.0 - sidak(0.01, 20)).powi(20) - 0.01).abs() < 1e-12);
}

#[test]
fn correct_samplers_pass() {
    let r = settings(1)
        .run(
            |u, _| Some(warp::uniform_sphere(u)),
            |_| warp::uniform_sphere_pdf(),
        )
        .unwrap();
    assert_eq!(r.dof, 199);
    let r = settings(2)
        .run(
            |u, _| Some(warp::cosine_hemisphere(u)),
            |w| warp::cosine_hemisphere_pdf(w.z),
        )
        .unwrap();
    // Half the sphere has zero pdf: 100 cells and the `None` cell pooled.
    assert_eq!(r.dof, 99, "{r:?}");
    // A sampler that refuses half its samples, with its pdf.
    let r = settings(3)
        .run(
            |u, ul| (ul < 0.5).then(|| warp::uniform_sphere(u)),
            |_| 0.5 * warp::uniform_sphere_pdf(),
        )
        .unwrap();
    assert!(r.no_sample > 0 && r.dof == 200, "{r:?}");
    // A zoomed cap about a tilted axis: cosine lobe about `axis`, cells
    // over 1 − cos θ ≤ 0.3 and the rest of the sphere in one cell.
    let axis = Vec3A::new(0.3, -0.5, 0.8).normalize();
    let frame = Frame::from_normal(axis);
    let r = Chi2Test {
        axis,
        cos_theta_min: 0.7,
        ..settings(4)
    }
    .run(
        |u, _| Some(frame.to_world(warp::cosine_hemisphere(u))),
        |w| w.dot(axis).max(0.0) * INV_PI,
    )
    .unwrap();
    assert_eq!(r.dof, 200, "{r:?}");
}

#[test]
fn wrong_samplers_fail_and_name_cells() {
    // Uniform hemisphere directions claimed to be cosine-distributed.
    let e = settings(5)
        .run(
            |u, _| Some(warp::uniform_hemisphere(u)),
            |w| warp::cosine_hemisphere_pdf(w.z),
        )
        .unwrap_err();
    assert!(e.contains("cos θ ∈") && e.contains("deviation map"), "{e}");
    // A pdf that integrates to 2.
    let e = settings(6)
        .run(
            |u, _| Some(warp::cosine_hemisphere(u)),
            |w| 2.0 * warp::cosine_hemisphere_pdf(w.z),
        )
        .unwrap_err();
    assert!(e.contains("integrates to 2.0"), "{e}");
    // Samples where the pdf is zero.
    let e = settings(7)
        .run(
            |u, _| Some(warp::uniform_sphere(u)),
            |w| {
                if w.z > 0.0 {
                    2.0 * warp::uniform_sphere_pdf()
                } else {
                    0.0
                }
            },
        )
        .unwrap_err();
    assert!(e.contains("pdf is zero"), "{e}");
    // A sampler that refuses too often: the `None` cell catches it.
    let e = settings(8)
        .run(
            |u, ul| (ul < 0.45).then(|| warp::uniform_sphere(u)),
            |_| 0.5 * warp::uniform_sphere_pdf(),
        )
        .unwrap_err();
    assert!(e.contains("no sample (None)"), "{e}");
    // A non-unit direction.
    assert!(settings(9).run(|_, _| Some(Vec3A::ONE), |_| 1.0).is_err());
}

#[test]
fn frequencies() {
    let first = (0..100_000u64).filter(|&i| uniforms(3, i).1 < 0.3).count() as u64;
    let counts = [first, 100_000 - first];
    chi2_frequencies(&counts, &[0.3, 0.7], 0.01, FAMILY).unwrap();
    assert!(chi2_frequencies(&counts, &[0.31, 0.69], 0.01, FAMILY).is_err());
    assert!(chi2_frequencies(&counts, &[0.3, 0.6], 0.01, 1).is_err());
    chi2_frequencies(&[100, 0], &[1.0, 0.0], 0.01, 1).unwrap();
    assert!(chi2_frequencies(&[100, 1], &[1.0, 0.0], 0.01, 1).is_err());
}

#[test]
fn sample_pdf_check() {
    let sampler = |u: Vec2, _| {
        let w = warp::cosine_hemisphere(u);
        Some((w, warp::cosine_hemisphere_pdf(w.z)))
    };
    let n = check_sample_pdfs(10_000, 1, sampler, |w| w.z.max(0.0) * INV_PI, 1e-4).unwrap();
    assert!(n > 9_990);
    let e = check_sample_pdfs(10_000, 1, sampler, |w| w.z.max(0.0) * 0.3, 1e-4).unwrap_err();
    assert!(e.starts_with("10000 of 10000 samples"), "{e}");
}
