//! Exercise 2 — red–cyan anaglyph with desaturation.
//!
//! Slides: "Anaglyph glasses" ("Анаглифни очила"): each frame passes through
//! a colour filter, the results are mixed into one frame; glasses with the
//! same filters let each eye see only its own frame. With saturated colours
//! it helps to "kill" some of the colour first (desaturation).
//!
//! Task: mix one pixel of the left frame and the same pixel of the right
//! frame into the pixel of a red–cyan anaglyph (red filter over the left eye,
//! cyan over the right):
//! 1. desaturate both colours: `c' = (1 − d)·c + d·Y(c)`, where
//!    `Y(c) = raytracer::math::luminance(c)` is the grey of the same
//!    brightness and `d = desaturation ∈ [0, 1]` (0: unchanged, 1: grey);
//! 2. the red channel of the result comes from the left eye's `c'`, green and
//!    blue (cyan) from the right eye's `c'`.
//!
//! Receives: linear RGB colours `left`, `right` and `desaturation`.
//! Returns: the anaglyph colour.

use raytracer::math::Color;

/// One pixel of a red–cyan anaglyph.
pub fn anaglyph(left: Color, right: Color, desaturation: f32) -> Color {
    // TODO: desaturate both colours, then take red from the left and
    // green and blue from the right.
    todo!()
}
