//! Grader of exercise 2 (red–cyan anaglyph with desaturation).
//!
//! The desaturation is graded by its properties — unchanged at `d = 0`, a
//! grey at `d = 1`, the luminance kept at every `d`, the hue kept and the
//! colourfulness never growing with `d` — not against one formula; the
//! anaglyph against the student's own desaturation, exactly.

use raytracer::math::{Color, luminance};

use crate::stats::{close3, fmt3};

/// The signatures of exercise 2.
pub type DesaturateFn = fn(Color, f32) -> Color;
pub type AnaglyphFn = fn(Color, Color, f32) -> Color;

/// A colour desaturated by `d` along the straight line to the grey of the
/// same luminance (the grader's own, for the tables).
pub fn desaturate(c: Color, d: f32) -> Color {
    c.lerp(Color::splat(luminance(c)), d)
}

/// The grader's anaglyph.
pub fn expected(left: Color, right: Color, d: f32) -> Color {
    let (l, r) = (desaturate(left, d), desaturate(right, d));
    Color::new(l.x, r.y, r.z)
}

/// Colours of the desaturation test: saturated primaries and mixtures, a
/// grey, a bright one.
pub fn colours() -> Vec<Color> {
    vec![
        Color::new(0.9, 0.1, 0.05),
        Color::new(0.05, 0.6, 0.8),
        Color::new(0.2, 0.9, 0.3),
        Color::new(0.0, 0.0, 1.0),
        Color::splat(0.4),
        Color::new(3.0, 1.5, 0.2),
    ]
}

/// The amounts of the test, increasing.
pub const AMOUNTS: [f32; 6] = [0.0, 0.2, 0.5, 0.7, 0.9, 1.0];

/// The cases of the anaglyph test: saturated and grey colours, d from 0 to 1.
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

pub fn check(desat: DesaturateFn, f: AnaglyphFn) -> Result<(), String> {
    check_desaturate(desat)?;
    check_anaglyph(desat, f)
}

/// The properties of a desaturation, colour by colour.
fn check_desaturate(desat: DesaturateFn) -> Result<(), String> {
    for c in colours() {
        let y = luminance(c);
        let tol = 1e-4 * y.max(1.0);
        // Colourfulness: the difference from the grey of the same luminance.
        let chroma = |x: Color| x - Color::splat(y);
        let mut previous = chroma(c).length();
        for d in AMOUNTS {
            let got = desat(c, d);
            let what = crate::tr!("ex02.desat_what", c = fmt3(c), d, got = fmt3(got));
            if !got.is_finite() {
                return Err(crate::tr!("ex02.desat_nan", what));
            }
            if d == 0.0 && !close3(got, c, 1e-5) {
                let why = if close3(got, Color::splat(got.x), 1e-5) {
                    crate::tr!("ex02.reversed")
                } else {
                    String::new()
                };
                return Err(crate::tr!("ex02.desat_changed", what, why));
            }
            let yg = luminance(got);
            if (yg - y).abs() > tol {
                let mean = (c.x + c.y + c.z) / 3.0;
                let why = if close3(got, c.lerp(Color::splat(mean), d), 1e-4) {
                    crate::tr!("ex02.average")
                } else if yg > y {
                    crate::tr!("ex02.brighter")
                } else {
                    crate::tr!("ex02.darker")
                };
                return Err(crate::tr!("ex02.desat_luminance", what, yg, y, why));
            }
            if d == 1.0 && got.max_element() - got.min_element() > tol {
                return Err(crate::tr!("ex02.desat_not_grey", what));
            }
            // The hue kept: the difference from the grey stays a non-negative
            // multiple of the colour's own.
            let (a, b) = (chroma(c), chroma(got));
            let k = if a.length_squared() > 0.0 {
                a.dot(b) / a.length_squared()
            } else {
                0.0
            };
            if (b - k * a).length() > tol || k < -tol {
                return Err(crate::tr!("ex02.desat_hue", what));
            }
            if b.length() > previous + tol {
                return Err(crate::tr!("ex02.desat_more", what));
            }
            previous = b.length();
        }
    }
    Ok(())
}

/// The filters, against the student's own desaturation.
fn check_anaglyph(desat: DesaturateFn, f: AnaglyphFn) -> Result<(), String> {
    let mixed = |left: Color, right: Color, d: f32| {
        let (l, r) = (desat(left, d), desat(right, d));
        Color::new(l.x, r.y, r.z)
    };
    for (left, right, d) in cases() {
        let got = f(left, right, d);
        let want = mixed(left, right, d);
        if close3(got, want, 1e-4) {
            continue;
        }
        let what = crate::tr!(
            "ex02.what",
            left = fmt3(left),
            right = fmt3(right),
            d,
            got = fmt3(got)
        );
        let (l, r) = (desat(left, d), desat(right, d));
        let why = if close3(got, Color::new(r.x, l.y, l.z), 1e-4) {
            crate::tr!("ex02.swapped")
        } else if close3(got, mixed(left, right, 0.0), 1e-4) {
            crate::tr!("ex02.not_desaturated")
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
                .all(|(l0, r0, _)| close3(f(l0, r0, 0.0), mixed(l0, r0, 0.0), 1e-4));
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
        };
        return Err(crate::tr!("ex02.failure", what, why));
    }
    Ok(())
}
