//! A tile's private accumulators: what one render task gathers before it is
//! merged into the [`Film`](super::Film).
//!
//! Threads never add into shared sums (pbrt's atomic splats would make the
//! order of floating-point additions, hence the last bits of the image, depend
//! on scheduling). Each task fills its own `FilmTile`; the render loop merges
//! the tiles in a fixed order with [`Film::merge_tile`](super::Film::merge_tile).
//! A tile is reused from task to task: after warm-up no allocation happens.

use super::{PixelSums, Splat, is_valid_radiance, pixel_of_raster};
use crate::math::{Color, UVec2};

/// The camera samples of a rectangle of pixels and the splats made by its
/// samples (which may land anywhere on the film).
#[derive(Clone, Debug)]
pub struct FilmTile {
    film_size: UVec2,
    origin: UVec2,
    size: UVec2,
    pixels: Vec<PixelSums>,
    splats: Vec<Splat>,
    nonfinite: u64,
}

impl FilmTile {
    /// An empty tile covering `size` pixels from `origin` on a film of
    /// `film_size` pixels (clipped to the film).
    pub fn new(film_size: UVec2, origin: UVec2, size: UVec2) -> Self {
        let mut tile = FilmTile {
            film_size,
            origin,
            size,
            pixels: Vec::new(),
            splats: Vec::new(),
            nonfinite: 0,
        };
        tile.reset(origin, size);
        tile
    }

    /// Empties the tile and moves it to another rectangle of the same film,
    /// keeping its allocations.
    pub fn reset(&mut self, origin: UVec2, size: UVec2) {
        self.origin = origin.min(self.film_size);
        self.size = size.min(self.film_size - self.origin);
        self.pixels.clear();
        self.pixels.resize(
            self.size.x as usize * self.size.y as usize,
            PixelSums::default(),
        );
        self.splats.clear();
        self.nonfinite = 0;
    }

    pub fn film_size(&self) -> UVec2 {
        self.film_size
    }

    /// The tile's first pixel, in film coordinates.
    pub fn origin(&self) -> UVec2 {
        self.origin
    }

    pub fn size(&self) -> UVec2 {
        self.size
    }

    /// The sums of the pixel at `(tx, ty)` relative to the tile's origin.
    #[inline]
    pub(crate) fn pixel_sums(&self, tx: u32, ty: u32) -> &PixelSums {
        &self.pixels[ty as usize * self.size.x as usize + tx as usize]
    }

    /// The valid splats on the film, in the order they were made, those of one
    /// sample that hit the same pixel already added up.
    pub fn splats(&self) -> &[Splat] {
        &self.splats
    }

    /// Invalid samples and splats met so far.
    pub fn nonfinite_count(&self) -> u64 {
        self.nonfinite
    }

    /// Adds one camera sample of `pixel` (film coordinates, inside the tile),
    /// with the same rule for invalid values as [`Film::add_sample`](super::Film::add_sample).
    #[inline]
    pub fn add_sample(&mut self, pixel: UVec2, value: Color) {
        debug_assert!(pixel.cmpge(self.origin).all() && pixel.cmplt(self.origin + self.size).all());
        let local = pixel - self.origin;
        let i = local.y as usize * self.size.x as usize + local.x as usize;
        let value = if is_valid_radiance(value) {
            value
        } else {
            self.nonfinite += 1;
            Color::ZERO
        };
        self.pixels[i].add(value);
    }

    /// Runs one pixel sample: `sample` gets the tile's splat list to push its
    /// splats onto and returns the pixel's value, which is added to `pixel`.
    /// The splats of this sample are then checked and grouped (see
    /// [`FilmTile::finish_splats`]).
    #[inline]
    pub fn record(&mut self, pixel: UVec2, sample: impl FnOnce(&mut Vec<Splat>) -> Color) {
        self.record_unless_abandoned(pixel, |splats| Some(sample(splats)));
    }

    /// [`FilmTile::record`] for a sample that may be abandoned half-way
    /// (`None`, a render asked to stop): then neither its value nor its
    /// splats are kept, and it does not count. Returns whether it was kept.
    #[inline]
    pub fn record_unless_abandoned(
        &mut self,
        pixel: UVec2,
        sample: impl FnOnce(&mut Vec<Splat>) -> Option<Color>,
    ) -> bool {
        let start = self.splats.len();
        let Some(value) = sample(&mut self.splats) else {
            self.splats.truncate(start);
            return false;
        };
        self.add_sample(pixel, value);
        if self.splats.len() > start {
            self.finish_splats(start);
        }
        true
    }

    /// Cleans up the splats of one light path, `splats[start..]`: drops
    /// invalid ones (counted), ignores those off the film and those that are
    /// zero, and adds up those that landed in the same pixel, so that each
    /// remaining splat is the path's whole contribution `Y_{i,j}` to its pixel
    /// (what the film's variance estimate needs). Quadratic in the number of
    /// splats of the path, which is its length: a handful.
    pub fn finish_splats(&mut self, start: usize) {
        let (w, h) = (self.film_size.x, self.film_size.y);
        let mut kept = start;
        for i in start..self.splats.len() {
            let s = self.splats[i];
            if !is_valid_radiance(s.value) {
                self.nonfinite += 1;
                continue;
            }
            if s.value == Color::ZERO {
                continue;
            }
            let Some(p) = pixel_of_raster(s.raster, w, h) else {
                continue;
            };
            let same_pixel =
                (start..kept).find(|&k| pixel_of_raster(self.splats[k].raster, w, h) == Some(p));
            match same_pixel {
                Some(k) => self.splats[k].value += s.value,
                None => {
                    self.splats[kept] = s;
                    kept += 1;
                }
            }
        }
        self.splats.truncate(kept);
    }
}
