//! Grader of exercise 6 (perfect mirror): exact answers, including the edge
//! case `wo.z ≤ 0`.

use raytracer::brdf::BrdfSample;
use raytracer::math::{Color, Vec3A};

use crate::stats::{Mistake, close3, fmt3, recognise};

/// The signatures of exercise 6.
pub type ReflectFn = fn(Vec3A, Vec3A) -> Vec3A;
pub type MirrorFn = fn(Color, Vec3A) -> Option<BrdfSample>;

pub fn check(reflect: ReflectFn, sample: MirrorFn) -> Result<(), String> {
    check_reflect(reflect)?;
    check_sample(sample)
}

fn check_reflect(reflect: ReflectFn) -> Result<(), String> {
    let cases: Vec<(Vec3A, Vec3A)> = [
        (Vec3A::new(0.3, 0.8, 0.1), Vec3A::Y),
        (Vec3A::new(-0.5, 0.2, 0.7), Vec3A::new(0.2, 0.3, 0.9)),
        (Vec3A::new(0.0, 0.0, 1.0), Vec3A::new(0.0, 0.6, 0.8)),
        (Vec3A::new(1.0, 0.1, 0.0), Vec3A::X),
        (Vec3A::new(0.2, -0.9, 0.3), Vec3A::new(0.5, -0.5, 0.7)),
    ]
    .into_iter()
    .map(|(w, n)| (w.normalize(), n.normalize()))
    .collect();
    let want = |&(w, n): &(Vec3A, Vec3A)| 2.0 * w.dot(n) * n - w;
    let got: Vec<Vec3A> = cases.iter().map(|&(w, n)| reflect(w, n)).collect();
    let Some(k) = (0..cases.len()).find(|&k| !close3(got[k], want(&cases[k]), 1e-5)) else {
        return Ok(());
    };
    let mistakes: [Mistake<(Vec3A, Vec3A), Vec3A>; 3] = [
        (
            "yours points into the surface: w − 2(w·n)n mirrors about the surface's plane; the mirror direction stays on the side of n, as w does",
            &|c| -want(c),
        ),
        (
            "(w·n)n − w is the part of w in the plane, reversed; the part along n must be kept: add (w·n)n once more",
            &|&(w, n)| w.dot(n) * n - w,
        ),
        (
            "a reflection keeps the length of w: the factor of (w·n)n is 2",
            &|&(w, n)| 4.0 * w.dot(n) * n - w,
        ),
    ];
    let (w, n) = cases[k];
    let why = recognise(&cases, &got, &mistakes, |g, a| close3(g, a, 1e-5)).unwrap_or_else(|| {
        "the result must keep the component of w along n and reverse the rest".to_string()
    });
    Err(format!(
        "reflect({}, {}) is {}, expected {} — {why}",
        fmt3(w),
        fmt3(n),
        fmt3(got[k]),
        fmt3(want(&cases[k]))
    ))
}

fn check_sample(sample: MirrorFn) -> Result<(), String> {
    let r = Color::new(0.9, 0.7, 0.4);
    for wo in [
        Vec3A::Z,
        Vec3A::new(0.5, 0.3, 0.81),
        Vec3A::new(-0.9, 0.1, 0.2),
        Vec3A::new(0.3, -0.95, 0.05),
    ] {
        let wo = wo.normalize();
        let what = format!("mirror_sample(R = {}, wo = {})", fmt3(r), fmt3(wo));
        let wi = Vec3A::new(-wo.x, -wo.y, wo.z);
        let Some(s) = sample(r, wo) else {
            return Err(format!(
                "{what}: you returned None, but wo is above the surface: the mirror reflects it to {}",
                fmt3(wi)
            ));
        };
        if !close3(s.wi, wi, 1e-5) {
            let why = if close3(s.wi, -wo, 1e-5) {
                "−wo sends the light straight back (a retro-reflector): the mirror keeps the normal component of wo and reverses the tangential one"
            } else if close3(s.wi, Vec3A::new(wo.x, wo.y, -wo.z), 1e-5) {
                "that points below the surface: both wo and wi point away from it, and the mirror direction keeps wo.z"
            } else {
                "wi is the mirror direction of wo about the normal +z"
            };
            return Err(format!(
                "{what}: wi is {}, expected {} — {why}",
                fmt3(s.wi),
                fmt3(wi)
            ));
        }
        if !s.is_delta {
            return Err(format!(
                "{what}: a mirror is a delta lobe: set is_delta: true (the integrators then know not to evaluate it or weigh it by MIS)"
            ));
        }
        if !(s.pdf_w > 0.0 && s.pdf_w.is_finite()) {
            return Err(format!(
                "{what}: pdf_w is {}, expected 1 (the only lobe, always chosen)",
                s.pdf_w
            ));
        }
        let weight = s.f * (s.wi.z.abs() / s.pdf_w);
        if !close3(weight, r, 1e-4) {
            let why = if close3(weight, r * wi.z, 1e-4) {
                "it is R·cos θ_i: f = R alone is not the delta's value — ∫ f_r L_i cos θ_i dω_i = R·L_i needs f = R/|cos θ_i|, so that the cosine the integrator multiplies by cancels"
            } else if close3(weight, r / wi.z, 1e-4) {
                "it is R/cos θ_i: divide by |cos θ_i| once (in f), the integrator multiplies by it once"
            } else {
                "f must be R/|cos θ_i| with pdf_w = 1"
            };
            return Err(format!(
                "{what}: the weight f·|cos θ_i|/pdf_w of your sample is {}, expected R — {why}",
                fmt3(weight)
            ));
        }
        if s.eta != 1.0 {
            return Err(format!(
                "{what}: eta is {}, expected 1 (reflection crosses no interface)",
                s.eta
            ));
        }
    }
    // The edge case: on or below the horizon there is nothing to reflect.
    for wo in [Vec3A::new(0.6, 0.8, 0.0), Vec3A::new(0.3, 0.4, -0.866)] {
        if let Some(s) = sample(r, wo) {
            return Err(format!(
                "mirror_sample(R, wo = {}) returned a sample (wi = {}, f = {}): for wo.z ≤ 0 return None — at wo.z = 0 the mirror direction lies in the surface and f = R/|cos θ_i| is infinite",
                fmt3(wo),
                fmt3(s.wi),
                fmt3(s.f)
            ));
        }
    }
    Ok(())
}
