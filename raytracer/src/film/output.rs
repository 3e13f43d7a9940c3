//! Writing and reading images: tone-mapped 8-bit sRGB PNG and linear EXR.
//!
//! PNG is for looking at: the linear radiance is multiplied by `2^stops`
//! (exposure), clamped to `[0, 1]` and encoded with the exact sRGB transfer
//! curve (IEC 61966-2-1)
//!
//! ```text
//!   V = 12.92 · L                    for L ≤ 0.0031308
//!   V = 1.055 · L^(1/2.4) − 0.055    otherwise
//! ```
//!
//! then rounded to 8 bits. EXR is for measuring: linear float32 RGB,
//! unclamped, bit for bit what the film computed (references for the grader,
//! environment maps).
//!
//! Errors are `std::io::Error`s whose message names the file. Creating the
//! parent directory is the caller's job; a missing one is reported as such.

use super::Image;
use crate::math::Color;
use image::ImageEncoder;
use std::fs::File;
use std::io::{self, BufWriter};
use std::path::Path;

/// The sRGB encoding `V(L)` of a linear value `L ∈ [0, 1]` (see the module doc).
#[inline]
pub fn linear_to_srgb(l: f32) -> f32 {
    if l <= 0.003_130_8 {
        12.92 * l
    } else {
        1.055 * l.powf(1.0 / 2.4) - 0.055
    }
}

/// A linear value, scaled by `exposure`, clamped to `[0, 1]`, sRGB-encoded
/// and rounded to 8 bits (NaN gives 0).
#[inline]
pub fn srgb8(linear: f32) -> u8 {
    let l = if linear.is_nan() {
        0.0
    } else {
        linear.clamp(0.0, 1.0)
    };
    (linear_to_srgb(l) * 255.0).round() as u8
}

/// An error about the file at `path`.
fn error(path: &Path, what: &str, cause: impl std::fmt::Display, kind: io::ErrorKind) -> io::Error {
    io::Error::new(kind, format!("{what} {}: {cause}", path.display()))
}

/// Reports a missing parent directory clearly instead of a bare "No such file".
fn check_parent(path: &Path) -> io::Result<()> {
    match path.parent() {
        Some(dir) if !dir.as_os_str().is_empty() && !dir.is_dir() => Err(error(
            path,
            "cannot write",
            format_args!("the directory {} does not exist", dir.display()),
            io::ErrorKind::NotFound,
        )),
        _ => Ok(()),
    }
}

impl Image {
    /// The 8-bit sRGB bytes (RGB, row by row) of the image scaled by
    /// `2^exposure_stops`.
    pub fn to_srgb8(&self, exposure_stops: f32) -> Vec<u8> {
        let scale = exposure_stops.exp2();
        self.pixels
            .iter()
            .flat_map(|&c| {
                let c: Color = c * scale;
                [srgb8(c.x), srgb8(c.y), srgb8(c.z)]
            })
            .collect()
    }

    /// Writes an 8-bit sRGB PNG of the image scaled by `2^exposure_stops`
    /// (0 = as rendered, +1 = twice as bright).
    pub fn write_png(&self, path: impl AsRef<Path>, exposure_stops: f32) -> io::Result<()> {
        let path = path.as_ref();
        check_parent(path)?;
        let bytes = self.to_srgb8(exposure_stops);
        let file = File::create(path).map_err(|e| error(path, "cannot create", &e, e.kind()))?;
        let mut writer = BufWriter::new(file);
        image::codecs::png::PngEncoder::new(&mut writer)
            .write_image(
                &bytes,
                self.width,
                self.height,
                image::ExtendedColorType::Rgb8,
            )
            .map_err(|e| error(path, "cannot write PNG", e, io::ErrorKind::Other))?;
        io::Write::flush(&mut writer).map_err(|e| error(path, "cannot write PNG", &e, e.kind()))
    }

    /// Writes the image as a linear, unclamped float32 RGB OpenEXR file.
    pub fn write_exr(&self, path: impl AsRef<Path>) -> io::Result<()> {
        let path = path.as_ref();
        check_parent(path)?;
        let width = self.width as usize;
        exr::prelude::write_rgb_file(path, width, self.height as usize, |x, y| {
            let c = self.pixels[y * width + x];
            (c.x, c.y, c.z)
        })
        .map_err(|e| match e {
            exr::error::Error::Io(io) => error(path, "cannot write EXR", &io, io.kind()),
            e => error(path, "cannot write EXR", e, io::ErrorKind::Other),
        })
    }

