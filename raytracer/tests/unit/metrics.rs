//! Unit tests of `metrics.rs`.

use raytracer::film::Image;
use raytracer::math::{Color, UVec2};
use raytracer::metrics::*;

fn constant(w: u32, h: u32, c: f32) -> Image {
    Image::from_fn(w, h, |_, _| Color::splat(c))
}

#[test]
fn errors_of_known_images() {
    let a = Image::from_fn(2, 2, |x, y| Color::new(x as f32, y as f32, 1.0));
    assert_eq!(mean(&a), Color::new(0.5, 0.5, 1.0));
    let b = constant(2, 2, 1.0);
    // Differences: x−1 ∈ {−1, 0}, y−1 ∈ {−1, 0}, 0: four of the 12 are −1.
    assert!((rmse(&a, &b) - (4.0f32 / 12.0).sqrt()).abs() < 1e-7);
    assert!((mean_abs_diff(&a, &b) - 4.0 / 12.0).abs() < 1e-7);
    // Relative to r = 1: (4 · 1/1.01) / 12.
    assert!((relative_mse(&a, &b) - 4.0 / 1.01 / 12.0).abs() < 1e-7);
    assert_eq!(rmse(&a, &a), 0.0);
    assert_eq!(mean(&Image::new(0, 0)), Color::ZERO);
}

#[test]
#[should_panic(expected = "differ in size")]
fn different_sizes_panic() {
    rmse(&Image::new(2, 2), &Image::new(2, 3));
}

#[test]
fn tiles_cover_partial_edges() {
    // 5×3 with tiles of 2: a 3×2 grid; pixel value = x.
    let img = Image::from_fn(5, 3, |x, _| Color::splat(x as f32));
    assert_eq!(tile_grid(5, 3, 2), UVec2::new(3, 2));
    let m = tile_means(&img, 2);
    let xs: Vec<f32> = m.iter().map(|c| c.x).collect();
    assert_eq!(xs, vec![0.5, 2.5, 4.0, 0.5, 2.5, 4.0]);
    // Variance of a mean of n pixels of variance 1: 1/n.
    let v = tile_variances(&constant(5, 3, 1.0), 2);
    let vs: Vec<f32> = v.iter().map(|c| c.x).collect();
    assert_eq!(vs, vec![0.25, 0.25, 0.5, 0.5, 0.5, 1.0]);
}

#[test]
fn z_scores_of_known_differences() {
    // a − b = 0.1 everywhere; per-pixel variances 0.01 + 0.03 = 0.04;
    // a 2×2 tile mean has variance 0.04/4 = 0.01: z = 0.1/0.1 = 1.
    let (a, b) = (constant(4, 4, 0.6), constant(4, 4, 0.5));
    let z = z_test(&a, &constant(4, 4, 0.01), &b, &constant(4, 4, 0.03), 2);
    assert_eq!(z.grid, UVec2::new(2, 2));
    assert_eq!(z.z.len(), 4);
    assert!((z.max_abs_z - 1.0).abs() < 1e-5, "{}", z.max_abs_z);
    // A bias in one tile is found there, with the right sign.
    let mut c = b.clone();
    c.set(3, 2, Color::splat(0.5 + 0.8));
    let z = z_test(&b, &constant(4, 4, 0.01), &c, &constant(4, 4, 0.03), 2);
    assert_eq!(z.worst_tile, UVec2::new(1, 1));
    assert!((z.z[3].x + 2.0).abs() < 1e-5, "{}", z.z[3]);
    // Exact images: equal → 0, different → ∞; unknown variance → 0.
    let zero = Image::new(4, 4);
    assert_eq!(z_test(&a, &zero, &a, &zero, 2).max_abs_z, 0.0);
    assert_eq!(z_test(&a, &zero, &b, &zero, 2).max_abs_z, f32::INFINITY);
    let unknown = constant(4, 4, f32::INFINITY);
    assert_eq!(z_test(&a, &unknown, &b, &zero, 2).max_abs_z, 0.0);
}

#[test]
fn z_threshold_bounds_the_false_failure_rate() {
    // One two-sided test at 5%: the exact quantile is 1.96; the bound is a
    // little higher. 3000 tests at 1e-6: about 6.3.
    let t = z_threshold(1, 0.05);
    assert!(t > 1.96 && t < 2.1, "{t}");
    let t = z_threshold(3000, 1e-6);
    assert!(t > 6.0 && t < 6.6, "{t}");
}
