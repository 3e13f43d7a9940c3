//! Grader of exercise 8 (the density of the Phong-lobe warp): exact values
//! of the student's density, the usual mistakes named, and for an unnamed
//! one how much the density integrates to.

use raytracer::math::INV_2PI;

use crate::stats::{Mistake, close, recognise};

/// The signature of exercise 8.
pub type PdfFn = fn(f32, f32) -> f32;

/// The grader's density `(n+1)/(2π) cos^n α` (0 for `cos α ≤ 0`).
pub fn expected(n: f32, cos_alpha: f32) -> f32 {
    if cos_alpha <= 0.0 {
        0.0
    } else {
        ((n as f64 + 1.0) / std::f64::consts::TAU * (cos_alpha as f64).powf(n as f64)) as f32
    }
}

/// The cases: exponents from a hemisphere-wide lobe to a narrow one, and
/// cosines from the axis to the edge of the lobe.
pub fn cases() -> Vec<(f32, f32)> {
    let mut c = Vec::new();
    for n in [0.0, 1.0, 3.5, 10.0, 100.0] {
        for t in [1.0, 0.95, 0.7, 0.3] {
            c.push((n, t));
        }
    }
    c
}

/// `∫ p dω` over the sphere of a density that depends on `cos α` only:
/// `2π ∫_{−1}^{1} p(t) dt`, by the midpoint rule (NaN and infinities count
/// as such).
fn integral(pdf: PdfFn, n: f32) -> f64 {
    let m = 20_000;
    let sum: f64 = (0..m)
        .map(|i| pdf(n, (-1.0 + 2.0 * (i as f64 + 0.5) / m as f64) as f32) as f64)
        .sum();
    std::f64::consts::TAU * sum * 2.0 / m as f64
}

pub fn check(pdf: PdfFn) -> Result<(), String> {
    let cases = cases();
    let got: Vec<f32> = cases.iter().map(|&(n, t)| pdf(n, t)).collect();
    if let Some(k) =
        (0..cases.len()).find(|&k| !close(got[k], expected(cases[k].0, cases[k].1), 1e-4))
    {
        let sin = |t: f32| (1.0 - t * t).max(0.0).sqrt();
        let mistakes: [Mistake<(f32, f32), f32>; 7] = [
            (&crate::tr!("ex08.s_n"), &|&(n, t)| {
                (n + 2.0) * INV_2PI * t.powf(n)
            }),
            (&crate::tr!("ex08.two_pi"), &|&(n, t)| (n + 1.0) * t.powf(n)),
            (&crate::tr!("ex08.d_alpha"), &|&(n, t)| {
                (n + 1.0) * INV_2PI * t.powf(n) * sin(t)
            }),
            (&crate::tr!("ex08.power"), &|&(n, t)| {
                (n + 1.0) * INV_2PI * t.powf(n + 1.0)
            }),
            (&crate::tr!("ex08.derivative"), &|&(n, t)| {
                n * INV_2PI * t.powf(n - 1.0)
            }),
            (&crate::tr!("ex08.uniform"), &|_| INV_2PI),
            (&crate::tr!("ex08.pi"), &|&(n, t)| {
                (n + 1.0) * 0.5 * t.powf(n)
            }),
        ];
        let (n, t) = cases[k];
        let why = recognise(&cases, &got, &mistakes, |g, a| close(g, a, 1e-4))
            .unwrap_or_else(|| crate::tr!("ex08.integral", integral = integral(pdf, n), n));
        return Err(crate::tr!("ex08.pdf", got = got[k], n, t, why));
    }
    // The edge: directions the warp never produces have density 0.
    for (n, t) in [(10.0, 0.0), (10.0, -0.4), (2.5, -0.9), (0.0, -1.0)] {
        let g = pdf(n, t);
        if g != 0.0 {
            return Err(crate::tr!(
                "ex08.below",
                nan = if g.is_nan() {
                    crate::tr!("ex08.nan")
                } else {
                    String::new()
                },
                n,
                t,
                g
            ));
        }
    }
    Ok(())
}
