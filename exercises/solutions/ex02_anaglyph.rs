//! Reference solution of exercise 2 (see `src/ex02_anaglyph.rs` for the task).

use raytracer::math::{Color, luminance};

/// One pixel of a red–cyan anaglyph.
pub fn anaglyph(left: Color, right: Color, desaturation: f32) -> Color {
    let desaturate = |c: Color| c.lerp(Color::splat(luminance(c)), desaturation);
    let (l, r) = (desaturate(left), desaturate(right));
    Color::new(l.x, r.y, r.z)
}
