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
        let what = format!(
            "left {}, right {}, desaturation {d}: yours {}, expected {}",
            fmt3(left),
            fmt3(right),
            fmt3(got),
            fmt3(want)
        );
        let (l, r) = (desaturate(left, d), desaturate(right, d));
        let why = if close3(got, Color::new(r.x, l.y, l.z), 1e-4) {
            "the channels are swapped: your red comes from the right frame and your green and blue from the left, but the red filter is over the left eye".to_string()
        } else if close3(got, expected(left, right, 1.0 - d), 1e-4) {
            "the desaturation is reversed: your colours are greyest where d is smallest".to_string()
        } else if close3(got, expected(left, right, 0.0), 1e-4) {
            "the colours were not desaturated: your pixel is the same whatever d is".to_string()
        } else {
            let avg = |c: Color| c.lerp(Color::splat((c.x + c.y + c.z) / 3.0), d);
            let (la, ra) = (avg(left), avg(right));
            if close3(got, Color::new(la.x, ra.y, ra.z), 1e-4) {
                "your grey is the plain average of the three channels, not the luminance Y(c) of the stub (the eye weighs green far more than blue)".to_string()
            } else {
                let bad: Vec<&str> = [
                    "red (the left eye's)",
                    "green (the right eye's)",
                    "blue (the right eye's)",
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
                format!(
                    "wrong in the {} channel{}; {}",
                    bad.join(" and "),
                    if bad.len() > 1 { "s" } else { "" },
                    if plain {
                        "the cases with d = 0 pass, so the filters are right and the desaturation is not"
                    } else {
                        "wrong with d = 0 too, so the filters' mixing itself is wrong"
                    }
                )
            }
        };
        return Err(format!("{what} — {why}"));
    }
    Ok(())
}
