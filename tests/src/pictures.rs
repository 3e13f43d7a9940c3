//! Pictures the grader writes beside a failure message, under
//! `target/grading/`: images enlarged so that a 32×32 render can be read, and
//! histograms of a student's samples against the density they should have.
//!
//! Drawn pixel by pixel into the renderer's [`Image`] and written with its
//! PNG writer: two bar charts do not justify a plotting crate and its fonts.

use std::path::Path;

use raytracer::film::Image;
use raytracer::math::Color;

/// The smallest width of a written picture: smaller images are enlarged by
/// an integer factor, nearest neighbour (each pixel becomes a square block).
pub const MIN_WIDTH: u32 = 256;

/// The integer factor that makes `width` at least [`MIN_WIDTH`].
pub fn scale_for(width: u32) -> u32 {
    MIN_WIDTH.div_ceil(width.max(1)).max(1)
}

/// `image` enlarged `factor` times, nearest neighbour.
pub fn enlarge(image: &Image, factor: u32) -> Image {
    let f = factor.max(1);
    Image::from_fn(image.width * f, image.height * f, |x, y| {
        image.get(x / f, y / f)
    })
}

/// Writes `image` as a PNG (linear radiance, no exposure change), enlarged
/// to at least [`MIN_WIDTH`] pixels across.
pub fn write_enlarged(image: &Image, path: &Path) -> std::io::Result<()> {
    enlarge(image, scale_for(image.width)).write_png(path, 0.0)
}

/// One histogram: the observed fraction of samples per bin over `[lo, hi)`,
/// and the density the samples should have (per unit of the axis).
pub struct Histogram<'a> {
    pub lo: f64,
    pub hi: f64,
    pub counts: Vec<u64>,
    pub expected_density: &'a dyn Fn(f64) -> f64,
}

impl Histogram<'_> {
    /// The observed density of bin `i` (fraction of samples / bin width).
    pub fn observed_density(&self, i: usize) -> f64 {
        let total: u64 = self.counts.iter().sum();
        let width = (self.hi - self.lo) / self.counts.len() as f64;
        self.counts[i] as f64 / (total.max(1) as f64 * width)
    }
}

/// Draws the histograms one above the other, each 512×192 pixels: grey bars
/// for the student's samples, a red line for the expected density, on a
/// common vertical scale per chart. Written as a PNG to `path`.
pub fn write_histograms(histograms: &[Histogram<'_>], path: &Path) -> std::io::Result<()> {
    let (w, h, margin) = (512u32, 192u32, 8u32);
    let bar = Color::splat(0.35);
    let line = Color::new(0.9, 0.05, 0.05);
    let axis = Color::splat(0.0);
    let background = Color::splat(1.0);
    let mut image = Image::from_fn(w, h * histograms.len() as u32, |_, _| background);
    for (k, hist) in histograms.iter().enumerate() {
        let bins = hist.counts.len().max(1);
        let expected: Vec<f64> = (0..w)
            .map(|x| {
                let t = hist.lo + (hist.hi - hist.lo) * (x as f64 + 0.5) / w as f64;
                (hist.expected_density)(t)
            })
            .collect();
        let top = (0..bins)
            .map(|i| hist.observed_density(i))
            .chain(expected.iter().copied())
            .fold(0.0f64, f64::max)
            .max(1e-12)
            * 1.1;
        let y0 = k as u32 * h;
        let plot_h = (h - 2 * margin) as f64;
        let row = |v: f64| y0 + h - margin - ((v / top).clamp(0.0, 1.0) * plot_h) as u32;
        for x in 0..w {
            let bin = ((x as usize * bins) / w as usize).min(bins - 1);
            let top_row = row(hist.observed_density(bin));
            for y in top_row..(y0 + h - margin) {
                image.pixels[(y * w + x) as usize] = bar;
            }
            image.pixels[((y0 + h - margin) * w + x) as usize] = axis;
            let e = row(expected[x as usize]).min(y0 + h - margin);
            for y in e.saturating_sub(1)..=e {
                if y >= y0 {
                    image.pixels[(y * w + x) as usize] = line;
                }
            }
        }
    }
    image.write_png(path, 0.0)
}

/// Width and height of a PNG file (its IHDR chunk), for tests.
pub fn png_size(path: &Path) -> std::io::Result<(u32, u32)> {
    let bytes = std::fs::read(path)?;
    if bytes.len() < 24 || &bytes[1..4] != b"PNG" {
        return Err(std::io::Error::other(format!(
            "{} is not a PNG",
            path.display()
        )));
    }
    let be = |i: usize| u32::from_be_bytes([bytes[i], bytes[i + 1], bytes[i + 2], bytes[i + 3]]);
    Ok((be(16), be(20)))
}
