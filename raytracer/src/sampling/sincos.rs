//! Sine and cosine of the angles the warps draw, without a library call.
//!
//! Lecture topic: Monte Carlo sampling (the step from uniform numbers to a
//! direction). Every cosine-weighted bounce of a path turns an angle into
//! `(cos φ, sin φ)`; the C library's `sincosf` reduces arbitrary arguments
//! and showed up as a few per cent of a path tracer's profile. The warps
//! only ever need angles they built themselves, so the reduction is exact
//! and cheap:
//!
//! - on `|x| ≤ π/4` the Taylor polynomials
//!   `sin x = x − x³/3! + x⁵/5! − x⁷/7! + x⁹/9!` and
//!   `cos x = 1 − x²/2! + x⁴/4! − x⁶/6! + x⁸/8! − x¹⁰/10!`
//!   are off by less than the next term, `(π/4)¹¹/11! < 2·10⁻⁹` and
//!   `(π/4)¹²/12! < 2·10⁻¹⁰`, far below an `f32` ulp of 1 (6·10⁻⁸), so the
//!   results are as accurate as `sincosf`'s up to rounding in the last bit;
//! - a full turn `2π·u` is split into quarter turns `k` and a remainder
//!   `x = (π/2)(4u − k)`, `|x| ≤ π/4` (`4u − k` is exact in floating point),
//!   and rotated back by `k` quarter turns, which only swaps and negates.

use crate::math::PI;

/// `(sin x, cos x)` for `|x| ≤ π/4` (see the module doc for the error).
#[inline(always)]
pub fn sincos_small(x: f32) -> (f32, f32) {
    let x2 = x * x;
    // Horner form of the Taylor polynomials, the highest power innermost.
    let s = x
        * (1.0
            + x2 * (-1.0 / 6.0
                + x2 * (1.0 / 120.0 + x2 * (-1.0 / 5040.0 + x2 * (1.0 / 362_880.0)))));
    let c = 1.0
        + x2 * (-0.5
            + x2 * (1.0 / 24.0
                + x2 * (-1.0 / 720.0 + x2 * (1.0 / 40_320.0 + x2 * (-1.0 / 3_628_800.0)))));
    (s, c)
}

/// `(sin 2πu, cos 2πu)` for `u ∈ [0, 1]` (the azimuth of a warp).
#[inline(always)]
pub fn sincos_turn(u: f32) -> (f32, f32) {
    // 2πu = (π/2)(k + r) with k the nearest quarter turn and |r| ≤ ½.
    let q = 4.0 * u;
    let k = (q + 0.5).floor();
    let (s, c) = sincos_small((PI / 2.0) * (q - k));
    // Rotating by k quarter turns: (sin, cos)(θ + kπ/2).
    match (k as i32) & 3 {
        0 => (s, c),
        1 => (c, -s),
        2 => (-s, -c),
        _ => (-c, s),
    }
}
