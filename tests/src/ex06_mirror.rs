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
            "yours points into the surface: you mirrored w through the surface's plane, but the mirror direction stays on the side of n, as w does",
            &|c| -want(c),
        ),
        (
            "yours is only the part of w in the surface's plane, reversed: the part along n is missing (the result is shorter than w)",
            &|&(w, n)| w.dot(n) * n - w,
        ),
        (
            "yours is longer than w: the part along n was added too many times (a reflection keeps the length)",
            &|&(w, n)| 4.0 * w.dot(n) * n - w,
        ),
    ];
    let (w, n) = cases[k];
    let why = recognise(&cases, &got, &mistakes, |g, a| close3(g, a, 1e-5)).unwrap_or_else(|| {
        let r = got[k];
        format!(
            "yours has length {:.4} (w has 1), makes an angle of {:.1}° with n (w makes {:.1}°), and lies {} the plane of w and n",
            r.length(),
            r.normalize_or_zero().dot(n).clamp(-1.0, 1.0).acos().to_degrees(),
            w.dot(n).clamp(-1.0, 1.0).acos().to_degrees(),
            if r.dot(w.cross(n)).abs() < 1e-4 { "in" } else { "outside" }
        )
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
                "−wo sends the light straight back (a retro-reflector), and points below the surface"
            } else if close3(s.wi, Vec3A::new(wo.x, wo.y, -wo.z), 1e-5) {
                "that points below the surface (wi.z < 0): both wo and wi point away from it"
            } else {
                "that is not the mirror direction of wo about the normal +z"
            };
            return Err(format!(
                "{what}: wi is {}, expected {} — {why}",
                fmt3(s.wi),
                fmt3(wi)
            ));
        }
        if !s.is_delta {
            return Err(format!(
                "{what}: a mirror is a delta lobe, but your sample says is_delta = false (the integrators would then try to evaluate it and weigh it by MIS)"
            ));
        }
        // pdf_w of a delta lobe is the probability of choosing the lobe, as
        // the stub defines it: the mirror's only lobe is always chosen. A
        // pdf that varies with the direction (cos θ_i) may still give the
        // right weight with f = R, but it is no probability of a lobe.
        if !(s.pdf_w > 0.0 && s.pdf_w.is_finite()) {
            return Err(format!(
                "{what}: pdf_w is {} — a probability of choosing the lobe must be positive and finite",
                s.pdf_w
            ));
        }
        if (s.pdf_w - 1.0).abs() > 1e-5 {
            let why = if (s.pdf_w - wi.z).abs() < 1e-5 {
                "it equals cos θ_i: your pdf_w changes with the direction, as a density over directions would, but a delta lobe has no density over directions; pdf_w of a delta lobe is the probability that the sampler picks this lobe, and the mirror's one lobe is picked every time"
            } else {
                "pdf_w of a delta lobe is the probability that the sampler picks this lobe, and the mirror's one lobe is picked every time (a probability below 1 would mean another lobe is picked otherwise)"
            };
            return Err(format!("{what}: pdf_w is {} — {why}", s.pdf_w));
        }
        let weight = s.f * (s.wi.z.abs() / s.pdf_w);
        if !close3(weight, r, 1e-4) {
            let why = if close3(weight, r * wi.z, 1e-4) {
                "it is R·cos θ_i: too dark at grazing angles — your f is the reflectance itself, and the integrator's |cos θ_i| is left in the weight, though a mirror reflects R of the light at every angle".to_string()
            } else if close3(weight, r / wi.z, 1e-4) {
                "it is R/cos θ_i: too bright at grazing angles — the cosine was divided out twice"
                    .to_string()
            } else {
                let k = weight / r;
                if (k - Vec3A::splat(k.x)).abs().max_element() < 1e-4 {
                    format!(
                        "the weight is ×{:.4} of R at cos θ_i = {:.4}: the scale of f is wrong",
                        k.x, wi.z
                    )
                } else {
                    "the weight's colour differs from R's: f is not R's colour scaled".to_string()
                }
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
                "mirror_sample(R, wo = {}) returned a sample (wi = {}, f = {}) for wo on or below the surface (wo.z ≤ 0): there is no reflected direction above the surface there (at wo.z = 0 it lies in the surface, where the delta's weight per unit cos θ_i is infinite)",
                fmt3(wo),
                fmt3(s.wi),
                fmt3(s.f)
            ));
        }
    }
    Ok(())
}
