//! The wavefront engine is the lecture's path tracer run another way: it
//! must give `path`'s image.
//!
//! - **Sample for sample.** Each path draws `path`'s random numbers in
//!   `path`'s order and sums its radiance in the same order, and the film gets
//!   the samples in the per-sample loop's order, so with the same seed both
//!   engines give the same image bit for bit, on 1 or 2 threads, on every
//!   built-in scene (area, sphere, point and environment lights; Lambert,
//!   textured, Phong, mirror and glass).
//! - **As an estimator.** With independent seeds the two agree tile by tile
//!   (z-tests), the furnaces' exact values come out, and the Cornell box
//!   matches Mitsuba 3's reference tile by tile.
//! - What the engine does not run is refused with one line.

use raytracer::film::Image;
use raytracer::integrator::{DirectStrategy, PathTracer};
use raytracer::metrics::{z_test, z_threshold};
use raytracer::render::{RenderOptions, render};
use raytracer::scene::Scene;
use raytracer::wavefront::WavefrontPathTracer;

fn options(spp: u32, seed: u64, threads: usize) -> RenderOptions {
    RenderOptions {
        spp,
        seed,
        threads: Some(threads),
        progress: false,
        ..RenderOptions::default()
    }
}

fn small(name: &str, width: u32) -> Scene {
    let mut scene = Scene::builtin(name).unwrap();
    let (w, h) = (scene.settings.width, scene.settings.height);
    scene.set_resolution(width, (h * width / w).max(1));
    scene
}

fn same(a: &Image, b: &Image) -> bool {
    a.pixels
        .iter()
        .zip(&b.pixels)
        .all(|(x, y)| x.to_array().map(f32::to_bits) == y.to_array().map(f32::to_bits))
}

/// Every built-in scene, at 40 pixels wide, 20 spp (a full pass and a
/// partial one), max depth 8 and unlimited: the wavefront image is the path
/// tracer's, bit for bit, its mean and its variance, on 1 and 2 threads,
/// with rays traced one by one or as streams.
#[test]
fn same_image_as_path_bit_for_bit_on_every_builtin_scene() {
    let names = [
        "cornell",
        "furnace",
        "white-furnace",
        "caustic",
        "door",
        "stereo",
        "brdf-gallery",
        "veach-mis",
    ];
    for name in names {
        let scene = small(name, 40);
        for max_depth in [Some(8), None] {
            let path = PathTracer {
                max_depth,
                rr_depth: 3,
                strategy: DirectStrategy::Mis,
            };
            let reference = render(&scene, &path, &options(20, 11, 2)).film;
            let engine = WavefrontPathTracer::from_path(&path).unwrap();
            for (threads, streams) in [(1, false), (2, false), (2, true)] {
                let engine = WavefrontPathTracer { streams, ..engine };
                let film = engine.render(&scene, &options(20, 11, threads)).film;
                assert_eq!(film.total_samples(), reference.total_samples());
                assert!(
                    same(&film.image(), &reference.image())
                        && same(&film.variance_image(), &reference.variance_image()),
                    "{name}, max depth {max_depth:?}, {threads} threads, streams {streams}: not path's image"
                );
            }
        }
    }
}

/// With independent seeds, the Cornell box (64×64, 64 spp each, max depth
/// 65) agrees with `path` in 8×8 tiles: 64 tiles × 3 channels of
/// `z = (m_a − m_b)/√(v_a + v_b)`, the threshold bounding their largest |z|
/// with probability 1 − 1e-4 (union bound): false failure below 1e-4.
#[test]
fn agrees_with_path_tile_by_tile_with_independent_seeds() {
    let scene = small("cornell", 64);
    let path = PathTracer {
        max_depth: Some(65),
        rr_depth: 5,
        strategy: DirectStrategy::Mis,
    };
    let a = render(&scene, &path, &options(64, 1, 2)).film;
    let engine = WavefrontPathTracer::from_path(&path).unwrap();
    let b = engine.render(&scene, &options(64, 2, 2)).film;
    let z = z_test(
        &a.image(),
        &a.variance_image(),
        &b.image(),
        &b.variance_image(),
        8,
    );
    let threshold = z_threshold(z.z.len() * 3, 1e-4) as f32;
    assert!(
        z.max_abs_z < threshold,
        "tile {} differs from path: |z| = {:.1} > {threshold:.1}",
        z.worst_tile,
        z.max_abs_z
    );
}

