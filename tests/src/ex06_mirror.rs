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
        (&crate::tr!("ex06.into_surface"), &|c| -want(c)),
        (&crate::tr!("ex06.plane_part"), &|&(w, n)| w.dot(n) * n - w),
        (&crate::tr!("ex06.longer"), &|&(w, n)| {
            4.0 * w.dot(n) * n - w
        }),
    ];
    let (w, n) = cases[k];
    let why = recognise(&cases, &got, &mistakes, |g, a| close3(g, a, 1e-5)).unwrap_or_else(|| {
        let r = got[k];
        crate::tr!(
            "ex06.unknown",
            length = r.length(),
            angle = r
                .normalize_or_zero()
                .dot(n)
                .clamp(-1.0, 1.0)
                .acos()
                .to_degrees(),
            w_angle = w.dot(n).clamp(-1.0, 1.0).acos().to_degrees(),
            plane = if r.dot(w.cross(n)).abs() < 1e-4 {
                crate::tr!("ex06.in_plane")
            } else {
                crate::tr!("ex06.outside_plane")
            }
        )
    });
    Err(crate::tr!(
        "ex06.reflect",
        w = fmt3(w),
        n = fmt3(n),
        got = fmt3(got[k]),
        want = fmt3(want(&cases[k])),
        why
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
        let what = crate::tr!("ex06.what", r = fmt3(r), wo = fmt3(wo));
        let wi = Vec3A::new(-wo.x, -wo.y, wo.z);
        let Some(s) = sample(r, wo) else {
            return Err(crate::tr!("ex06.none", mirror = fmt3(wi), what));
        };
        if !close3(s.wi, wi, 1e-5) {
            let why = if close3(s.wi, -wo, 1e-5) {
                crate::tr!("ex06.retro")
            } else if close3(s.wi, Vec3A::new(wo.x, wo.y, -wo.z), 1e-5) {
                crate::tr!("ex06.below")
            } else {
                crate::tr!("ex06.not_mirror")
            };
            return Err(crate::tr!(
                "ex06.wi",
                got = fmt3(s.wi),
                want = fmt3(wi),
                what,
                why
            ));
        }
        if !s.is_delta {
            return Err(crate::tr!("ex06.not_delta", what));
        }
        // pdf_w of a delta lobe is the probability of choosing the lobe, as
        // the stub defines it: the mirror's only lobe is always chosen. A
        // pdf that varies with the direction (cos θ_i) may still give the
        // right weight with f = R, but it is no probability of a lobe.
        if !(s.pdf_w > 0.0 && s.pdf_w.is_finite()) {
            return Err(crate::tr!("ex06.pdf_bad", pdf = s.pdf_w, what));
        }
        if (s.pdf_w - 1.0).abs() > 1e-5 {
            let why = if (s.pdf_w - wi.z).abs() < 1e-5 {
                crate::tr!("ex06.pdf_cos")
            } else {
                crate::tr!("ex06.pdf_one")
            };
            return Err(crate::tr!("ex06.pdf", pdf = s.pdf_w, what, why));
        }
        let weight = s.f * (s.wi.z.abs() / s.pdf_w);
        if !close3(weight, r, 1e-4) {
            let why = if close3(weight, r * wi.z, 1e-4) {
                crate::tr!("ex06.weight_cos")
            } else if close3(weight, r / wi.z, 1e-4) {
                crate::tr!("ex06.weight_inv_cos")
            } else {
                let k = weight / r;
                if (k - Vec3A::splat(k.x)).abs().max_element() < 1e-4 {
                    crate::tr!("ex06.weight_scale", k = k.x, cos = wi.z)
                } else {
                    crate::tr!("ex06.weight_colour")
                }
            };
            return Err(crate::tr!("ex06.weight", weight = fmt3(weight), what, why));
        }
        if s.eta != 1.0 {
            return Err(crate::tr!("ex06.eta", eta = s.eta, what));
        }
    }
    // The edge case: on or below the horizon there is nothing to reflect.
    for wo in [Vec3A::new(0.6, 0.8, 0.0), Vec3A::new(0.3, 0.4, -0.866)] {
        if let Some(s) = sample(r, wo) {
            return Err(crate::tr!(
                "ex06.below_horizon",
                wo = fmt3(wo),
                wi = fmt3(s.wi),
                f = fmt3(s.f)
            ));
        }
    }
    Ok(())
}
