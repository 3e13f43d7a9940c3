//! Image statistics: errors between images and the tile z-test of the grader.
//!
//! Lecture topic: Monte Carlo error. A rendered pixel is an estimate `Î` of
//! the true value `I`; its error shrinks like `σ/√N`. These functions measure
//! the error against a reference (RMSE, relative MSE) and decide whether two
//! noisy images can be estimates of the same thing (z-test).
//!
//! All sums are in `f64`. Functions that compare two images panic if their
//! sizes differ (a bug in the caller, not a property of the pictures).

use crate::film::Image;
use crate::math::{Color, UVec2};

fn same_size(a: &Image, b: &Image) {
    assert!(
        a.width == b.width && a.height == b.height,
        "images differ in size: {}×{} vs {}×{}",
        a.width,
        a.height,
        b.width,
        b.height
    );
}

/// The per-channel mean `(1/P) Σ_p c_p` over the `P` pixels (zero if empty).
pub fn mean(img: &Image) -> Color {
    let mut sum = [0.0f64; 3];
    for c in &img.pixels {
        for (s, v) in sum.iter_mut().zip(c.to_array()) {
            *s += v as f64;
        }
    }
    let n = img.pixels.len().max(1) as f64;
    Color::new(
        (sum[0] / n) as f32,
        (sum[1] / n) as f32,
        (sum[2] / n) as f32,
    )
}

/// The mean over all pixels and channels of `f(a, b)`.
fn mean_over_channels(a: &Image, b: &Image, f: impl Fn(f64, f64) -> f64) -> f64 {
    same_size(a, b);
    let mut sum = 0.0;
    for (x, y) in a.pixels.iter().zip(&b.pixels) {
        for c in 0..3 {
            sum += f(x[c] as f64, y[c] as f64);
        }
    }
    sum / (3 * a.pixels.len()).max(1) as f64
}

/// Root mean squared error `sqrt((1/3P) Σ_{p,c} (a − b)²)` over all pixels
/// and channels.
pub fn rmse(a: &Image, b: &Image) -> f32 {
    mean_over_channels(a, b, |x, y| (x - y) * (x - y)).sqrt() as f32
}

/// Relative mean squared error `(1/3P) Σ_{p,c} (a − r)² / (r² + ε)` of `a`
/// against the reference `r`, with `ε = 0.01` so that black pixels do not
/// divide by zero (the usual definition in the denoising literature). It
/// weighs errors in dark and bright regions alike.
pub fn relative_mse(a: &Image, reference: &Image) -> f32 {
    const EPS: f64 = 0.01;
    mean_over_channels(a, reference, |x, r| (x - r) * (x - r) / (r * r + EPS)) as f32
}

/// Mean absolute difference `(1/3P) Σ_{p,c} |a − b|`.
pub fn mean_abs_diff(a: &Image, b: &Image) -> f32 {
    mean_over_channels(a, b, |x, y| (x - y).abs()) as f32
}

/// The number of tiles across and down for square tiles of `tile` pixels
/// (the last row and column may be partial).
pub fn tile_grid(width: u32, height: u32, tile: u32) -> UVec2 {
    let tile = tile.max(1);
    UVec2::new(width.div_ceil(tile), height.div_ceil(tile))
}

/// Applies `f` to the pixels of each tile, row by row, tiles in raster order.
fn per_tile(
    img: &Image,
    tile: u32,
    mut f: impl FnMut(&mut dyn Iterator<Item = Color>) -> Color,
) -> Vec<Color> {
    let tile = tile.max(1);
    let grid = tile_grid(img.width, img.height, tile);
    let mut out = Vec::with_capacity((grid.x * grid.y) as usize);
    for ty in 0..grid.y {
        for tx in 0..grid.x {
            let (x0, y0) = (tx * tile, ty * tile);
            let (x1, y1) = ((x0 + tile).min(img.width), (y0 + tile).min(img.height));
            let mut pixels = (y0..y1).flat_map(|y| (x0..x1).map(move |x| img.get(x, y)));
            out.push(f(&mut pixels));
        }
    }
    out
}

/// The mean of each `tile × tile` block (partial blocks at the right and
/// bottom edges average their own pixels), in raster order of the tiles.
///
/// Averaging over a tile trades resolution for noise: a tile of `n` pixels
/// has `n` times less variance than one pixel, so a small bias that is lost
/// in the noise of single pixels stands out in a tile.
pub fn tile_means(img: &Image, tile: u32) -> Vec<Color> {
    per_tile(img, tile, |pixels| sum_over(pixels, 1))
}

