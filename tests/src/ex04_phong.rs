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

/// The exponents of the test: integers and not (a lobe's exponent is any
/// real `n ≥ 0`; a formula valid only for integers fails at 0.5, 3.7, 42.5).
pub const EXPONENTS: [f32; 9] = [0.0, 0.5, 1.0, 2.0, 3.7, 10.0, 42.5, 100.0, 1000.0];

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
    let mistakes: [Mistake<f32, f32>; 7] = [
        (
            "(n+1)/(2π) makes ∫ S(n) cos^n θ dω = 1, a probability density without the cosine θ_i of the albedo: the albedo at normal incidence becomes (n+1)/(n+2)·ρ_s < ρ_s — energy is lost",
            &|&n| (n + 1.0) * INV_2PI,
        ),
        (
            "an unnormalized lobe (S = 1): its albedo at normal incidence is 2π/(n+2), far below 1 for large n",
            &|_| 1.0,
        ),
        (
            "you returned the integral ∫ cos^{n+1} θ dω itself, not the constant that makes S(n) times it equal 1",
            &|&n| 1.0 / expected_s(n),
        ),
        (
            "twice too large in every case: as if the integral over φ gave π, half a turn",
            &|&n| (n + 2.0) * 2.0 * INV_2PI,
        ),
        (
            "half the right value in every case: as if the integral ran over the whole sphere of directions, not the hemisphere above the surface",
            &|&n| (n + 2.0) * 0.5 * INV_2PI,
        ),
        (
            "too large by ×π in every case: a missing π (the integral over φ of a full turn brings it)",
            &|&n| (n + 2.0) * 0.5,
        ),
        (
            "right at integer exponents only: your n was rounded to an integer, but a lobe's exponent is any real n ≥ 0 (see n = 0.5, 3.7, 42.5)",
            &|&n| (n.trunc() + 2.0) * INV_2PI,
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
        for n in [1.0, 2.5, 10.0, 50.0] {
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
    let mistakes: [Mistake<Case, Color>; 8] = [
        (
            "your f_r is not zero where cos α < 0 (more than 90° from the mirror direction): a negative cosine went into the power",
            &|c| albedo * expected_s(c.n) * mirror_z(c.wo).dot(c.wi).abs().powf(c.n),
        ),
        (
            "ρ_s is missing: your lobe is that of a white surface",
            &|c| want(c) / albedo,
        ),
        ("S(n) is missing: your lobe is not normalized", &|c| {
            want(c) / expected_s(c.n)
        }),
        (
            "your lobe is centred on ω_o itself: α is measured from its MIRROR direction",
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
            "you raised S(n)·cos α to the power n, not the cosine alone",
            &|c| {
                let cos_a = mirror_z(c.wo).dot(c.wi);
                if cos_a <= 0.0 {
                    Color::ZERO
                } else {
                    albedo * (expected_s(c.n) * cos_a).powf(c.n)
                }
            },
        ),
        (
            "right at integer exponents only: the power was taken of an exponent rounded to an integer (n = 2.5 fails)",
            &|c| {
                lobe(albedo, c.n.trunc(), mirror_z(c.wo).dot(c.wi))
                    * (expected_s(c.n) / expected_s(c.n.trunc()))
            },
        ),
    ];
    // A negative cosine raised to a non-integer power is NaN.
    let negative_power = cases
        .iter()
        .zip(&got)
        .any(|(c, g)| !g.is_finite() && mirror_z(c.wo).dot(c.wi) < 0.0);
    let why = if negative_power {
        Some("your f_r is not zero where cos α < 0 (more than 90° from the mirror direction), and NaN there at n = 2.5: a negative cosine went into the power".to_string())
    } else {
        recognise(&cases, &got, &mistakes, |g, a| close3(g, a, 1e-3))
    }
    .unwrap_or_else(|| symptom(&cases, &got, &want));
    Err(format!(
        "n = {}, wo = {}, wi = {}: your f_r is {}, expected {} — {why}",
        c.n,
        fmt3(c.wo),
        fmt3(c.wi),
        fmt3(got[k]),
        fmt3(want(c))
    ))
}

/// What a wrong `f_r` that no known mistake explains does: a constant
/// factor everywhere (the scale), right at the peak but wrong around it (the
/// shape), or wrong at the peak too.
fn symptom(cases: &[Case], got: &[Color], want: &dyn Fn(&Case) -> Color) -> String {
    let ratios: Vec<f32> = cases
        .iter()
        .zip(got)
        .filter(|(c, _)| want(c).x > 1e-3)
        .map(|(c, g)| g.x / want(c).x)
        .collect();
    let k = ratios.first().copied().unwrap_or(1.0);
    if ratios.iter().all(|r| (r / k - 1.0).abs() < 1e-3) {
        return format!(
            "your f_r is ×{k:.4} the right one in every case: the lobe's shape is right, its scale is not"
        );
    }
    let peak = cases
        .iter()
        .zip(got)
        .filter(|(c, _)| (mirror_z(c.wo).dot(c.wi) - 1.0).abs() < 1e-6)
        .all(|(c, g)| close3(*g, want(c), 1e-3));
    if peak {
        "right at the mirror direction but wrong away from it: the lobe's fall-off with α is wrong"
            .to_string()
    } else {
        "wrong at the mirror direction already, where cos α = 1 and only the constants count"
            .to_string()
    }
}
