//! The film: where pixel estimates are accumulated and written out.
//!
//! A pixel's value is a Monte Carlo estimate of the measurement
//! `I_j = ∫ W_e^{(j)}(x, ω) L(x, ω) cos θ dA dω` of the lecture. The film keeps,
//! for every pixel `j`, the sums that give its estimate *and* the variance of
//! that estimate, so that lessons can show noise and the grader can run z-tests:
//!
//! - **pixel samples** (camera paths): `N_j` samples `X_{j,1..N_j}`, kept as
//!   `Σ X`, `Σ X²` (per channel, in `f64`) and `N_j`. Their estimate is the
//!   mean `X̄_j = ΣX / N_j`, and the variance of that mean is `s_j² / N_j`
//!   with the sample variance `s_j² = (ΣX² − (ΣX)²/N_j) / (N_j − 1)`.
//! - **splats** (light tracing, and the `t = 1` strategies of bidirectional
//!   tracing): a light path may contribute to any pixel. With `M` pixel
//!   samples on the whole film, each of which may launch one light path, the
//!   splat part of pixel `j` is `(W·H / M) · Σ_i Y_{i,j}`, where `Y_{i,j}` is
//!   what path `i` brought to pixel `j` (often zero). For a uniform sample
//!   count `W·H / M = 1/spp`: exactly pbrt's splat scale `1/spp` — the
//!   estimator of a light tracer that traces `spp·W·H` light paths in all.
//!   Writing the scale as `W·H / M` keeps it right when a render is
//!   interrupted and pixels hold slightly different sample counts.
//!
//! The final pixel is `X̄_j + (W·H / M) · Σ_i Y_{i,j}`
//! ([`Film::image`]); its variance is estimated by [`Film::variance_image`].
//!
//! **Invalid samples.** Radiance is finite and non-negative. A sample with a
//! NaN, an infinity or a negative channel never reaches the film: it is
//! counted ([`Film::nonfinite_count`]) and replaced by zero. It still counts
//! towards `N_j` — unlike pbrt, which drops it — so that the estimator keeps
//! its normalization `1/N` (dropping a sample would bias the pixel towards
//! the values of the samples that happened to be valid). An invalid splat is
//! counted and dropped (which is the same as a zero contribution).
//!
//! Files: [`image`] (the final linear RGB picture), [`output`] (PNG with the
//! sRGB curve, linear EXR), [`tile`] (a tile's private accumulators, merged by
//! the render loop in a fixed order so that images are bit-for-bit
//! reproducible with any number of threads).

pub mod image;
pub mod output;
pub mod tile;

pub use image::Image;
pub use output::{linear_to_srgb, srgb8};
pub use tile::FilmTile;

use crate::math::{Color, UVec2, Vec2};
use std::path::Path;

/// A contribution to an arbitrary raster position (light tracing connects a
/// light-path vertex to the camera and lands anywhere on the film).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Splat {
    pub raster: Vec2,
    pub value: Color,
}

/// True if `c` may reach the film: every channel finite and `≥ 0`.
#[inline]
pub fn is_valid_radiance(c: Color) -> bool {
    // `NaN >= 0` is false, so the comparison alone also rejects NaN.
    c.is_finite() && c.cmpge(Color::ZERO).all()
}

/// The pixel whose square `[x, x+1) × [y, y+1)` contains the raster point
/// (camera convention), or `None` outside a `width × height` film.
#[inline]
pub fn pixel_of_raster(raster: Vec2, width: u32, height: u32) -> Option<UVec2> {
    // Written so that NaN coordinates fail the test too.
    let inside =
        raster.x >= 0.0 && raster.y >= 0.0 && raster.x < width as f32 && raster.y < height as f32;
    // `as u32` truncates towards zero: the floor for non-negative values; the
    // `min` guards against rounding of `x < width` just below `width`.
    inside.then(|| {
        UVec2::new(
            (raster.x as u32).min(width - 1),
            (raster.y as u32).min(height - 1),
        )
    })
}

/// `Σ x += value`, `Σ x² += value²`, per channel in `f64`.
#[inline]
fn add_moments(sum: &mut [f64; 3], sum_sq: &mut [f64; 3], value: Color) {
    for ((s, q), v) in sum.iter_mut().zip(sum_sq.iter_mut()).zip(value.to_array()) {
        let v = v as f64;
        *s += v;
        *q += v * v;
    }
}

/// Sums of the camera samples of one pixel.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PixelSums {
    /// `Σ X` per channel.
    pub sum: [f64; 3],
    /// `Σ X²` per channel.
    pub sum_sq: [f64; 3],
    /// `N`, the number of samples (invalid ones included, as zeros).
    pub count: u64,
}

