//! Test helpers shared by the BRDF models' tests (compiled for tests only):
//! chi-square settings, the sampled-pdf and reciprocity checks, and the
//! directional albedo `ρ(ω_o) = ∫ f_r cos θ_i dω_i` estimated with a model's
//! own sampling, with the check that a BRDF conserves energy.

use raytracer::brdf::{Brdf, BrdfSample, TransportMode};
use raytracer::math::{Color, Vec2, Vec3A};
use raytracer::sampling::chi2::{Chi2Report, Chi2Test, check_sample_pdfs, uniforms};
use raytracer::sampling::warp::uniform_sphere;

/// Number of chi-square tests of correct samplers in the brdf suite, the
/// Šidák family: Lambert 4, Phong 13, glass frequencies 6. The whole suite
/// fails a correct implementation with probability α = 0.01.
pub const CHI2_TESTS: usize = 23;

/// A local direction at `theta_deg` from the normal (beyond 90°: below), at
/// an azimuth of 37° so that no coordinate is special.
pub fn dir(theta_deg: f32) -> Vec3A {
    let (t, p) = (theta_deg.to_radians(), 37f32.to_radians());
    Vec3A::new(t.sin() * p.cos(), t.sin() * p.sin(), t.cos())
}

/// A 10×20 grid over the whole sphere, 2^19 samples.
pub fn full_sphere(seed: u64) -> Chi2Test {
    Chi2Test {
        samples: 1 << 19,
        seed,
        tests: CHI2_TESTS,
        ..Chi2Test::default()
    }
}

/// A 10×20 grid over the cap `cos θ ≥ cos_min` about `axis`, 2^19 samples.
pub fn zoomed(axis: Vec3A, cos_min: f32, seed: u64) -> Chi2Test {
    Chi2Test {
        axis,
        cos_theta_min: cos_min,
        ..full_sphere(seed)
    }
}

/// Chi-square test of `Brdf::sample` against `Brdf::pdf` for a fixed `wo`.
pub fn chi2_brdf(b: &Brdf, wo: Vec3A, settings: Chi2Test) -> Result<Chi2Report, String> {
    let what = format!("{b:?} at wo {wo}: ");
    let start = std::time::Instant::now();
    let r = settings.run(
        |u, u_lobe| {
            b.sample(wo, Vec2::ZERO, u_lobe, u, TransportMode::Radiance)
                .map(|s| s.wi)
        },
        |wi| b.pdf(wo, wi, Vec2::ZERO),
    );
    // Shown with `--nocapture`: the statistics behind the verdict.
    eprintln!("{what}{r:?} in {:.2} s", start.elapsed().as_secs_f32());
    r
}

/// The pdf and the value a sample reports agree with `Brdf::pdf` and
/// `Brdf::eval` (relative 1e-3: float rounding of `cos^n α` at n = 1000 is
/// about 1e-4).
pub fn check_pdfs(b: &Brdf, wo: Vec3A) -> Result<u64, String> {
    let sample = |u: Vec2, ul: f32| b.sample(wo, Vec2::ZERO, ul, u, TransportMode::Radiance);
    let n = 1 << 14;
    for i in 0..n {
        let (u, ul) = uniforms(1, i);
        if let Some(s) = sample(u, ul) {
            let f = b.eval(wo, s.wi, Vec2::ZERO);
            if (f - s.f).abs().max_element() > 1e-3 * f.max_element().max(s.f.max_element()) {
                return Err(format!("sample {i}: f = {} but eval gives {f}", s.f));
            }
        }
    }
    check_sample_pdfs(
        n,
        1,
        |u, ul| sample(u, ul).map(|s| (s.wi, s.pdf_w)),
        |wi| b.pdf(wo, wi, Vec2::ZERO),
        1e-3,
    )
}

/// `f_r(ω_o, ω_i) = f_r(ω_i, ω_o)` on 2·10⁵ pairs: half uniform on the
/// sphere, half near the mirror direction (where a narrow lobe is non-zero).
pub fn check_reciprocity(b: &Brdf) {
    let mut nonzero = 0u64;
    let n = 100_000;
    for i in 0..n {
        let (u, _) = uniforms(77, 2 * i);
        let (v, _) = uniforms(77, 2 * i + 1);
        let wo = uniform_sphere(u);
        let near = (Vec3A::new(-wo.x, -wo.y, wo.z) + 0.05 * uniform_sphere(v)).normalize();
        for wi in [uniform_sphere(v), near] {
            let a = b.eval(wo, wi, Vec2::ZERO);
            let c = b.eval(wi, wo, Vec2::ZERO);
            let scale = a.max_element().max(c.max_element());
            assert!(
                (a - c).abs().max_element() <= 1e-5 * scale,
                "f({wo}, {wi}) = {a} but f({wi}, {wo}) = {c}"
            );
            nonzero += (scale > 0.0) as u64;
        }
    }
    assert!(nonzero > n / 5, "only {nonzero} pairs were non-zero");
}

/// Monte Carlo directional albedo `∫ f_r cos θ_i dω_i` by `f |cos θ_i| / pdf`
/// with a sampler `sample(wo, u_lobe, u)` (`None` counts as zero). Returns
/// the mean and its standard error per channel.
pub fn directional_albedo(
    wo: Vec3A,
    n: u64,
    seed: u64,
    sample: impl Fn(Vec3A, f32, Vec2) -> Option<BrdfSample>,
) -> (Color, Color) {
    let (mut sum, mut sum_sq) = ([0.0f64; 3], [0.0f64; 3]);
    for i in 0..n {
        let (u, ul) = uniforms(seed, i);
        if let Some(s) = sample(wo, ul, u) {
            let w = s.f * s.wi.z.abs() / s.pdf_w;
            for k in 0..3 {
                sum[k] += w[k] as f64;
                sum_sq[k] += (w[k] as f64).powi(2);
            }
        }
    }
    let nf = n as f64;
    let mean = sum.map(|s| s / nf);
    let se = [0, 1, 2].map(|k| ((sum_sq[k] / nf - mean[k] * mean[k]).max(0.0) / (nf - 1.0)).sqrt());
    (
        Color::new(mean[0] as f32, mean[1] as f32, mean[2] as f32),
        Color::new(se[0] as f32, se[1] as f32, se[2] as f32),
    )
}

/// The albedo checks of the energy tests:
/// - energy conservation: no channel above 1 by more than 5 standard errors
///   (plus 1e-4 for rounding): a correct BRDF fails with probability below
///   3e-7 per channel (one-sided normal tail);
/// - if `analytic` is given: within 1% of it, and the estimate must be
///   precise enough for that, 5 standard errors ≤ 1% (so a correct BRDF
///   fails with probability below 6e-7 per channel).
pub fn check_albedo(mean: Color, se: Color, analytic: Option<Color>) -> Result<(), String> {
    for k in 0..3 {
        if mean[k] - 5.0 * se[k] > 1.0 + 1e-4 {
            return Err(format!(
                "directional albedo {mean} (standard error {se}) exceeds 1: the BRDF creates energy"
            ));
        }
    }
    if let Some(a) = analytic {
        for k in 0..3 {
            let tolerance = 0.01 * a[k].abs() + 1e-6;
            if 5.0 * se[k] > tolerance {
                return Err(format!(
                    "albedo {mean} too noisy (standard error {se}) for a 1% check"
                ));
            }
            if (mean[k] - a[k]).abs() > tolerance {
                return Err(format!(
                    "directional albedo {mean} (standard error {se}) differs from the analytic \
                     {a} by more than 1%"
                ));
            }
        }
    }
    Ok(())
}
