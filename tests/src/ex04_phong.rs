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
        (&crate::tr!("ex04.s_density"), &|&n| (n + 1.0) * INV_2PI),
        (&crate::tr!("ex04.s_unnormalized"), &|_| 1.0),
        (&crate::tr!("ex04.s_integral"), &|&n| 1.0 / expected_s(n)),
        (&crate::tr!("ex04.s_twice"), &|&n| (n + 2.0) * 2.0 * INV_2PI),
        (&crate::tr!("ex04.s_half"), &|&n| (n + 2.0) * 0.5 * INV_2PI),
        (&crate::tr!("ex04.s_pi"), &|&n| (n + 2.0) * 0.5),
        (&crate::tr!("ex04.s_integer"), &|&n| {
            (n.trunc() + 2.0) * INV_2PI
        }),
    ];
    let n = EXPONENTS[k];
    let why =
        recognise(&EXPONENTS, &got, &mistakes, |g, a| close(g, a, 1e-4)).unwrap_or_else(|| {
            // The albedo at normal incidence is S(n)·2π/(n+2): too large an
            // S creates energy, too small a one loses it.
            if got[k] > expected_s(n) {
                crate::tr!("ex04.s_bright")
            } else {
                crate::tr!("ex04.s_dark")
            }
        });
    Err(crate::tr!("ex04.s", n, got = got[k], why))
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
        (&crate::tr!("ex04.f_negative"), &|c| {
            albedo * expected_s(c.n) * mirror_z(c.wo).dot(c.wi).abs().powf(c.n)
        }),
        (&crate::tr!("ex04.f_albedo"), &|c| want(c) / albedo),
        (&crate::tr!("ex04.f_s"), &|c| want(c) / expected_s(c.n)),
        (&crate::tr!("ex04.f_wo"), &|c| {
            lobe(albedo, c.n, c.wo.dot(c.wi))
        }),
        (&crate::tr!("ex04.f_normal"), &|c| lobe(albedo, c.n, c.wi.z)),
        (&crate::tr!("ex04.f_minus_wi"), &|c| {
            lobe(albedo, c.n, -mirror_z(c.wo).dot(c.wi))
        }),
        (&crate::tr!("ex04.f_power"), &|c| {
            let cos_a = mirror_z(c.wo).dot(c.wi);
            if cos_a <= 0.0 {
                Color::ZERO
            } else {
                albedo * (expected_s(c.n) * cos_a).powf(c.n)
            }
        }),
        (&crate::tr!("ex04.f_integer"), &|c| {
            lobe(albedo, c.n.trunc(), mirror_z(c.wo).dot(c.wi))
                * (expected_s(c.n) / expected_s(c.n.trunc()))
        }),
    ];
    // A negative cosine raised to a non-integer power is NaN.
    let negative_power = cases
        .iter()
        .zip(&got)
        .any(|(c, g)| !g.is_finite() && mirror_z(c.wo).dot(c.wi) < 0.0);
    let why = if negative_power {
        Some(crate::tr!("ex04.f_nan"))
    } else {
        recognise(&cases, &got, &mistakes, |g, a| close3(g, a, 1e-3))
    }
    .unwrap_or_else(|| symptom(&cases, &got, &want));
    Err(crate::tr!(
        "ex04.f",
        n = c.n,
        wo = fmt3(c.wo),
        wi = fmt3(c.wi),
        got = fmt3(got[k]),
        why
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
        return if k > 1.0 {
            crate::tr!("ex04.scale_bright")
        } else {
            crate::tr!("ex04.scale_dark")
        };
    }
    let peak = cases
        .iter()
        .zip(got)
        .filter(|(c, _)| (mirror_z(c.wo).dot(c.wi) - 1.0).abs() < 1e-6)
        .all(|(c, g)| close3(*g, want(c), 1e-3));
    if peak {
        crate::tr!("ex04.peak_right")
    } else {
        crate::tr!("ex04.peak_wrong")
    }
}
