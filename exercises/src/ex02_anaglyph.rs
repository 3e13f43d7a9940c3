//! Exercise 2 — red–cyan anaglyph with desaturation.
//!
//! Slides: "Anaglyph glasses" ("Анаглифни очила"), "Anaglyphs of saturated
//! scenes" ("Анаглифи на картинки с наситени цветове").
//!
//! Each frame passes through a colour filter, the results are mixed into
//! one frame, and glasses with the same filters let each eye see only its
//! own frame. With saturated colours it helps to "kill" some of the colour
//! first (desaturation).
//!
//! Task: mix one pixel of the left frame and the same pixel of the right
//! frame into the pixel of a red–cyan anaglyph (red filter over the left
//! eye, cyan over the right):
//! 1. desaturate both colours by `d = desaturation ∈ [0, 1]`: `d = 0`
//!    leaves a colour as it is, `d = 1` turns it into the grey of the same
//!    luminance (`raytracer::math::luminance`), and in between the colour
//!    changes linearly with `d` (its luminance stays the same throughout:
//!    check that yours does);
//! 2. each filter lets through its own channels: red for the left eye,
//!    green and blue (cyan) for the right.
//!
//! Receives: linear RGB colours `left`, `right` and `desaturation`.
//! Returns: the anaglyph colour.

use raytracer::math::Color;

/// One pixel of a red–cyan anaglyph.
pub fn anaglyph(left: Color, right: Color, desaturation: f32) -> Color {
    // TODO: desaturate both colours, then keep what each filter lets through.
    todo!()
}