impl PixelSums {
    #[inline]
    pub fn add(&mut self, value: Color) {
        add_moments(&mut self.sum, &mut self.sum_sq, value);
        self.count += 1;
    }

    #[inline]
    pub fn merge(&mut self, other: &PixelSums) {
        for c in 0..3 {
            self.sum[c] += other.sum[c];
            self.sum_sq[c] += other.sum_sq[c];
        }
        self.count += other.count;
    }
}

/// Sums of the splats of one pixel: `Σ_i Y_{i,j}` and `Σ_i Y_{i,j}²`, one term
/// per light path (the render loop adds up the splats of one path that land
/// in the same pixel before they arrive here).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct SplatSums {
    sum: [f64; 3],
    sum_sq: [f64; 3],
}

const NO_SPLATS: SplatSums = SplatSums {
    sum: [0.0; 3],
    sum_sq: [0.0; 3],
};

/// The accumulation buffer of a `width × height` image.
///
/// Two films compare equal if every sum is bit for bit the same (the
/// determinism tests of the render loop compare films, not just images: the
/// rounding to `f32` in [`Film::image`] would hide differences in the order of
/// the `f64` additions).
#[derive(Clone, Debug, PartialEq)]
pub struct Film {
    width: u32,
    height: u32,
    pixels: Vec<PixelSums>,
    /// Empty until the first splat arrives (most integrators never splat).
    splats: Vec<SplatSums>,
    total_samples: u64,
    nonfinite: u64,
}

impl Film {
    /// A black film with no samples.
    pub fn new(width: u32, height: u32) -> Self {
        let n = width as usize * height as usize;
        Film {
            width,
            height,
            pixels: vec![PixelSums::default(); n],
            splats: Vec::new(),
            total_samples: 0,
            nonfinite: 0,
        }
    }

    #[inline]
    pub fn width(&self) -> u32 {
        self.width
    }

    #[inline]
    pub fn height(&self) -> u32 {
        self.height
    }

    #[inline]
    fn index(&self, pixel: UVec2) -> usize {
        assert!(
            pixel.x < self.width && pixel.y < self.height,
            "pixel ({}, {}) is outside the {}×{} film",
            pixel.x,
            pixel.y,
            self.width,
            self.height
        );
        pixel.y as usize * self.width as usize + pixel.x as usize
    }

    /// Adds one camera sample of `pixel`. An invalid value (NaN, infinite or
    /// negative channel) is counted in [`Film::nonfinite_count`] and enters
    /// as zero: it still counts as one of the pixel's `N` samples.
    ///
    /// # Panics
    /// If `pixel` is outside the film (a bug in the caller).
    pub fn add_sample(&mut self, pixel: UVec2, value: Color) {
        let i = self.index(pixel);
        let value = if is_valid_radiance(value) {
            value
        } else {
            self.nonfinite += 1;
            Color::ZERO
        };
        self.pixels[i].add(value);
        self.total_samples += 1;
    }

    /// Adds a light path's contribution to the pixel that contains
    /// `splat.raster`; splats outside the film are ignored, invalid ones are
    /// counted in [`Film::nonfinite_count`] and dropped.
    ///
    /// Each call counts as the whole contribution of one light path to that
    /// pixel (for the variance estimate): if a path lands twice in the same
    /// pixel, add the two values up first. [`FilmTile`] does this for you.
    pub fn add_splat(&mut self, splat: Splat) {
        if !is_valid_radiance(splat.value) {
            self.nonfinite += 1;
            return;
        }
        if let Some(p) = pixel_of_raster(splat.raster, self.width, self.height) {
            let i = self.index(p);
            self.add_splat_at(i, splat.value);
        }
    }

    #[inline]
    fn add_splat_at(&mut self, i: usize, value: Color) {
        if self.splats.is_empty() {
            self.splats = vec![SplatSums::default(); self.pixels.len()];
        }
        let s = &mut self.splats[i];
        add_moments(&mut s.sum, &mut s.sum_sq, value);
    }

    /// Adds everything a tile accumulated: its pixels' sums, then its splats
    /// in the order they were made, then its count of invalid values. The
    /// render loop calls this for tiles in a fixed order, which fixes the order
    /// of every floating-point addition and makes the image reproducible.
    ///
    /// # Panics
    /// If the tile was made for a film of another size.
    pub fn merge_tile(&mut self, tile: &FilmTile) {
        assert_eq!(
            tile.film_size(),
            UVec2::new(self.width, self.height),
            "tile of another film"
        );
        let (origin, size) = (tile.origin(), tile.size());
        for ty in 0..size.y {
            for tx in 0..size.x {
                let i = self.index(origin + UVec2::new(tx, ty));
                let sums = tile.pixel_sums(tx, ty);
                self.pixels[i].merge(sums);
                self.total_samples += sums.count;
            }
        }
        // The tile has already checked, located and grouped its splats.
        for splat in tile.splats() {
            let p = pixel_of_raster(splat.raster, self.width, self.height)
                .expect("a tile keeps only splats on the film");
            let i = self.index(p);
            self.add_splat_at(i, splat.value);
        }
        self.nonfinite += tile.nonfinite_count();
    }

