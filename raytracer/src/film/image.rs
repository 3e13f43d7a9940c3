//! A finished picture: linear RGB radiance per pixel, row by row from the top.
//!
//! The film turns its sums into an `Image` ([`Film::image`](super::Film::image),
//! [`Film::variance_image`](super::Film::variance_image)); metrics compare
//! images and [`output`](super::output) writes them as PNG or EXR.

use crate::math::Color;

/// A `width × height` linear RGB image; pixel `(x, y)` is
/// `pixels[y·width + x]`, `y = 0` at the top.
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    pub width: u32,
    pub height: u32,
    pub pixels: Vec<Color>,
}

impl Image {
    /// A black image.
    pub fn new(width: u32, height: u32) -> Self {
        Image {
            width,
            height,
            pixels: vec![Color::ZERO; width as usize * height as usize],
        }
    }

    /// Every channel of every pixel as its bit pattern, in pixel order: two
    /// images are the same bit for bit when these are equal (unlike `==` on
    /// the values, which takes −0 for 0 and no NaN for itself).
    pub fn bits(&self) -> Vec<u32> {
        self.pixels
            .iter()
            .flat_map(|c| c.to_array().map(f32::to_bits))
            .collect()
    }

    /// An image whose pixel `(x, y)` is `f(x, y)`.
    pub fn from_fn(width: u32, height: u32, mut f: impl FnMut(u32, u32) -> Color) -> Self {
        let mut pixels = Vec::with_capacity(width as usize * height as usize);
        for y in 0..height {
            for x in 0..width {
                pixels.push(f(x, y));
            }
        }
        Image {
            width,
            height,
            pixels,
        }
    }

    #[inline]
    fn index(&self, x: u32, y: u32) -> usize {
        assert!(
            x < self.width && y < self.height,
            "pixel ({x}, {y}) is outside the {}×{} image",
            self.width,
            self.height
        );
        y as usize * self.width as usize + x as usize
    }

    /// The pixel `(x, y)`.
    ///
    /// # Panics
    /// If `(x, y)` is outside the image.
    #[inline]
    pub fn get(&self, x: u32, y: u32) -> Color {
        self.pixels[self.index(x, y)]
    }

    /// Sets the pixel `(x, y)`.
    ///
    /// # Panics
    /// If `(x, y)` is outside the image.
    #[inline]
    pub fn set(&mut self, x: u32, y: u32, value: Color) {
        let i = self.index(x, y);
        self.pixels[i] = value;
    }

    /// The same image with every pixel mapped by `f`.
    pub fn map(&self, f: impl FnMut(Color) -> Color) -> Image {
        Image {
            width: self.width,
            height: self.height,
            pixels: self.pixels.iter().copied().map(f).collect(),
        }
    }
}
