//! Grader of exercise 6 (cosine-weighted sampling): the pdf exactly, then a
//! chi-square test of the student's directions against the grader's own pdf.

use raytracer::math::{INV_PI, Vec2, Vec3A};
use raytracer::sampling::chi2::Chi2Test;

use crate::stats::{close, fmt3};

/// The signatures of exercise 6.
pub type SampleFn = fn(Vec2) -> Vec3A;
pub type PdfFn = fn(Vec3A) -> f32;

/// The grader's own pdf.
pub fn expected_pdf(w: Vec3A) -> f32 {
    w.z.max(0.0) * INV_PI
}

/// Significance of the chi-square test: a correct sampler fails it with
/// probability 1e-4 (for the fixed seed: deterministically pass or fail).
pub const SIGNIFICANCE: f64 = 1e-4;

pub fn check(sample: SampleFn, pdf: PdfFn) -> Result<(), String> {
    // 1. The pdf at fixed directions.
    for w in [
        Vec3A::Z,
        Vec3A::new(0.6, 0.0, 0.8),
        Vec3A::new(-0.3, 0.9, 0.1).normalize(),
        Vec3A::new(0.0, 0.6, -0.8),
    ] {
        let (got, want) = (pdf(w), expected_pdf(w));
        if !(close(got, want, 1e-4) || (want == 0.0 && got == 0.0)) {
            let why = if close(got, 0.5 * INV_PI, 1e-4) {
                "1/(2π) is the pdf of UNIFORM hemisphere sampling"
            } else if want == 0.0 {
                "below the horizon the density is 0"
            } else if close(got, w.z, 1e-4) {
                "did you forget to divide by π? The pdf must integrate to 1"
            } else {
                "the density per solid angle is cos θ / π"
            };
            return Err(format!(
                "cosine_hemisphere_pdf({}) is {got}, expected {want} — {why}",
                fmt3(w)
            ));
        }
    }
    // 2. Unit directions in the upper hemisphere.
    let n = 64;
    for j in 0..n {
        for i in 0..n {
            let u = Vec2::new(i as f32 / n as f32, j as f32 / n as f32);
            let w = sample(u);
            if !((w.length() - 1.0).abs() < 1e-4 && w.z >= 0.0) {
                return Err(format!(
                    "sample_cosine_hemisphere({u}) is {} (length {:.4}): expected a unit vector with z ≥ 0",
                    fmt3(w),
                    w.length()
                ));
            }
        }
    }
    // 3. The distribution: chi-square over 10×20 cells, 2^18 samples.
    let test = Chi2Test {
        samples: 1 << 18,
        seed: 6,
        significance: SIGNIFICANCE,
        ..Chi2Test::default()
    };
    test.run(|u, _| Some(sample(u)), expected_pdf).map_err(|e| {
        format!(
            "your directions are not distributed as cos θ/π (is r = sqrt(u.x)? is z = sqrt(1 − r²)?): {e}"
        )
    })?;
    Ok(())
}
