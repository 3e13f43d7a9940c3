//! Light-field images: an N×N grid of pinhole views across an aperture.
//!
//! Lecture topic: "light-field images" — the radiance arriving at every point
//! of a small 2D patch (the size of a camera's front lens) from every
//! direction, a 4D function. A pinhole image is one point of the patch; a
//! grid of them samples the whole light field. From it one can refocus after
//! the fact and take stereo pairs, as the lecture says.
//!
//! # Geometry
//!
//! View `(col, row)` is a pinhole at `position + u · rightDir + v · upDir`
//! looking along the same `forward` (parallel views), with
//! `u = −A/2 + col · A/(N−1)` left to right and `v = A/2 − row · A/(N−1)`
//! top to bottom, `A` the aperture's side. A point at depth `d` (along
//! `forward`) that the central view sees at raster `(x₀, y₀)` appears in the
//! view at `(u, v)` at
//!
//! ```text
//!   x = x₀ − k u / d,   y = y₀ + k v / d,   k = H / (2 tan(fov/2))
//! ```
//!
//! (`k` pixels per image-plane unit at distance 1; raster `y` grows
//! downwards). Shift-and-add refocusing at depth `d` averages every view read
//! at these positions: points at depth `d` add up in register and are sharp,
//! others are spread over the views' disparities — the synthetic aperture of
//! side `A` blurs them exactly as a lens of that size focused at `d` would
//! (with N² discrete lens points, so blur shows as N² faint copies).

use super::anaglyph::assert_same_size;
use crate::camera::{Camera, CameraParams};
use crate::film::Image;
use crate::integrator::Integrator;
use crate::math::{Color, Vec2, luminance};
use crate::render::{RenderOptions, render};
use crate::scene::Scene;

/// A grid of pinhole views and the camera they were taken around.
#[derive(Clone, Debug)]
pub struct LightField {
    /// Views per side.
    pub n: u32,
    /// Side of the square aperture the views cover, in scene units.
    pub aperture: f32,
    /// The central camera (its lens is ignored: every view is a pinhole).
    pub base: Camera,
    /// The views, row by row from the top, each row from the left.
    pub views: Vec<Image>,
}

impl LightField {
    /// Offset `(u, v)` of view `(col, row)` along `(rightDir, upDir)`.
    pub fn offset(n: u32, aperture: f32, col: u32, row: u32) -> Vec2 {
        if n <= 1 {
            return Vec2::ZERO;
        }
        let step = aperture / (n - 1) as f32;
        Vec2::new(
            -0.5 * aperture + col as f32 * step,
            0.5 * aperture - row as f32 * step,
        )
    }

    /// The pinhole camera of view `(col, row)`.
    pub fn view_camera(base: &Camera, n: u32, aperture: f32, col: u32, row: u32) -> Camera {
        let o = Self::offset(n, aperture, col, row);
        let d = o.x * base.right_dir() + o.y * base.up_dir();
        let p = base.params;
        Camera::new(
            CameraParams {
                position: p.position + d,
                look_at: p.look_at + d,
                aperture_radius: 0.0,
                ..p
            },
            base.width,
            base.height,
        )
    }

    /// Renders the `n × n` views of `scene` around its camera, all with the
    /// same options and seed (correlated noise, as for the stereo eyes).
    ///
    /// # Panics
    /// If `n` is 0.
    pub fn render(
        scene: &Scene,
        integrator: &dyn Integrator,
        options: &RenderOptions,
        n: u32,
        aperture: f32,
    ) -> LightField {
        assert!(n > 0, "a light field needs at least one view");
        let base = scene.camera;
        let mut view_scene = scene.clone();
        let mut views = Vec::with_capacity((n * n) as usize);
        for row in 0..n {
            for col in 0..n {
                view_scene.camera = Self::view_camera(&base, n, aperture, col, row);
                let opts = RenderOptions {
                    label: format!("{} {}/{}", options.label, row * n + col + 1, n * n),
                    ..options.clone()
                };
                views.push(render(&view_scene, integrator, &opts).film.image());
            }
        }
        LightField {
            n,
            aperture,
            base,
            views,
        }
    }

    /// View `(col, row)`.
    pub fn view(&self, col: u32, row: u32) -> &Image {
        &self.views[(row * self.n + col) as usize]
    }

    /// Pixels per image-plane unit at distance 1 (`k` of the module doc).
    pub fn pixels_per_unit(&self) -> f32 {
        self.base.height as f32 / (2.0 * (self.base.params.vfov_deg.to_radians() * 0.5).tan())
    }

