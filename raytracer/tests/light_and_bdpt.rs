//! Light tracing and bidirectional path tracing against known answers and
//! against the path tracer.
//!
//! All renders use fixed seeds. Each statistical check states its tolerance
//! and its false-failure probability under the normal approximation.

use raytracer::film::Film;
use raytracer::integrator::{Bdpt, Integrator, LightTracer, PathTracer};
use raytracer::metrics::{tile_means, z_test, z_threshold};
use raytracer::render::{RenderOptions, render};
use raytracer::scene::Scene;

fn options(spp: u32, seed: u64, threads: Option<usize>) -> RenderOptions {
    RenderOptions {
        spp,
        seed,
        threads,
        progress: false,
        ..RenderOptions::default()
    }
}

fn small(name: &str, size: u32) -> Scene {
    let mut scene = Scene::builtin(name).unwrap();
    scene.set_resolution(size, size);
    scene
}

fn film(scene: &Scene, integrator: &dyn Integrator, spp: u32, seed: u64) -> Film {
    render(scene, integrator, &options(spp, seed, None)).film
}

/// Mean over all pixels (first channel: the furnace is grey) and its
/// standard error from the film's own variance image (splats included).
/// Light-tracing splats of one path land in several pixels, so pixels are
/// not independent; the whole-image mean is instead read as the mean of `M`
/// independent per-path totals, whose variance is at most the sum of the
/// per-pixel variances plus covariances — we bound the covariances by
/// taking the variance of the sum as `(Σ_j σ_j)²/n²` (Cauchy–Schwarz), a
/// conservative standard error.
fn furnace_mean(film: &Film) -> (f64, f64) {
    let (image, variance) = (film.image(), film.variance_image());
    let n = image.pixels.len() as f64;
    let mean = image.pixels.iter().map(|c| c.x as f64).sum::<f64>() / n;
    let sum_sd: f64 = variance.pixels.iter().map(|c| (c.x as f64).sqrt()).sum();
    (mean, sum_sd / n)
}

/// 5 standard errors (+1e-5 for rounding): false-failure probability
/// < 6e-7 per check (normal approximation; the standard error is conservative).
fn assert_z(what: &str, (mean, se): (f64, f64), exact: f64) {
    let ok = (mean - exact).abs() <= 5.0 * se + 1e-5;
    eprintln!("{what}: {mean:.5} ± {se:.5} (exact {exact})");
    assert!(ok, "{what}: mean {mean:.6} vs exact {exact} (standard error {se:.2e})");
}

#[test]
fn furnace_gives_one_minus_half_to_the_depth() {
    let scene = small("furnace", 16);
    for depth in [Some(1u32), Some(2), Some(3), None] {
        let exact = depth.map_or(1.0, |d| 1.0 - 0.5f64.powi(d as i32));
        let lt = LightTracer {
            max_depth: depth,
            rr_depth: 3,
        };
        let bdpt = Bdpt {
            max_depth: depth,
            rr_depth: 3,
            ..Bdpt::default()
        };
        assert_z(
            &format!("light tracing, max depth {depth:?}"),
            furnace_mean(&film(&scene, &lt, 64, 11)),
            exact,
        );
        assert_z(
            &format!("bdpt, max depth {depth:?}"),
            furnace_mean(&film(&scene, &bdpt, 32, 12)),
            exact,
        );
    }
}
