//! Textures: a colour as a function of the surface's `(u, v)` coordinates.
//!
//! Lecture topic: "BRDF-и" — a spatially varying BRDF `f_r(x, ω_i → ω_o)`:
//! the albedo of a Lambertian surface may change from point to point.
//! All colours are linear RGB; PNG and JPEG files store sRGB-encoded values,
//! which are decoded on load with the exact sRGB transfer curve.

use std::sync::Arc;

use crate::math::{Color, Vec2};

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

impl Texture {
    /// The colour at `uv`. The checker square `(⌊u·scale⌋, ⌊v·scale⌋)` is `a`
    /// when the sum of its indices is even (so the square at the origin,
    /// `[0, 1/scale)²`, is `a`), `b` when odd.
    #[inline]
    pub fn eval(&self, uv: Vec2) -> Color {
        match self {
            Texture::Constant(c) => *c,
            Texture::Checker { a, b, scale } => {
                let i = (uv.x * scale).floor() as i64 + (uv.y * scale).floor() as i64;
                if i.rem_euclid(2) == 0 { *a } else { *b }
            }
            Texture::Image(image) => image.eval(uv),
        }
    }
}

/// An RGB image in linear colour (sRGB PNGs are decoded to linear on load).
#[derive(Clone, Debug, PartialEq)]
pub struct ImageTexture {
    pub width: u32,
    pub height: u32,
    /// Row-major, top row first.
    pub pixels: Vec<Color>,
}

/// The sRGB electro-optical transfer function (IEC 61966-2-1): an encoded
/// value `c ∈ [0, 1]` to linear, `c/12.92` for `c ≤ 0.04045`, else
/// `((c + 0.055)/1.055)^2.4`. Not a pure gamma 2.2: the linear toe avoids an
/// infinite slope at black.
#[inline]
pub fn srgb_to_linear(c: f32) -> f32 {
    if c <= 0.040_45 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// The most pixels an image texture may have (8192 × 8192; 768 MiB as
/// linear RGB): a PNG's header is read before its pixels, and a larger
/// claim is refused before anything is allocated.
pub const MAX_TEXTURE_PIXELS: u64 = 1 << 26;

impl ImageTexture {
    /// An image from linear pixels, top row first; checks the size.
    pub fn new(width: u32, height: u32, pixels: Vec<Color>) -> Result<ImageTexture, String> {
        if width == 0 || height == 0 || pixels.len() != width as usize * height as usize {
            return Err(format!(
                "an image texture of {width}×{height} needs {} pixels, got {}",
                width as usize * height as usize,
                pixels.len()
            ));
        }
        Ok(ImageTexture {
            width,
            height,
            pixels,
        })
    }

    /// Loads a PNG (any colour type and bit depth: palette, grey, 8 or 16
    /// bits) or a JPEG of at most [`MAX_TEXTURE_PIXELS`] pixels, converting
    /// its sRGB values to linear RGB; alpha is ignored. The format is found
    /// from the file's first bytes, not its name.
    ///
    /// The header is read first and a size over the limit is refused before
    /// any pixel memory is taken (a file of a few bytes may claim billions of
    /// pixels); the decoder is also given that limit for what it allocates.
    pub fn load(path: &std::path::Path) -> Result<ImageTexture, String> {
        use image::{ImageDecoder, ImageFormat, ImageReader, Limits};
        let named = |e: &dyn std::fmt::Display| {
            format!(
                "cannot load texture '{}': {}",
                path.display(),
                crate::film::output::one_line(&e.to_string())
            )
        };
        let reader = ImageReader::open(path)
            .and_then(|r| r.with_guessed_format())
            .map_err(|e| named(&e))?;
        match reader.format() {
            Some(ImageFormat::Png | ImageFormat::Jpeg) => {}
            Some(other) => {
                return Err(named(&format!(
                    "a {other:?} image; textures are PNG or JPEG files"
                )));
            }
            None => return Err(named(&"not a PNG or JPEG file")),
        }
        // The decoder reads the header alone; its size is checked before
        // any pixel memory is taken.
        let mut decoder = reader.into_decoder().map_err(|e| named(&e))?;
        let (w, h) = decoder.dimensions();
        if w as u64 * h as u64 > MAX_TEXTURE_PIXELS {
            return Err(named(&format!(
                "{w} × {h} pixels, more than a texture may have ({MAX_TEXTURE_PIXELS} pixels, \
                 e.g. 8192 × 8192, 768 MiB in linear RGB)"
            )));
        }
        let mut limits = Limits::default();
        // At most 16-bit RGBA in the decoder's buffer, plus its working memory.
        limits.max_alloc = Some(MAX_TEXTURE_PIXELS * 8 + (64 << 20));
        decoder.set_limits(limits).map_err(|e| named(&e))?;
        let decoded = image::DynamicImage::from_decoder(decoder).map_err(|e| named(&e))?;
        // 8- and 16-bit samples to [0, 1] (k/255, k/65535), grey to RGB,
        // alpha dropped; then sRGB decoded to linear.
        let rgb = decoded.to_rgb32f();
        let pixels = rgb
            .pixels()
            .map(|p| {
                Color::new(
                    srgb_to_linear(p.0[0]),
                    srgb_to_linear(p.0[1]),
                    srgb_to_linear(p.0[2]),
                )
            })
            .collect();
        ImageTexture::new(rgb.width(), rgb.height(), pixels)
            .map_err(|e| format!("texture '{}': {e}", path.display()))
    }

    /// The pixel at column `x`, row `y` (wrapped around, so the texture tiles).
    #[inline]
    fn texel(&self, x: i64, y: i64) -> Color {
        let x = x.rem_euclid(self.width as i64) as usize;
        let y = y.rem_euclid(self.height as i64) as usize;
        self.pixels
            .get(y * self.width as usize + x)
            .copied()
            .unwrap_or(Color::ZERO)
    }

    /// Bilinear lookup with wrap-around. `u` runs left to right and `v`
    /// bottom to top (the OBJ convention), so `v = 1` is the top row; pixel
    /// centres sit at half-integer coordinates `(u·w, (1 − v)·h)`.
    #[inline]
    pub fn eval(&self, uv: Vec2) -> Color {
        if self.width == 0 || self.height == 0 {
            return Color::ZERO;
        }
        let x = uv.x * self.width as f32 - 0.5;
        let y = (1.0 - uv.y) * self.height as f32 - 0.5;
        if !(x.is_finite() && y.is_finite()) {
            return Color::ZERO;
        }
        let (x0, y0) = (x.floor(), y.floor());
        let (fx, fy) = (x - x0, y - y0);
        let (x0, y0) = (x0 as i64, y0 as i64);
        let top = self.texel(x0, y0).lerp(self.texel(x0 + 1, y0), fx);
        let bottom = self.texel(x0, y0 + 1).lerp(self.texel(x0 + 1, y0 + 1), fx);
        top.lerp(bottom, fy)
    }
}
