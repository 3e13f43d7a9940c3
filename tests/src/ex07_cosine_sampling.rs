//! Grader of exercise 7 (cosine-weighted sampling): the pdf exactly, then a
//! chi-square test of the student's directions against the grader's own pdf.
//! On failure the marginal distributions of `cos θ` and `φ` of the student's
//! directions name the usual mistakes, and their histograms (against the
//! densities they should have) are written to `target/grading/`.

use std::f64::consts::{PI, TAU};

use raytracer::math::{INV_PI, Vec2, Vec3A};
use raytracer::sampling::chi2::{Chi2Test, uniforms};

use crate::pictures::{Histogram, write_histograms};
use crate::stats::{close, fmt3, output_dir};

/// The signatures of exercise 7.
pub type SampleFn = fn(Vec2) -> Vec3A;
pub type PdfFn = fn(Vec3A) -> f32;

/// The grader's own pdf.
pub fn expected_pdf(w: Vec3A) -> f32 {
    w.z.max(0.0) * INV_PI
}

/// Significance of the chi-square test: a correct sampler fails it with
/// probability 1e-4 (for the fixed seed: deterministically pass or fail).
pub const SIGNIFICANCE: f64 = 1e-4;

/// Samples of the chi-square test and of the histograms.
pub const SAMPLES: u64 = 1 << 18;

/// The file the histograms are written to.
pub fn histogram_path() -> std::path::PathBuf {
    output_dir().join("ex07_cosine_sampling_histograms.png")
}

pub fn check(sample: SampleFn, pdf: PdfFn) -> Result<(), String> {
    // 1. The pdf at fixed directions.
    for w in [
        Vec3A::Z,
        Vec3A::new(0.6, 0.0, 0.8),
        Vec3A::new(-0.3, 0.9, 0.1).normalize(),
        Vec3A::new(0.0, 0.6, -0.8),
        Vec3A::new(0.8, -0.6, 0.0),
    ] {
        let (got, want) = (pdf(w), expected_pdf(w));
        if !(close(got, want, 1e-4) || (want == 0.0 && got == 0.0)) {
            let c = w.z.max(0.0);
            let why = if close(got, 0.5 * INV_PI, 1e-4) {
                crate::tr!("ex07.uniform_pdf")
            } else if want == 0.0 {
                crate::tr!("ex07.below_pdf")
            } else if close(got, w.z, 1e-4) {
                crate::tr!("ex07.cos_itself", integral = std::f64::consts::PI)
            } else if close(got, c * c * c * INV_PI, 1e-4) {
                crate::tr!("ex07.cos3")
            } else {
                crate::tr!(
                    "ex07.integrates",
                    integral = pdf_integral(pdf),
                    proportional = if close(got / c, pdf(Vec3A::Z), 1e-3) {
                        String::new()
                    } else {
                        crate::tr!("ex07.not_proportional")
                    }
                )
            };
            return Err(crate::tr!("ex07.pdf", w = fmt3(w), got, why));
        }
    }
    // 2. Unit directions in the upper hemisphere.
    let n = 64;
    for j in 0..n {
        for i in 0..n {
            let u = Vec2::new(i as f32 / n as f32, j as f32 / n as f32);
            let w = sample(u);
            if !((w.length() - 1.0).abs() < 1e-4 && w.z >= 0.0) {
                return Err(crate::tr!(
                    "ex07.not_unit",
                    got = fmt3(w),
                    length = w.length(),
                    u
                ));
            }
        }
    }
    // 3. The distribution: chi-square over 10×20 cells.
    let test = Chi2Test {
        samples: SAMPLES,
        seed: 6,
        significance: SIGNIFICANCE,
        ..Chi2Test::default()
    };
    if let Err(e) = test.run(|u, _| Some(sample(u)), expected_pdf) {
        let first = e.lines().next().unwrap_or_default();
        let first = first.split(" Worst cells").next().unwrap_or(first);
        return Err(crate::tr!(
            "ex07.chi2",
            diagnosis = diagnose(sample, test.seed),
            picture = write_picture(sample, test.seed),
            first
        ));
    }
    Ok(())
}

