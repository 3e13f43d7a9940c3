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
        (&crate::tr!("ex05.solid_angle"), &|&t| {
            1.0 / (2.0 * PI * (1.0 - t.cos()))
        }),
        (&crate::tr!("ex05.lambert"), &|_| 1.0 / PI),
        (&crate::tr!("ex05.small_angle"), &|&t| 1.0 / (PI * t * t)),
        (&crate::tr!("ex05.integral"), &|&t| PI * sin2(t)),
        (&crate::tr!("ex05.half"), &|&t| 1.0 / (2.0 * PI * sin2(t))),
        (&crate::tr!("ex05.twice"), &|&t| 2.0 / (PI * sin2(t))),
        (&crate::tr!("ex05.pi"), &|&t| 1.0 / sin2(t)),
        (&crate::tr!("ex05.degrees"), &|&t| {
            let s = (t * PI / 180.0).sin();
            1.0 / (PI * s * s)
        }),
    ];
    let t = ANGLES[k];
    let why = recognise(&ANGLES, &got, &mistakes, |g, a| close(g, a, 1e-4)).unwrap_or_else(|| {
        // The albedo at normal incidence is ρ·C·π sin²θ_m: too large a C
        // creates energy, too small a one loses it.
        if got[k] > expected(t) {
            crate::tr!("ex05.albedo_bright")
        } else {
            crate::tr!("ex05.albedo_dark")
        }
    });
    Err(crate::tr!(
        "ex05.c",
        t,
        degrees = t.to_degrees(),
        got = got[k],
        why
    ))
}
