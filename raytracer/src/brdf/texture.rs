//! Textures: a colour as a function of the surface's `(u, v)` coordinates.

use std::sync::Arc;

use crate::math::Color;

/// A colour over the surface.
#[derive(Clone, Debug)]
pub enum Texture {
    Constant(Color),
    /// Alternating squares of `a` and `b`, `scale` squares per unit of `u` and `v`.
    Checker {
        a: Color,
        b: Color,
        scale: f32,
    },
    Image(Arc<ImageTexture>),
}

/// An RGB image in linear colour (sRGB PNGs are decoded to linear on load).
#[derive(Clone, Debug, PartialEq)]
pub struct ImageTexture {
    pub width: u32,
    pub height: u32,
    /// Row-major, top row first.
    pub pixels: Vec<Color>,
}

impl ImageTexture {
    /// Loads a PNG, converting its sRGB values to linear RGB.
    pub fn load(path: &std::path::Path) -> Result<ImageTexture, String> {
        let _ = path;
        todo!("brdf helper")
    }
}
