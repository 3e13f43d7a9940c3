//! Crosstalk: what each eye sees through imperfect filters (ghosting).
//!
//! Lecture topic: a drawback of anaglyph (and polarising) glasses — if the
//! filters are not perfect, part of the wrong frame shows through, a faint
//! double image called ghosting.
//!
//! A filter with leakage `k` passes its own channels fully and a fraction `k`
//! of the others: `t = t_ideal + k (1 − t_ideal)`. What the eye behind it
//! gets from an anaglyph pixel `c` is the light `t ⊙ c`; we show its
//! brightness as a grey value, normalized so that white stays white:
//!
//! ```text
//!   seen = w · (t ⊙ c) / (w · t)        (w = luminance weights)
//! ```
//!
//! For glasses without colour (shutter, polarised), [`leak_pair`] mixes a
//! fraction `k` of the other eye's image into each eye.

use super::anaglyph::{Anaglyph, LUMA, assert_same_size};
use super::rig::Eye;
use crate::film::Image;
use crate::math::{Color, Vec3A};

/// The transmission of `eye`'s filter with leakage `k` ∈ [0, 1].
#[inline]
pub fn leaky_filter(glasses: Anaglyph, eye: Eye, leakage: f32) -> Color {
    let t = glasses.filter(eye);
    t + leakage * (Vec3A::ONE - t)
}

/// What `eye` sees of the anaglyph `image` through `glasses` whose filters
/// leak `leakage` of the other channels, as a grey image (see module doc).
pub fn eye_view(image: &Image, glasses: Anaglyph, eye: Eye, leakage: f32) -> Image {
    let t = leaky_filter(glasses, eye, leakage);
    let norm = 1.0 / LUMA.dot(t);
    image.map(|c| Vec3A::splat(LUMA.dot(t * c) * norm))
}

/// Both eyes' views of an anaglyph, left first.
pub fn eye_views(image: &Image, glasses: Anaglyph, leakage: f32) -> [Image; 2] {
    Eye::BOTH.map(|e| eye_view(image, glasses, e, leakage))
}

/// A two-image display whose separation leaks: each eye sees
/// `(1 − k) · own + k · other`.
pub fn leak_pair(left: &Image, right: &Image, leakage: f32) -> [Image; 2] {
    assert_same_size(left, right);
    let mix = |a: &Image, b: &Image| Image {
        width: a.width,
        height: a.height,
        pixels: a
            .pixels
            .iter()
            .zip(&b.pixels)
            .map(|(&x, &y)| x + leakage * (y - x))
            .collect(),
    };
    [mix(left, right), mix(right, left)]
}