    /// Reads the first RGB(A) layer of an OpenEXR file (alpha is ignored;
    /// half and integer channels are converted to f32).
    pub fn read_exr(path: impl AsRef<Path>) -> io::Result<Image> {
        let path = path.as_ref();
        let read = exr::prelude::read_first_rgba_layer_from_file(
            path,
            |size, _| Image::new(size.width() as u32, size.height() as u32),
            |image: &mut Image, pos, (r, g, b, _a): (f32, f32, f32, f32)| {
                image.set(pos.x() as u32, pos.y() as u32, Color::new(r, g, b));
            },
        )
        .map_err(|e| match e {
            exr::error::Error::Io(io) => error(path, "cannot read EXR", &io, io.kind()),
            e => error(path, "cannot read EXR", e, io::ErrorKind::InvalidData),
        })?;
        Ok(read.layer_data.channel_data.pixels)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::PathBuf;

    /// A fresh directory for one test (removed at the end of the test).
    fn temp_dir(name: &str) -> PathBuf {
        let dir =
            std::env::temp_dir().join(format!("raytracer-film-{}-{name}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    #[test]
    fn srgb_curve() {
        assert_eq!(srgb8(0.0), 0);
        assert_eq!(srgb8(1.0), 255);
        assert_eq!(srgb8(5.0), 255);
        assert_eq!(srgb8(-1.0), 0);
        assert_eq!(srgb8(f32::NAN), 0);
        // 1.055 · 0.5^(1/2.4) − 0.055 = 0.73536 → 187.5 → 188.
        assert_eq!(srgb8(0.5), 188);
        // The linear toe: 12.92 · 0.002 · 255 = 6.59 → 7.
        assert_eq!(srgb8(0.002), 7);
        // The two pieces meet (continuity at the threshold).
        let t = 0.003_130_8f32;
        assert!((linear_to_srgb(t) - (1.055 * t.powf(1.0 / 2.4) - 0.055)).abs() < 1e-6);
    }

    #[test]
    fn png_and_exr_round_trip() {
        let dir = temp_dir("roundtrip");
        let img = Image::from_fn(5, 3, |x, y| {
            Color::new(0.5, x as f32 * 1.37 + 1e-7, -(y as f32) * 1e5 + 0.1)
        });
        let exr = dir.join("a.exr");
        img.write_exr(&exr).unwrap();
        let back = Image::read_exr(&exr).unwrap();
        assert_eq!(back.width, 5);
        assert_eq!(back.height, 3);
        for (a, b) in img.pixels.iter().zip(&back.pixels) {
            for c in 0..3 {
                assert_eq!(a[c].to_bits(), b[c].to_bits());
            }
        }

        let png = dir.join("a.png");
        img.write_png(&png, 0.0).unwrap();
        let decoded = image::open(&png).unwrap().to_rgb8();
        assert_eq!(decoded.dimensions(), (5, 3));
        // 0.1 linear: 1.055 · 0.1^(1/2.4) − 0.055 = 0.3492 → 89.04 → 89.
        assert_eq!(decoded.get_pixel(0, 0).0, [188, 0, 89]);
        assert_eq!(decoded.get_pixel(4, 2).0, [188, 255, 0]);
        // One stop brighter: 0.5 → 1.0.
        img.write_png(&png, 1.0).unwrap();
        assert_eq!(
            image::open(&png).unwrap().to_rgb8().get_pixel(0, 0).0[0],
            255
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn errors_name_the_file() {
        let img = Image::new(2, 2);
        let missing = std::env::temp_dir().join("raytracer-no-such-dir-7d1f/x.png");
        let e = img.write_png(&missing, 0.0).unwrap_err();
        assert_eq!(e.kind(), io::ErrorKind::NotFound);
        assert!(e.to_string().contains("raytracer-no-such-dir-7d1f"), "{e}");
        assert!(e.to_string().contains("does not exist"), "{e}");
        let e = img.write_exr(missing.with_extension("exr")).unwrap_err();
        assert!(e.to_string().contains("x.exr"), "{e}");
        let e = Image::read_exr(missing.with_extension("exr")).unwrap_err();
        assert!(e.to_string().contains("cannot read EXR"), "{e}");
    }
}
