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
            (
                "(n+2)/(2π) cos^n α is S(n), the BRDF's normalization (exercise 4): that makes ∫ p cos θ dω = 1 at normal incidence; a density must make ∫ p dω = 1, without the cosine",
                &|&(n, t)| (n + 2.0) * INV_2PI * t.powf(n),
            ),
            (
                "too large by ×2π: (n+1) cos^n α is the density of t = cos α alone; the spread of the directions over φ is missing",
                &|&(n, t)| (n + 1.0) * t.powf(n),
            ),
            (
                "that is a density per dα dφ: it carries the sin α of dω = sin α dα dφ (and vanishes on the axis, where the warp puts the most directions), so it is not per unit solid angle",
                &|&(n, t)| (n + 1.0) * INV_2PI * t.powf(n) * sin(t),
            ),
            (
                "one power of cos α too many: your density goes as cos^{n+1} α, the warp's as a lower power",
                &|&(n, t)| (n + 1.0) * INV_2PI * t.powf(n + 1.0),
            ),
            (
                "n t^{n−1}/(2π) is the derivative of the lobe cos^n α itself, not of the distribution function of the cos α the warp produces",
                &|&(n, t)| n * INV_2PI * t.powf(n - 1.0),
            ),
            (
                "1/(2π) is the density of UNIFORM directions over the hemisphere (the warp with n = 0)",
                &|_| INV_2PI,
            ),
            (
                "too large by ×π in every case: a missing π (the integral over φ of a full turn brings one)",
                &|&(n, t)| (n + 1.0) * 0.5 * t.powf(n),
            ),
        ];
        let (n, t) = cases[k];
        let why = recognise(&cases, &got, &mistakes, |g, a| close(g, a, 1e-4)).unwrap_or_else(|| {
            format!(
                "over all directions your density integrates to {:.4} for n = {n}, and a density must integrate to 1",
                integral(pdf, n)
            )
        });
        return Err(format!(
            "phong_lobe_pdf(n = {n}, cos α = {t}) is {}, expected {} — {why}",
            got[k],
            expected(n, t)
        ));
    }
    // The edge: directions the warp never produces have density 0.
    for (n, t) in [(10.0, 0.0), (10.0, -0.4), (2.5, -0.9), (0.0, -1.0)] {
        let g = pdf(n, t);
        if g != 0.0 {
            return Err(format!(
                "phong_lobe_pdf(n = {n}, cos α = {t}) is {g}, expected 0 — the warp gives cos α = u₁^(1/(n+1)) > 0, so directions with cos α ≤ 0 have density 0 (a negative cosine raised to a power is not a density{})",
                if g.is_nan() { ": here it is NaN" } else { "" }
            ));
        }
    }
    Ok(())
}
