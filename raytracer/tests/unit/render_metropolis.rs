//! Unit tests of `render/metropolis/mod.rs`.

use raytracer::film::Film;
use raytracer::film::Splat;
use raytracer::integrator::Integrator;
use raytracer::math::Color;
use raytracer::math::{UVec2, Vec2, luminance};
use raytracer::render::RenderOptions;
use raytracer::render::metropolis::parameters::Metropolis;
use raytracer::render::metropolis::*;
use raytracer::sampling::Sampler;
use raytracer::scene::Scene;
use std::sync::atomic::AtomicUsize;
use std::sync::atomic::{AtomicBool, Ordering};

/// A toy integrator with a known image on a `W × 2` film: pixel `(x, y)`
/// gets `(2u · k, k, 1/2)` with `k = 1 + x` and `u` its first number
/// (mean `(k, k, 1/2)`), and every sample splats `(v/10, 0, 0)` into
/// pixel (0, 0) with `v` its second number (mean `W·H/20` there). `f`
/// varies by a factor of 40 over primary space, so the chains are no
/// independent sampler in disguise.
struct Toy {
    /// After this many samples, set `stop` (an interrupted render).
    stop_after: Option<(usize, &'static AtomicBool)>,
    calls: AtomicUsize,
}

impl Toy {
    fn new() -> Self {
        Toy {
            stop_after: None,
            calls: AtomicUsize::new(0),
        }
    }
}

impl Integrator for Toy {
    fn name(&self) -> &'static str {
        "toy"
    }
    fn sample(&self, _: &Scene, pixel: UVec2, s: &mut Sampler, splats: &mut Vec<Splat>) -> Color {
        if let Some((n, flag)) = self.stop_after
            && self.calls.fetch_add(1, Ordering::Relaxed) >= n
        {
            flag.store(true, Ordering::Relaxed);
        }
        let (u, v) = (s.next_1d(), s.next_1d());
        splats.push(Splat {
            raster: Vec2::new(0.5, 0.5),
            value: Color::new(v / 10.0, 0.0, 0.0),
        });
        let k = 1.0 + pixel.x as f32;
        Color::new(2.0 * u * k, k, 0.5)
    }
}

fn toy_scene(width: u32) -> Scene {
    let mut scene = Scene::builtin("furnace").unwrap();
    scene.set_resolution(width, 2);
    scene
}

fn options(spp: u32, threads: usize) -> RenderOptions {
    RenderOptions {
        spp,
        seed: 5,
        threads: Some(threads),
        tile_size: 2,
        progress: false,
        label: "test".into(),
    }
}

fn exact(x: u32, y: u32, width: u32) -> Color {
    let k = 1.0 + x as f32;
    let splat = if (x, y) == (0, 0) {
        width as f32 * 2.0 / 20.0
    } else {
        0.0
    };
    Color::new(k + splat, k, 0.5)
}

/// Every pixel of the toy against its exact value, with the variance
/// of the chains (64 independent chains, given `b̂`) plus `b̂`'s own
/// relative variance. 16 pixels × 3 channels = 48 tests at |z| ≤ 6: with
/// the chains' variance estimated from 63 degrees of freedom, a
/// Student-t tail of 1.1e-7 each, false failure < 6e-6 in all (normal
/// chain means assumed; each averages 256 steps).
#[test]
fn the_toy_image_is_unbiased() {
    let scene = toy_scene(8);
    let metropolis = Metropolis {
        bootstrap: Some(4096),
        ..Metropolis::default()
    };
    let r = render_metropolis_with_stop(
        &scene,
        &Toy::new(),
        &options(1024, 2),
        &metropolis,
        &AtomicBool::new(false),
    );
    assert!(!r.stats.interrupted);
    assert_eq!(r.stats.samples, 1024 * 16);
    assert_eq!(r.chains, 64);
    let b = r.bootstrap.as_ref().unwrap();
    let rel = b.relative_error();
    assert!(rel > 0.0 && rel < 0.05, "{rel}");
    let (image, variance) = (r.film.image(), r.film.variance_image());
    let mut worst = 0.0f64;
    for y in 0..2 {
        for x in 0..8 {
            let (m, v, e) = (image.get(x, y), variance.get(x, y), exact(x, y, 8));
            for c in 0..3 {
                let var = v[c] as f64 + (m[c] as f64 * rel).powi(2);
                let z = (m[c] as f64 - e[c] as f64) / var.sqrt();
                worst = worst.max(z.abs());
                assert!(
                    z.abs() < 6.0,
                    "pixel ({x}, {y}) channel {c}: {} vs {} (z = {z})",
                    m[c],
                    e[c]
                );
            }
        }
    }
    eprintln!(
        "toy: b = {} ± {:.2} %, worst |z| = {worst:.2}",
        b.b,
        100.0 * rel
    );
    // It could fail: the acceptance is far from 1, the chains do move.
    assert!(
        (0.2..0.95).contains(&r.acceptance_rate),
        "{}",
        r.acceptance_rate
    );
}

