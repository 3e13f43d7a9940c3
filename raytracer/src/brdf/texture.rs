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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn checker_alternates() {
        let (a, b) = (Color::new(1.0, 0.0, 0.0), Color::new(0.0, 0.0, 1.0));
        let t = Texture::Checker { a, b, scale: 4.0 };
        // Squares of size 1/4.
        assert_eq!(t.eval(Vec2::new(0.1, 0.1)), a);
        assert_eq!(t.eval(Vec2::new(0.3, 0.1)), b);
        assert_eq!(t.eval(Vec2::new(0.3, 0.3)), a);
        assert_eq!(t.eval(Vec2::new(0.1, 0.3)), b);
        assert_eq!(t.eval(Vec2::new(0.6, 0.9)), b);
        // Negative coordinates continue the pattern (no mirrored square at 0).
        assert_eq!(t.eval(Vec2::new(-0.1, 0.1)), b);
        assert_eq!(t.eval(Vec2::new(-0.1, -0.1)), a);
        assert_eq!(Texture::Constant(a).eval(Vec2::new(7.0, -3.0)), a);
    }

    #[test]
    fn srgb_decoding_is_exact() {
        assert!((srgb_to_linear(0.5) - 0.214_041).abs() < 1e-5);
        assert_eq!(srgb_to_linear(0.0), 0.0);
        assert!((srgb_to_linear(1.0) - 1.0).abs() < 1e-6);
        assert!((srgb_to_linear(0.04) - 0.04 / 12.92).abs() < 1e-9);
        // Continuous at the junction of the two pieces.
        assert!((srgb_to_linear(0.040_45) - srgb_to_linear(0.040_46)).abs() < 1e-5);
    }

    #[test]
    fn image_lookup_is_bilinear_and_wraps() {
        // 2×2: top row red, green; bottom row blue, white.
        let px = vec![Color::X, Color::Y, Color::Z, Color::ONE];
        let img = ImageTexture::new(2, 2, px).unwrap();
        // Pixel centres: (u, v) = (0.25, 0.75) is the top-left pixel.
        assert!((img.eval(Vec2::new(0.25, 0.75)) - Color::X).length() < 1e-6);
        assert!((img.eval(Vec2::new(0.75, 0.25)) - Color::ONE).length() < 1e-6);
        // Halfway between the two top pixels.
        let mid = img.eval(Vec2::new(0.5, 0.75));
        assert!((mid - Color::new(0.5, 0.5, 0.0)).length() < 1e-6);
        // Wrap-around: u = 0 is halfway between the right and left columns.
        let edge = img.eval(Vec2::new(0.0, 0.75));
        assert!((edge - Color::new(0.5, 0.5, 0.0)).length() < 1e-6);
        assert!((img.eval(Vec2::new(1.25, -0.25)) - Color::X).length() < 1e-6);
        assert!(ImageTexture::new(2, 2, vec![Color::ONE; 3]).is_err());
    }

    #[test]
    fn png_is_loaded_as_linear_and_errors_name_the_file() {
        let dir = std::env::temp_dir().join(format!("brdf-texture-test-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("two.png");
        let write = |color: png::ColorType, depth: png::BitDepth, data: &[u8]| {
            let file = std::fs::File::create(&path).unwrap();
            let mut encoder = png::Encoder::new(std::io::BufWriter::new(file), 2, 1);
            encoder.set_color(color);
            encoder.set_depth(depth);
            let mut writer = encoder.write_header().unwrap();
            writer.write_image_data(data).unwrap();
            writer.finish().unwrap();
        };
        let g = srgb_to_linear(128.0 / 255.0);
        assert!((g - 0.2158).abs() < 1e-4);
        let second = Color::new(1.0, 0.0, srgb_to_linear(64.0 / 255.0));
        // 2×1 sRGB: mid grey (128) and (255, 0, 64), as RGB, as RGBA, and as
        // 16-bit RGB (128·257 is 128/255 exactly); grey alone as 8-bit grey.
        for (color, depth, data) in [
            (
                png::ColorType::Rgb,
                png::BitDepth::Eight,
                vec![128, 128, 128, 255, 0, 64],
            ),
            (
                png::ColorType::Rgba,
                png::BitDepth::Eight,
                vec![128, 128, 128, 7, 255, 0, 64, 9],
            ),
            (
                png::ColorType::Rgb,
                png::BitDepth::Sixteen,
                [128u16 * 257, 128 * 257, 128 * 257, 65535, 0, 64 * 257]
                    .iter()
                    .flat_map(|v| v.to_be_bytes())
                    .collect(),
            ),
        ] {
            write(color, depth, &data);
            let t = ImageTexture::load(&path).unwrap();
            assert_eq!((t.width, t.height), (2, 1));
            assert!(
                (t.pixels[0] - Color::splat(g)).length() < 1e-6,
                "{color:?} {depth:?}"
            );
            assert!(
                (t.pixels[1] - second).length() < 1e-6,
                "{color:?} {depth:?}"
            );
        }
        write(png::ColorType::Grayscale, png::BitDepth::Eight, &[128, 255]);
        let t = ImageTexture::load(&path).unwrap();
        assert_eq!(t.pixels, vec![Color::splat(g), Color::ONE]);
        std::fs::write(&path, b"not a png").unwrap();
        let err = ImageTexture::load(&path).unwrap_err();
        assert!(err.contains("two.png"), "{err}");
        std::fs::remove_dir_all(&dir).ok();

        let missing = std::path::Path::new("/nonexistent/dir/albedo.png");
        let err = ImageTexture::load(missing).unwrap_err();
        assert!(err.contains("/nonexistent/dir/albedo.png"), "{err}");
    }

    /// A PNG whose header claims a huge image (here 40 000 × 40 000, 4.8 GB
    /// of samples, in a file of a few dozen bytes) is refused with a line
    /// naming the file, before its pixels are allocated.
    #[test]
    fn a_huge_png_is_refused_before_it_is_allocated() {
        let crc = |bytes: &[u8]| {
            let mut c = !0u32;
            for &b in bytes {
                c ^= b as u32;
                for _ in 0..8 {
                    c = if c & 1 != 0 {
                        (c >> 1) ^ 0xEDB8_8320
                    } else {
                        c >> 1
                    };
                }
            }
            !c
        };
        let chunk = |kind: &[u8], data: &[u8]| {
            let mut body = kind.to_vec();
            body.extend_from_slice(data);
            let mut out = (data.len() as u32).to_be_bytes().to_vec();
            out.extend_from_slice(&body);
            out.extend_from_slice(&crc(&body).to_be_bytes());
            out
        };
        let mut ihdr = 40_000u32.to_be_bytes().to_vec();
        ihdr.extend_from_slice(&40_000u32.to_be_bytes());
        ihdr.extend_from_slice(&[8, 2, 0, 0, 0]); // 8-bit RGB
        let mut file = b"\x89PNG\r\n\x1a\n".to_vec();
        file.extend(chunk(b"IHDR", &ihdr));
        // The start of the pixel data (a zlib stream with one empty block):
        // a decoder reads up to here before it says the image's size.
        file.extend(chunk(b"IDAT", &[0x78, 0x01, 0x01, 0x00, 0x00, 0xff, 0xff]));
        file.extend(chunk(b"IEND", &[]));
        let dir = std::env::temp_dir().join(format!("huge_png_{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("huge.png");
        std::fs::write(&path, &file).unwrap();
        let err = ImageTexture::load(&path).unwrap_err();
        std::fs::remove_dir_all(&dir).ok();
        assert!(
            err.contains("huge.png") && err.contains("40000 × 40000 pixels"),
            "{err}"
        );
    }

    /// A JPEG photograph is read as sRGB and decoded to linear; a file of
    /// another format is refused by what its bytes say, whatever its name;
    /// a truncated JPEG is named in one line.
    #[test]
    fn jpeg_is_loaded_as_linear_and_other_formats_are_refused() {
        let dir = std::env::temp_dir().join(format!("jpeg-texture-test-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("grey.jpg");
        // A flat 16 × 8 image of sRGB 128: JPEG keeps a flat block exact to
        // a unit or so.
        let flat = image::RgbImage::from_pixel(16, 8, image::Rgb([128, 128, 128]));
        flat.save_with_format(&path, image::ImageFormat::Jpeg)
            .unwrap();
        let t = ImageTexture::load(&path).unwrap();
        assert_eq!((t.width, t.height), (16, 8));
        let lo = srgb_to_linear(127.0 / 255.0);
        let hi = srgb_to_linear(129.0 / 255.0);
        for p in &t.pixels {
            assert!((lo..=hi).contains(&p.x) && p.x == p.y && p.y == p.z, "{p}");
        }
        // Truncated: the header and half the data.
        let bytes = std::fs::read(&path).unwrap();
        let cut = dir.join("cut.jpg");
        std::fs::write(&cut, &bytes[..bytes.len() / 2]).unwrap();
        let err = ImageTexture::load(&cut).unwrap_err();
        assert!(err.contains("cut.jpg") && !err.contains('\n'), "{err}");
        // A Radiance HDR file named .png is not a texture.
        let hdr = dir.join("sky.png");
        let px = vec![image::Rgb([1.0f32, 0.5, 0.25]); 4];
        image::codecs::hdr::HdrEncoder::new(std::fs::File::create(&hdr).unwrap())
            .encode(&px, 2, 2)
            .unwrap();
        let err = ImageTexture::load(&hdr).unwrap_err();
        assert!(
            err.contains("sky.png") && err.contains("PNG or JPEG"),
            "{err}"
        );
        std::fs::remove_dir_all(&dir).ok();
    }
}
