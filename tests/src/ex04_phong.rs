//! Grader of exercise 4 (normalized Phong): exact values of `S(n)` and
//! `f_r`; a wrong answer is compared with the answers of the usual mistakes
//! in every case at once, and the matching one is named.

use raytracer::math::{Color, INV_2PI, Vec3A};

use crate::stats::{Mistake, close, close3, fmt3, recognise};

/// The signatures of exercise 4.
pub type NormFn = fn(f32) -> f32;
pub type PhongFn = fn(Color, f32, Vec3A, Vec3A) -> Color;

/// The grader's `S(n)`.
pub fn expected_s(n: f32) -> f32 {
    (n + 2.0) * INV_2PI
}

/// The mirror direction of `w` about `+z`.
fn mirror_z(w: Vec3A) -> Vec3A {
    Vec3A::new(-w.x, -w.y, w.z)
}

/// `ρ_s S(n) max(0, c)^n` for a cosine `c`.
fn lobe(albedo: Color, n: f32, c: f32) -> Color {
    if c <= 0.0 {
        Color::ZERO
    } else {
        albedo * expected_s(n) * c.min(1.0).powf(n)
    }
}

/// The grader's `f_r`.
pub fn expected_f(albedo: Color, n: f32, wo: Vec3A, wi: Vec3A) -> Color {
    lobe(albedo, n, mirror_z(wo).dot(wi))
}

/// The exponents of the test.
pub const EXPONENTS: [f32; 6] = [0.0, 1.0, 2.0, 10.0, 100.0, 1000.0];

pub fn check(s: NormFn, f: PhongFn) -> Result<(), String> {
    check_normalization(s)?;
    check_eval(f)
}

fn check_normalization(s: NormFn) -> Result<(), String> {
    let got: Vec<f32> = EXPONENTS.iter().map(|&n| s(n)).collect();
    let Some(k) = (0..EXPONENTS.len()).find(|&k| !close(got[k], expected_s(EXPONENTS[k]), 1e-4))
    else {
        return Ok(());
    };
    let mistakes: [Mistake<f32, f32>; 5] = [
        (
            "(n+1)/(2π) makes ∫ S(n) cos^n θ dω = 1, a probability density without the cosine θ_i of the albedo: the albedo at normal incidence becomes (n+1)/(n+2)·ρ_s < ρ_s — energy is lost",
            &|&n| (n + 1.0) * INV_2PI,
        ),
        (
            "an unnormalized lobe (S = 1): its albedo at normal incidence is 2π/(n+2), far below 1 for large n",
            &|_| 1.0,
        ),
        (
            "that is the integral ∫ cos^{n+1} θ dω itself: S(n) is one over it",
            &|&n| 1.0 / expected_s(n),
        ),
        ("(n+2)/π: the φ integral gives 2π, not π", &|&n| {
            (n + 2.0) * 2.0 * INV_2PI
        }),
        (
            "(n+2)/(4π): the lobe lies in one hemisphere, 2π of φ times ∫_0^1 t^{n+1} dt",
            &|&n| (n + 2.0) * 0.5 * INV_2PI,
        ),
    ];
    let n = EXPONENTS[k];
    let why =
        recognise(&EXPONENTS, &got, &mistakes, |g, a| close(g, a, 1e-4)).unwrap_or_else(|| {
            format!(
                "with it the albedo at normal incidence would be {:.3}·ρ_s instead of ρ_s",
                got[k] / expected_s(n)
            )
        });
    Err(format!(
        "S({n}) is {}, expected {} — {why}",
        got[k],
        expected_s(n)
    ))
}

/// One case of `phong_eval`.
struct Case {
    n: f32,
    wo: Vec3A,
    wi: Vec3A,
}

fn check_eval(f: PhongFn) -> Result<(), String> {
    let albedo = Color::new(0.9, 0.6, 0.3);
    let mut cases = Vec::new();
    for wo in [
        Vec3A::new(0.4, -0.2, 0.89).normalize(),
        Vec3A::new(-0.6, 0.3, 0.5).normalize(),
    ] {
        let mirror = mirror_z(wo);
        let dirs = [
            mirror,
            (mirror + Vec3A::new(0.1, 0.05, 0.0)).normalize(),
            (mirror + Vec3A::new(-0.3, 0.2, 0.1)).normalize(),
            Vec3A::Z,
            (Vec3A::Z + Vec3A::new(0.2, -0.1, 0.0)).normalize(),
            // Upper hemisphere, but more than 90° from the mirror direction.
            Vec3A::new(-3.0 * mirror.x, -3.0 * mirror.y, 0.2).normalize(),
        ];
        for n in [1.0, 10.0, 50.0] {
            for wi in dirs {
                cases.push(Case { n, wo, wi });
            }
        }
    }
    let got: Vec<Color> = cases.iter().map(|c| f(albedo, c.n, c.wo, c.wi)).collect();
    let want = |c: &Case| expected_f(albedo, c.n, c.wo, c.wi);
    let Some(k) = (0..cases.len()).find(|&k| !close3(got[k], want(&cases[k]), 1e-3)) else {
        return Ok(());
    };
    let c = &cases[k];
    let mistakes: [Mistake<Case, Color>; 7] = [
        (
            "cos α < 0 somewhere: return black there (max(0, cos α)) before taking the power",
            &|c| albedo * expected_s(c.n) * mirror_z(c.wo).dot(c.wi).abs().powf(c.n),
        ),
        ("multiply by the albedo ρ_s", &|c| want(c) / albedo),
        ("multiply by S(n)", &|c| want(c) / expected_s(c.n)),
        (
            "α is the angle between wi and the MIRROR direction of wo, not wo itself",
            &|c| lobe(albedo, c.n, c.wo.dot(c.wi)),
        ),
        (
            "your cos α is wi.z, the angle from the normal: α is measured from the mirror direction of wo (reflect(ω_o)), which is the normal only at normal incidence",
            &|c| lobe(albedo, c.n, c.wi.z),
        ),
        (
            "you mirrored −ω_i, the lecture's incoming direction: here ω_i points away from the surface, and the angle is between ω_i and reflect(ω_o)",
            &|c| lobe(albedo, c.n, -mirror_z(c.wo).dot(c.wi)),
        ),
        (
            "the exponent n belongs on cos α, not on S(n)·cos α",
            &|c| {
                let cos_a = mirror_z(c.wo).dot(c.wi);
                if cos_a <= 0.0 {
                    Color::ZERO
                } else {
                    albedo * (expected_s(c.n) * cos_a).powf(c.n)
                }
            },
        ),
    ];
    let why = recognise(&cases, &got, &mistakes, |g, a| close3(g, a, 1e-3))
        .unwrap_or_else(|| "f_r = ρ_s · S(n) · max(0, cos α)^n".to_string());
    Err(format!(
        "n = {}, wo = {}, wi = {}: your f_r is {}, expected {} — {why}",
        c.n,
        fmt3(c.wo),
        fmt3(c.wi),
        fmt3(got[k]),
        fmt3(want(c))
    ))
}