/// Every step splats one unit of luminance (`(1 − a) f(x)/f(x) + a f(y)/f(y)`),
/// so the image's mean luminance is `b̂` itself, to rounding.
#[test]
fn the_mean_luminance_is_b() {
    let scene = toy_scene(4);
    let r = render_metropolis_with_stop(
        &scene,
        &Toy::new(),
        &options(64, 2),
        &Metropolis::default(),
        &AtomicBool::new(false),
    );
    let image = r.film.image();
    let mean: f64 = image
        .pixels
        .iter()
        .map(|&c| luminance(c) as f64)
        .sum::<f64>()
        / image.pixels.len() as f64;
    let b = r.bootstrap.unwrap().b;
    assert!((mean / b - 1.0).abs() < 1e-5, "{mean} vs {b}");
}

#[test]
fn same_image_on_any_number_of_threads() {
    let scene = toy_scene(5);
    let run = |threads, seed| {
        let o = RenderOptions {
            seed,
            ..options(32, threads)
        };
        render_metropolis_with_stop(
            &scene,
            &Toy::new(),
            &o,
            &Metropolis {
                chains: 7,
                ..Metropolis::default()
            },
            &AtomicBool::new(false),
        )
    };
    let one = run(1, 5);
    for threads in [2, 3] {
        let r = run(threads, 5);
        assert!(r.film == one.film, "{threads} threads: the films differ");
        assert_eq!(r.chain_tile_means, one.chain_tile_means);
        assert_eq!(r.stats.samples, one.stats.samples);
    }
    assert!(run(2, 6).film != one.film, "the seed is ignored");
}

/// The watcher sees the bootstrap, then every chain in chain order, and
/// the last film it is shown is the render's film.
#[test]
fn the_watcher_sees_every_chain_in_order() {
    let scene = toy_scene(4);
    let metropolis = Metropolis {
        chains: 5,
        ..Metropolis::default()
    };
    let mut seen: Vec<(u32, u64, Film)> = Vec::new();
    let r = render_metropolis_watched(
        &scene,
        &Toy::new(),
        &options(16, 2),
        &metropolis,
        &AtomicBool::new(false),
        &mut |p| seen.push((p.chains, p.mutations, p.film.clone())),
    );
    let chains: Vec<u32> = seen.iter().map(|s| s.0).collect();
    assert_eq!(chains, [0, 1, 2, 3, 4, 5]);
    assert!(seen.windows(2).all(|w| w[1].1 > w[0].1));
    let last = seen.last().unwrap();
    assert_eq!(last.1, r.stats.samples);
    assert!(last.2 == r.film, "the last film shown is the render's");
}

/// A stop request half-way: the chains that ran keep their steps (the
/// film has samples, fewer mutations than asked), the others are left
/// out, and the image is still finite and non-negative.
#[test]
fn an_interrupted_render_keeps_its_chains() {
    static STOP: AtomicBool = AtomicBool::new(false);
    let scene = toy_scene(4);
    let toy = Toy {
        stop_after: Some((300 + 8 + 2000, &STOP)),
        calls: AtomicUsize::new(0),
    };
    let metropolis = Metropolis {
        chains: 8,
        bootstrap: Some(300),
        ..Metropolis::default()
    };
    let r = render_metropolis_with_stop(&scene, &toy, &options(1000, 2), &metropolis, &STOP);
    assert!(r.stats.interrupted);
    assert!(
        r.stats.samples >= 1900 && r.stats.samples < 8000,
        "{}",
        r.stats.samples
    );
    assert!(r.chains >= 1 && r.chains <= 8);
    assert_eq!(r.film.sample_count(UVec2::ZERO), r.chains as u64);
    assert!(
        r.film
            .image()
            .pixels
            .iter()
            .all(|c| c.is_finite() && c.min_element() >= 0.0)
    );
    // Stopped during the bootstrap: no chain, an empty film.
    let stopped = AtomicBool::new(true);
    let r = render_metropolis_with_stop(&scene, &Toy::new(), &options(8, 2), &metropolis, &stopped);
    assert!(r.bootstrap.is_none() && r.chains == 0 && r.stats.samples == 0);
    assert!(r.stats.interrupted);
}
