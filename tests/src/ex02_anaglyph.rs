//! Grader of exercise 2 (red–cyan anaglyph): exact answers.

use raytracer::math::{Color, luminance};

use crate::stats::{close3, fmt3};

/// The signature of exercise 2.
pub type AnaglyphFn = fn(Color, Color, f32) -> Color;

/// A colour desaturated by `d`.
pub fn desaturate(c: Color, d: f32) -> Color {
    c.lerp(Color::splat(luminance(c)), d)
}

/// The grader's own answer.
pub fn expected(left: Color, right: Color, d: f32) -> Color {
    let (l, r) = (desaturate(left, d), desaturate(right, d));
    Color::new(l.x, r.y, r.z)
}

/// The cases of the test: saturated and grey colours, d from 0 to 1.
pub fn cases() -> Vec<(Color, Color, f32)> {
    let red = Color::new(0.9, 0.1, 0.05);
    let teal = Color::new(0.05, 0.6, 0.8);
    let grey = Color::splat(0.4);
    let odd = Color::new(0.2, 0.9, 0.3);
    vec![
        (red, teal, 0.0),
        (teal, red, 0.0),
        (red, teal, 0.5),
        (odd, red, 0.3),
        (grey, odd, 1.0),
        (teal, odd, 0.75),
    ]
}

/// Exact comparison with diagnostics.
pub fn check(f: AnaglyphFn) -> Result<(), String> {
    for (left, right, d) in cases() {
        let got = f(left, right, d);
        let want = expected(left, right, d);
        if close3(got, want, 1e-4) {
            continue;
        }
        let what = crate::tr!(
            "ex02.what",
            left = fmt3(left),
            right = fmt3(right),
            d,
            got = fmt3(got),
            want = fmt3(want)
        );
        let (l, r) = (desaturate(left, d), desaturate(right, d));
        let why = if close3(got, Color::new(r.x, l.y, l.z), 1e-4) {
            crate::tr!("ex02.swapped")
        } else if close3(got, expected(left, right, 1.0 - d), 1e-4) {
            crate::tr!("ex02.reversed")
        } else if close3(got, expected(left, right, 0.0), 1e-4) {
            crate::tr!("ex02.not_desaturated")
        } else {
            let avg = |c: Color| c.lerp(Color::splat((c.x + c.y + c.z) / 3.0), d);
            let (la, ra) = (avg(left), avg(right));
            if close3(got, Color::new(la.x, ra.y, ra.z), 1e-4) {
                crate::tr!("ex02.average")
            } else {
                let bad: Vec<String> = [
                    crate::tr!("ex02.red"),
                    crate::tr!("ex02.green"),
                    crate::tr!("ex02.blue"),
                ]
                .into_iter()
                .enumerate()
                .filter(|&(k, _)| (got[k] - want[k]).abs() > 1e-4 * want[k].abs().max(1.0))
                .map(|(_, name)| name)
                .collect();
                let plain = cases()
                    .into_iter()
                    .filter(|c| c.2 == 0.0)
                    .all(|(l0, r0, _)| close3(f(l0, r0, 0.0), expected(l0, r0, 0.0), 1e-4));
                let channels = bad.join(&crate::tr!("ex02.and"));
                let why = if plain {
                    crate::tr!("ex02.filters_right")
                } else {
                    crate::tr!("ex02.filters_wrong")
                };
                if bad.len() > 1 {
                    crate::tr!("ex02.wrong_channels", channels, why)
                } else {
                    crate::tr!("ex02.wrong_channel", channels, why)
                }
            }
        };
        return Err(crate::tr!("ex02.failure", what, why));
    }
    Ok(())
}