/// The variance of each tile's mean, given per-pixel variances of the mean
/// (e.g. [`Film::variance_image`](crate::film::Film::variance_image)): pixels
/// are independent estimates, so `Var((1/n) Σ X_p) = (1/n²) Σ Var(X_p)`.
pub fn tile_variances(variance: &Image, tile: u32) -> Vec<Color> {
    per_tile(variance, tile, |pixels| sum_over(pixels, 2))
}

/// `(Σ c) / nᵖ` over the pixels, in `f64`.
fn sum_over(pixels: &mut dyn Iterator<Item = Color>, power: i32) -> Color {
    let mut sum = [0.0f64; 3];
    let mut n = 0usize;
    for c in pixels {
        for (s, v) in sum.iter_mut().zip(c.to_array()) {
            *s += v as f64;
        }
        n += 1;
    }
    let d = (n.max(1) as f64).powi(power);
    Color::new(
        (sum[0] / d) as f32,
        (sum[1] / d) as f32,
        (sum[2] / d) as f32,
    )
}

/// The result of a tile-by-tile z-test between two images.
#[derive(Clone, Debug, PartialEq)]
pub struct ZTest {
    /// Tile edge in pixels.
    pub tile: u32,
    /// Tiles across and down.
    pub grid: UVec2,
    /// Per tile (raster order) and channel: `z = (m_a − m_b) / √(v_a + v_b)`.
    pub z: Vec<Color>,
    /// The largest `|z|` over all tiles and channels.
    pub max_abs_z: f32,
    /// The tile (column, row) where it occurs.
    pub worst_tile: UVec2,
}

/// Compares two estimates of the same image tile by tile.
///
/// `a` and `b` are the images, `a_var` and `b_var` the variances of their
/// pixel means (e.g. `film.variance_image()`; a zero image for an exact
/// reference). For every tile and channel, with tile means `m` and variances
/// of the tile means `v` ([`tile_variances`]),
///
/// ```text
///   z = (m_a − m_b) / √(v_a + v_b)
/// ```
///
/// is about standard normal if both are unbiased estimates of the same image
/// (central limit theorem over the tile's samples). A large `|z|` is evidence
/// of a bias. Conventions: an infinite variance (unknown, see the film) gives
/// `z = 0`; zero variance gives `z = 0` if the means agree and `±∞` if not.
pub fn z_test(a: &Image, a_var: &Image, b: &Image, b_var: &Image, tile: u32) -> ZTest {
    same_size(a, b);
    same_size(a, a_var);
    same_size(b, b_var);
    let (ma, mb) = (tile_means(a, tile), tile_means(b, tile));
    let (va, vb) = (tile_variances(a_var, tile), tile_variances(b_var, tile));
    let grid = tile_grid(a.width, a.height, tile);
    let mut result = ZTest {
        tile: tile.max(1),
        grid,
        z: Vec::with_capacity(ma.len()),
        max_abs_z: 0.0,
        worst_tile: UVec2::ZERO,
    };
    for i in 0..ma.len() {
        let z: [f32; 3] = std::array::from_fn(|c| {
            let d = ma[i][c] as f64 - mb[i][c] as f64;
            let v = va[i][c] as f64 + vb[i][c] as f64;
            if v.is_infinite() || d == 0.0 {
                0.0
            } else {
                (d / v.sqrt()) as f32
            }
        });
        let z = Color::from_array(z);
        let worst = z.abs().max_element();
        // `>` is false for NaN: a NaN never hides behind a finite maximum.
        if worst > result.max_abs_z || worst.is_nan() {
            result.max_abs_z = worst;
            result.worst_tile = UVec2::new(i as u32 % grid.x, i as u32 / grid.x);
        }
        result.z.push(z);
    }
    result
}

/// A threshold `t` for the largest `|z|` of `tests` z-scores such that, if all
/// are standard normal, `P(max |z| > t) ≤ alpha`.
///
/// Union (Bonferroni) bound over the tests with the Mills-ratio tail bound
/// `P(|Z| > t) ≤ 2 φ(t) / t`, `φ(t) = e^{−t²/2} / √(2π)`: it is solved for
/// `tests · 2φ(t)/t = alpha` by bisection. Both bounds are conservative, so
/// the false-failure probability is at most `alpha` (e.g. 1000 tiles ×
/// 3 channels with `alpha = 1e-6` gives `t ≈ 6.3`).
pub fn z_threshold(tests: usize, alpha: f64) -> f64 {
    let tail = |t: f64| {
        tests.max(1) as f64 * 2.0 * (-0.5 * t * t).exp() / ((2.0 * std::f64::consts::PI).sqrt() * t)
    };
    let (mut lo, mut hi) = (0.5f64, 40.0f64);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if tail(mid) > alpha {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    hi
}
