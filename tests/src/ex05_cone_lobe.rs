//! Grader of exercise 5 (the normalization of a uniform cone lobe): exact
//! values of `C(θ_m)`, the usual mistakes named.

use raytracer::math::PI;

use crate::stats::{Mistake, close, recognise};

/// The signature of exercise 5.
pub type NormFn = fn(f32) -> f32;

/// The grader's `C(θ_m) = 1/(π sin²θ_m)`.
pub fn expected(theta_max: f32) -> f32 {
    let s = (theta_max as f64).sin();
    (1.0 / (std::f64::consts::PI * s * s)) as f32
}

/// The half-angles of the test, in radians: the whole hemisphere (Lambert),
/// 60°, 45°, 30°, and a narrow cone of 0.1 rad.
pub const ANGLES: [f32; 5] = [PI / 2.0, PI / 3.0, PI / 4.0, PI / 6.0, 0.1];

pub fn check(f: NormFn) -> Result<(), String> {
    let got: Vec<f32> = ANGLES.iter().map(|&t| f(t)).collect();
    let Some(k) = (0..ANGLES.len()).find(|&k| !close(got[k], expected(ANGLES[k]), 1e-4)) else {
        return Ok(());
    };
    let sin2 = |t: f32| t.sin() * t.sin();
    let mistakes: [Mistake<f32, f32>; 8] = [
        (
            "1/(2π(1 − cos θ_m)) is one over the cone's solid angle: it makes ∫ C dω = 1, a probability density, but the albedo weights each direction by cos θ_i — with it the albedo at normal incidence is (1 + cos θ_m)/2 · ρ < ρ: energy is lost",
            &|&t| 1.0 / (2.0 * PI * (1.0 - t.cos())),
        ),
        (
            "1/π is Lambert's constant: right only when the cone is the whole hemisphere (θ_m = π/2)",
            &|_| 1.0 / PI,
        ),
        (
            "1/(π θ_m²) uses the small-angle approximation sin θ_m ≈ θ_m: right for narrow cones only, and wrong by more and more as the cone widens (×0.41 at θ_m = 90°)",
            &|&t| 1.0 / (PI * t * t),
        ),
        (
            "you returned the integral of cos θ over the cone itself, not the constant that makes ρ·C times it equal ρ",
            &|&t| PI * sin2(t),
        ),
        (
            "half the right value at every angle: a factor 2 was lost in the integral over θ or over φ (energy is lost)",
            &|&t| 1.0 / (2.0 * PI * sin2(t)),
        ),
        (
            "twice the right value at every angle: a factor 2 too many in the integral over θ or over φ (energy is created)",
            &|&t| 2.0 / (PI * sin2(t)),
        ),
        (
            "too large by ×π at every angle: a missing π (the integral over φ of a full turn brings it)",
            &|&t| 1.0 / sin2(t),
        ),
        (
            "θ_m is already in radians: do not convert it from degrees",
            &|&t| {
                let s = (t * PI / 180.0).sin();
                1.0 / (PI * s * s)
            },
        ),
    ];
    let t = ANGLES[k];
    let why = recognise(&ANGLES, &got, &mistakes, |g, a| close(g, a, 1e-4)).unwrap_or_else(|| {
        format!(
            "with it the albedo at normal incidence would be {:.3}·ρ instead of ρ",
            got[k] as f64 / expected(t) as f64
        )
    });
    Err(format!(
        "C(θ_m = {t:.4} rad = {:.1}°) is {}, expected {} — {why}",
        t.to_degrees(),
        got[k],
        expected(t)
    ))
}