    /// `N_j`, the number of samples of `pixel`.
    pub fn sample_count(&self, pixel: UVec2) -> u64 {
        self.pixels[self.index(pixel)].count
    }

    /// How many pixels have no sample at all (an interrupted render: their
    /// mean is shown as 0, and their variance as infinite).
    pub fn unsampled_pixels(&self) -> u64 {
        self.pixels.iter().filter(|p| p.count == 0).count() as u64
    }

    /// `M`, the number of pixel samples on the whole film.
    pub fn total_samples(&self) -> u64 {
        self.total_samples
    }

    /// How many samples and splats were rejected as NaN, infinite or negative.
    pub fn nonfinite_count(&self) -> u64 {
        self.nonfinite
    }

    /// The factor `W·H / M` that turns the sum of a pixel's splats into its
    /// estimate: `1/spp` for a uniform sample count; zero on an empty film.
    pub fn splat_scale(&self) -> f64 {
        if self.total_samples == 0 {
            0.0
        } else {
            (self.width as f64 * self.height as f64) / self.total_samples as f64
        }
    }

    /// The final linear RGB image: `X̄_j + (W·H / M) · Σ_i Y_{i,j}` (a pixel
    /// with no samples has mean 0).
    pub fn image(&self) -> Image {
        let scale = self.splat_scale();
        let pixels = self
            .pixels
            .iter()
            .zip(self.splats.iter().chain(std::iter::repeat(&NO_SPLATS)))
            .map(|(p, s)| {
                let n = p.count.max(1) as f64;
                let v: [f64; 3] = std::array::from_fn(|c| p.sum[c] / n + scale * s.sum[c]);
                Color::new(v[0] as f32, v[1] as f32, v[2] as f32)
            })
            .collect();
        Image {
            width: self.width,
            height: self.height,
            pixels,
        }
    }

    /// The estimated variance of each pixel of [`Film::image`], per channel.
    ///
    /// Camera-sample part: `s_j² / N_j`, the variance of the mean of `N_j`
    /// samples. Splat part: the pixel gets `c · Σ_{i=1..M} Y_{i,j}` with
    /// `c = W·H / M`; taking the `M` paths as independent and identically
    /// distributed, its variance is `c² · M · Var(Y_j)`, estimated with
    /// `Var(Y_j) ≈ (ΣY² − (ΣY)²/M) / (M − 1)`. The two parts are added (their
    /// covariance is neglected). With fewer than 2 samples the variance is
    /// unknown and reported as `f32::INFINITY`, which a z-test reads as "no
    /// evidence" rather than "exact".
    pub fn variance_image(&self) -> Image {
        let m = self.total_samples as f64;
        let scale = self.splat_scale();
        let pixels = self
            .pixels
            .iter()
            .zip(self.splats.iter().chain(std::iter::repeat(&NO_SPLATS)))
            .map(|(p, s)| {
                if p.count < 2 {
                    return Color::splat(f32::INFINITY);
                }
                let n = p.count as f64;
                let v: [f64; 3] = std::array::from_fn(|c| {
                    let sample_var = (p.sum_sq[c] - p.sum[c] * p.sum[c] / n) / (n - 1.0);
                    let splat_var =
                        (s.sum_sq[c] - s.sum[c] * s.sum[c] / m) / (m - 1.0) * m * scale * scale;
                    // Cancellation may leave a tiny negative number.
                    sample_var.max(0.0) / n + splat_var.max(0.0)
                });
                Color::new(v[0] as f32, v[1] as f32, v[2] as f32)
            })
            .collect();
        Image {
            width: self.width,
            height: self.height,
            pixels,
        }
    }

    /// Writes [`Film::image`] as an 8-bit sRGB PNG (see [`Image::write_png`]).
    pub fn write_png(&self, path: impl AsRef<Path>, exposure_stops: f32) -> std::io::Result<()> {
        self.image().write_png(path, exposure_stops)
    }

    /// Writes [`Film::image`] as a linear float32 EXR (see [`Image::write_exr`]).
    pub fn write_exr(&self, path: impl AsRef<Path>) -> std::io::Result<()> {
        self.image().write_exr(path)
    }
}