/// The furnace (albedo 0.5, L_e = 0.5): every pixel is `1 − 0.5^D` at max
/// depth D and 1 unlimited; the white furnace's sphere is invisible (1).
/// Image mean against the exact value within 5 standard errors of the film's
/// own variance (false failure below 6e-7 per check).
#[test]
fn furnaces_give_their_exact_values() {
    let engine = |max_depth| WavefrontPathTracer {
        max_depth,
        rr_depth: 3,
        streams: true,
    };
    let cases = [
        ("furnace", Some(1), 0.5),
        ("furnace", Some(3), 1.0 - 0.5f64.powi(3)),
        ("furnace", None, 1.0),
        ("white-furnace", None, 1.0),
    ];
    for (name, max_depth, exact) in cases {
        let scene = small(name, 16);
        let film = engine(max_depth).render(&scene, &options(64, 5, 2)).film;
        let (image, variance) = (film.image(), film.variance_image());
        let n = image.pixels.len() as f64;
        let mean = image.pixels.iter().map(|c| c.x as f64).sum::<f64>() / n;
        let se = (variance.pixels.iter().map(|c| c.x as f64).sum::<f64>() / (n * n)).sqrt();
        assert!(
            (mean - exact).abs() <= 5.0 * se + 1e-6,
            "{name}, max depth {max_depth:?}: mean {mean} vs exact {exact} (standard error {se:.2e})"
        );
    }
}

/// The BRDF-only and light-only variants of `path` are refused, in one line
/// that names the variant.
#[test]
fn refuses_what_it_does_not_run_in_one_line() {
    for (strategy, name) in [
        (DirectStrategy::BrdfOnly, "path-brdf"),
        (DirectStrategy::LightOnly, "path-nee"),
    ] {
        let path = PathTracer {
            strategy,
            ..PathTracer::default()
        };
        let e = WavefrontPathTracer::from_path(&path)
            .unwrap_err()
            .to_string();
        assert!(e.contains(name) && !e.contains('\n'), "{e}");
    }
}

/// Mitsuba 3's Cornell box (`data/cornell-mitsuba.exr`, 2048 spp, see
/// `mitsuba_cornell.rs`) against the wavefront engine at 32 spp, max depth
/// 65: 16×16 tiles × 3 channels of z-scores, the threshold bounding their
/// largest |z| with probability 1 − 1e-4 (union bound), so a false failure
/// has probability below 1e-4.
#[test]
fn cornell_box_matches_mitsuba_tile_by_tile() {
    let read = |name: &str| {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("tests/data")
            .join(name);
        Image::read_exr(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
    };
    let scene = Scene::builtin("cornell").unwrap();
    let engine = WavefrontPathTracer {
        max_depth: Some(65),
        rr_depth: 5,
        streams: false,
    };
    let film = engine.render(&scene, &options(32, 2029, 2)).film;
    let z = z_test(
        &film.image(),
        &film.variance_image(),
        &read("cornell-mitsuba.exr"),
        &read("cornell-mitsuba-variance.exr"),
        16,
    );
    let threshold = z_threshold(z.z.len() * 3, 1e-4) as f32;
    assert!(
        z.max_abs_z < threshold,
        "tile {} differs from Mitsuba: |z| = {:.1} > {threshold:.1}",
        z.worst_tile,
        z.max_abs_z
    );
}
