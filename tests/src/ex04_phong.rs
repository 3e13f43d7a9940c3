//! Grader of exercise 4 (normalized Phong): exact values of S(n) and f_r.

use raytracer::math::{Color, INV_2PI, Vec3A};

use crate::stats::{close, close3, fmt3};

/// The signatures of exercise 4.
pub type NormFn = fn(f32) -> f32;
pub type PhongFn = fn(Color, f32, Vec3A, Vec3A) -> Color;

/// The grader's `S(n)`.
pub fn expected_s(n: f32) -> f32 {
    (n + 2.0) * INV_2PI
}

/// The grader's `f_r`.
pub fn expected_f(albedo: Color, n: f32, wo: Vec3A, wi: Vec3A) -> Color {
    let cos_a = Vec3A::new(-wo.x, -wo.y, wo.z).dot(wi);
    if cos_a <= 0.0 {
        Color::ZERO
    } else {
        albedo * expected_s(n) * cos_a.min(1.0).powf(n)
    }
}

/// The exponents of the test.
pub const EXPONENTS: [f32; 6] = [0.0, 1.0, 2.0, 10.0, 100.0, 1000.0];

pub fn check(s: NormFn, f: PhongFn) -> Result<(), String> {
    for n in EXPONENTS {
        let got = s(n);
        let want = expected_s(n);
        if close(got, want, 1e-4) {
            continue;
        }
        let why = if close(got, (n + 1.0) * INV_2PI, 1e-4) {
            "(n+1)/(2π) normalizes the lobe without the cosine θ_i of the albedo: the albedo at normal incidence becomes (n+2)/(n+1)·ρ > ρ — energy is created".to_string()
        } else if close(got, 1.0, 1e-4) {
            "an unnormalized lobe: its albedo is 2π/(n+2), far below 1 for large n".to_string()
        } else {
            format!(
                "with it the albedo at normal incidence would be {:.3}·ρ instead of ρ",
                got / want
            )
        };
        return Err(format!("S({n}) is {got}, expected {want} — {why}"));
    }
    let albedo = Color::new(0.9, 0.6, 0.3);
    let wo = Vec3A::new(0.4, -0.2, 0.89).normalize();
    let mirror = Vec3A::new(-wo.x, -wo.y, wo.z);
    let dirs = [
        mirror,
        (mirror + Vec3A::new(0.1, 0.05, 0.0)).normalize(),
        (mirror + Vec3A::new(-0.3, 0.2, 0.1)).normalize(),
        Vec3A::Z,
        // Upper hemisphere, but more than 90° from the mirror direction.
        Vec3A::new(0.9, -0.3, 0.3).normalize(),
    ];
    for n in [1.0, 10.0, 50.0] {
        for wi in dirs {
            let got = f(albedo, n, wo, wi);
            let want = expected_f(albedo, n, wo, wi);
            if close3(got, want, 1e-3) {
                continue;
            }
            let what = format!(
                "n = {n}, wo = {}, wi = {}: your f_r is {}, expected {}",
                fmt3(wo),
                fmt3(wi),
                fmt3(got),
                fmt3(want)
            );
            let why = if want == Color::ZERO {
                "cos α < 0 here: clamp it to 0 (max(0, cos α)) before the power"
            } else if close3(got, want / albedo, 1e-3) {
                "multiply by the albedo ρ_s"
            } else if close3(got, want / expected_s(n), 1e-3) {
                "multiply by S(n)"
            } else if close3(
                got,
                albedo * expected_s(n) * wo.dot(wi).max(0.0).powf(n),
                1e-3,
            ) {
                "α is the angle between wi and the MIRROR direction of wo, not wo itself"
            } else {
                "f_r = ρ_s · S(n) · max(0, cos α)^n"
            };
            return Err(format!("{what} — {why}"));
        }
    }
    Ok(())
}
