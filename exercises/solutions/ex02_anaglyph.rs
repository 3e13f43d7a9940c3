//! Reference solution of exercise 2 (see `src/ex02_anaglyph.rs` for the task).

use raytracer::math::{Color, luminance};

/// `c` desaturated by `d ∈ [0, 1]`, keeping its luminance.
///
/// The grey `(g, g, g)` has luminance `g·(w_R + w_G + w_B) = g` (the weights
/// sum to 1), so the grey of the same luminance is `g = Y(c)`. Luminance is
/// linear, so every point `(1 − d)·c + d·(Y, Y, Y)` of the straight line has
/// luminance `(1 − d)·Y + d·Y = Y`; the difference from the grey is
/// `(1 − d)·(c − (Y, Y, Y))`: same direction, shrinking with `d`.
pub fn desaturate(c: Color, d: f32) -> Color {
    c.lerp(Color::splat(luminance(c)), d)
}

/// One pixel of a red–cyan anaglyph.
pub fn anaglyph(left: Color, right: Color, desaturation: f32) -> Color {
    let (l, r) = (
        desaturate(left, desaturation),
        desaturate(right, desaturation),
    );
    Color::new(l.x, r.y, r.z)
}
