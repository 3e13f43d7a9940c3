//! Grader of exercise 5 (perfect mirror): exact answers.

use raytracer::brdf::BrdfSample;
use raytracer::math::{Color, Vec3A};

use crate::stats::{close3, fmt3};

/// The signatures of exercise 5.
pub type ReflectFn = fn(Vec3A, Vec3A) -> Vec3A;
pub type MirrorFn = fn(Color, Vec3A) -> BrdfSample;

pub fn check(reflect: ReflectFn, sample: MirrorFn) -> Result<(), String> {
    let cases = [
        (Vec3A::new(0.3, 0.8, 0.1), Vec3A::Y),
        (Vec3A::new(-0.5, 0.2, 0.7), Vec3A::new(0.2, 0.3, 0.9)),
        (Vec3A::new(0.0, 0.0, 1.0), Vec3A::new(0.0, 0.6, 0.8)),
        (Vec3A::new(1.0, 0.1, 0.0), Vec3A::X),
    ];
    for (w, n) in cases {
        let (w, n) = (w.normalize(), n.normalize());
        let got = reflect(w, n);
        let want = 2.0 * w.dot(n) * n - w;
        if close3(got, want, 1e-5) {
            continue;
        }
        let why = if close3(got, -want, 1e-5) {
            "yours points into the surface: the result must be on the same side of n as w"
        } else {
            "reflect(w, n) keeps the component of w along n and flips the rest"
        };
        return Err(format!(
            "reflect({}, {}) is {}, expected {} — {why}",
            fmt3(w),
            fmt3(n),
            fmt3(got),
            fmt3(want)
        ));
    }
    let r = Color::new(0.9, 0.7, 0.4);
    for wo in [
        Vec3A::Z,
        Vec3A::new(0.5, 0.3, 0.81),
        Vec3A::new(-0.9, 0.1, 0.2),
    ] {
        let wo = wo.normalize();
        let s = sample(r, wo);
        let wi = Vec3A::new(-wo.x, -wo.y, wo.z);
        let what = format!("mirror_sample(R = {}, wo = {})", fmt3(r), fmt3(wo));
        if !close3(s.wi, wi, 1e-5) {
            return Err(format!(
                "{what}: wi is {}, expected the mirror direction {} (normal +z)",
                fmt3(s.wi),
                fmt3(wi)
            ));
        }
        if !s.is_delta {
            return Err(format!(
                "{what}: a mirror is a delta lobe: set is_delta: true"
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
                "it is R·cos θ_i: a delta BRDF's f is R/|cos θ_i|, so that the cosine the integrator multiplies by cancels"
            } else {
                "f must be R/|cos θ_i| with pdf_w = 1"
            };
            return Err(format!(
                "{what}: the weight f·|cos θ_i|/pdf_w of your sample is {}, expected R — {why}",
                fmt3(weight)
            ));
        }
    }
    Ok(())
}