/// `∫ pdf dω` over the hemisphere of a density that depends on `cos θ`
/// only (the student's along the `xz` plane), by the midpoint rule in
/// `t = cos θ` (`dω = dt dφ`).
fn pdf_integral(pdf: PdfFn) -> f64 {
    let m = 4000;
    let sum: f64 = (0..m)
        .map(|i| {
            let t = (i as f32 + 0.5) / m as f32;
            pdf(Vec3A::new((1.0 - t * t).sqrt(), 0.0, t)) as f64
        })
        .sum();
    TAU * sum / m as f64
}

/// `cos θ` and `φ ∈ [0, 2π)` of the student's directions for the chi-square
/// test's numbers.
fn angles(sample: SampleFn, seed: u64) -> impl Iterator<Item = (f64, f64)> {
    (0..SAMPLES).map(move |i| {
        let w = sample(uniforms(seed, i).0);
        let phi = (w.y as f64).atan2(w.x as f64).rem_euclid(TAU);
        (w.z as f64, phi)
    })
}

/// Names the mistake from the marginals of `cos θ` and `φ`.
fn diagnose(sample: SampleFn, seed: u64) -> String {
    let (mut sum_cos, mut upper_phi) = (0.0, 0u64);
    let mut phi_bins = [0u64; 16];
    for (c, phi) in angles(sample, seed) {
        sum_cos += c;
        if phi >= PI {
            upper_phi += 1;
        }
        phi_bins[((phi / TAU * 16.0) as usize).min(15)] += 1;
    }
    let n = SAMPLES as f64;
    let mean_cos = sum_cos / n;
    let empty = phi_bins
        .iter()
        .filter(|&&b| (b as f64) < 0.1 * n / 16.0)
        .count();
    // Standard error of the mean of cos θ under the right density (variance
    // 1/18): 4.6e-4; the alternatives below lie at least 0.014 (30 standard
    // errors) apart, and each is recognised within 0.005 (10 of them).
    if (upper_phi as f64) < 0.01 * n {
        crate::tr!("ex07.half_circle")
    } else if empty >= 4 {
        crate::tr!("ex07.sectors", empty)
    } else if (mean_cos - 0.5).abs() < 0.005 {
        crate::tr!("ex07.uniform")
    } else if (mean_cos - PI / 4.0).abs() < 0.005 {
        crate::tr!("ex07.sin_uniform")
    } else if (mean_cos - 0.8).abs() < 0.005 {
        crate::tr!("ex07.cos3_mean")
    } else if mean_cos > 2.0 / 3.0 {
        crate::tr!("ex07.too_many", mean_cos)
    } else {
        crate::tr!("ex07.too_few", mean_cos)
    }
}

/// Writes the histograms of `cos θ` and `φ` and says where.
fn write_picture(sample: SampleFn, seed: u64) -> String {
    let bins = 32;
    let (mut cos_counts, mut phi_counts) = (vec![0u64; bins], vec![0u64; bins]);
    for (c, phi) in angles(sample, seed) {
        cos_counts[((c.clamp(0.0, 1.0) * bins as f64) as usize).min(bins - 1)] += 1;
        phi_counts[((phi / TAU * bins as f64) as usize).min(bins - 1)] += 1;
    }
    let cos_density = |t: f64| 2.0 * t;
    let phi_density = |_: f64| 1.0 / TAU;
    let histograms = [
        Histogram {
            lo: 0.0,
            hi: 1.0,
            counts: cos_counts,
            expected_density: &cos_density,
        },
        Histogram {
            lo: 0.0,
            hi: TAU,
            counts: phi_counts,
            expected_density: &phi_density,
        },
    ];
    let path = histogram_path();
    let written =
        std::fs::create_dir_all(output_dir()).and_then(|()| write_histograms(&histograms, &path));
    match written {
        Ok(()) => crate::tr!("ex07.see", file = path.display()),
        Err(e) => crate::tr!("ex07.no_picture", e),
    }
}