    /// Synthetic refocusing at depth `depth` by shift-and-add (module doc).
    pub fn refocus(&self, depth: f32) -> Image {
        let k = self.pixels_per_unit() / depth;
        let (w, h) = (self.base.width, self.base.height);
        let mut sum = vec![Color::ZERO; (w * h) as usize];
        for row in 0..self.n {
            for col in 0..self.n {
                let o = Self::offset(self.n, self.aperture, col, row);
                let shift = Vec2::new(-k * o.x, k * o.y);
                let view = self.view(col, row);
                for y in 0..h {
                    for x in 0..w {
                        let p = Vec2::new(x as f32, y as f32) + shift;
                        sum[(y * w + x) as usize] += bilinear(view, p);
                    }
                }
            }
        }
        let scale = 1.0 / (self.n * self.n) as f32;
        Image {
            width: w,
            height: h,
            pixels: sum.into_iter().map(|c| c * scale).collect(),
        }
    }

    /// A stereo pair out of the grid: views `left_col` and `right_col` of
    /// `row`, `(right_col − left_col) · A/(N−1)` apart. The parallel views
    /// converge at infinity; with `convergence = Some(C)` each image is moved
    /// sideways by half the disparity of depth `C` (`k b / (2C)` pixels), so
    /// that depth has zero parallax, as the off-axis eyes of the rig.
    pub fn stereo_pair(
        &self,
        row: u32,
        left_col: u32,
        right_col: u32,
        convergence: Option<f32>,
    ) -> [Image; 2] {
        let (l, r) = (self.view(left_col, row), self.view(right_col, row));
        let Some(c) = convergence else {
            return [l.clone(), r.clone()];
        };
        let ul = Self::offset(self.n, self.aperture, left_col, row).x;
        let ur = Self::offset(self.n, self.aperture, right_col, row).x;
        let half = 0.5 * (ur - ul) * self.pixels_per_unit() / c;
        let moved = |img: &Image, dx: f32| {
            Image::from_fn(img.width, img.height, |x, y| {
                bilinear(img, Vec2::new(x as f32 + dx, y as f32))
            })
        };
        // A point at depth C is at x₀ − k u / C in each view: read it there.
        [moved(l, half), moved(r, -half)]
    }

    /// All views tiled in their grid positions, `gap` black pixels apart.
    pub fn contact_sheet(&self, gap: u32) -> Image {
        let (w, h) = (self.base.width, self.base.height);
        let side_w = self.n * w + (self.n - 1) * gap;
        let side_h = self.n * h + (self.n - 1) * gap;
        Image::from_fn(side_w, side_h, |x, y| {
            let (col, ix) = (x / (w + gap), x % (w + gap));
            let (row, iy) = (y / (h + gap), y % (h + gap));
            if ix < w && iy < h {
                self.view(col, row).get(ix, iy)
            } else {
                Color::ZERO
            }
        })
    }
}

/// Bilinear reading of `img` at pixel coordinates `p` (pixel `(i, j)`'s
/// centre at `(i, j)`), clamped to the edge.
#[inline]
fn bilinear(img: &Image, p: Vec2) -> Color {
    let max = Vec2::new(img.width as f32 - 1.0, img.height as f32 - 1.0);
    let p = p.clamp(Vec2::ZERO, max);
    let (x0, y0) = (p.x.floor() as u32, p.y.floor() as u32);
    let (x1, y1) = ((x0 + 1).min(img.width - 1), (y0 + 1).min(img.height - 1));
    let (fx, fy) = (p.x - x0 as f32, p.y - y0 as f32);
    let top = img.get(x0, y0) * (1.0 - fx) + img.get(x1, y0) * fx;
    let bottom = img.get(x0, y1) * (1.0 - fx) + img.get(x1, y1) * fx;
    top * (1.0 - fy) + bottom * fy
}

/// A sharpness measure: the mean squared difference of the luminance of
/// horizontally and vertically neighbouring pixels (the energy of the image's
/// gradient). Blur lowers it; it is larger for sharper edges.
pub fn sharpness(img: &Image) -> f64 {
    let y = |x: u32, j: u32| luminance(img.get(x, j)) as f64;
    let mut sum = 0.0;
    let mut count = 0u64;
    for j in 0..img.height {
        for x in 0..img.width {
            if x + 1 < img.width {
                sum += (y(x + 1, j) - y(x, j)).powi(2);
                count += 1;
            }
            if j + 1 < img.height {
                sum += (y(x, j + 1) - y(x, j)).powi(2);
                count += 1;
            }
        }
    }
    if count == 0 { 0.0 } else { sum / count as f64 }
}

/// The mean absolute difference of two images' luminance (for tests and
/// the page: how different two views are).
pub fn mean_abs_difference(a: &Image, b: &Image) -> f64 {
    assert_same_size(a, b);
    let sum: f64 = a
        .pixels
        .iter()
        .zip(&b.pixels)
        .map(|(&p, &q)| (luminance(p) - luminance(q)).abs() as f64)
        .sum();
    sum / a.pixels.len().max(1) as f64
}
