//! Furnace tests: scenes whose exact answer is known.
//!
//! `furnace`: the camera inside a closed sphere whose Lambertian wall has
//! albedo ρ = 0.5 and emits L_e = 0.5 everywhere. The radiance is the same at
//! every point and direction, so the rendering equation collapses to the
//! series L = L_e (1 + ρ + ρ² + …): with Mitsuba's max depth D (at most D − 1
//! bounces) every pixel is exactly `0.5 (1 − 0.5^D)/(1 − 0.5) = 1 − 0.5^D`,
//! and 1 with unlimited depth. `white-furnace`: a sphere of albedo 1 in a
//! uniform environment of radiance 1 reflects exactly what it receives, so it
//! is invisible (every pixel 1).
//!
//! Each check is a z-test: the image mean against the exact value, with the
//! standard error computed from the film's own per-pixel variance. The
//! tolerance of 5 standard errors gives a false-failure probability below
//! 6e-7 per check (normal approximation; each mean averages ≥ 16k samples).

use raytracer::integrator::{DirectStrategy, Integrator, NaiveRecursive, PathTracer};
use raytracer::render::{RenderOptions, render};
use raytracer::scene::Scene;

/// Mean over all pixels and channels, and its standard error.
fn mean_and_standard_error(
    scene: &Scene,
    integrator: &dyn Integrator,
    spp: u32,
    seed: u64,
) -> (f64, f64) {
    let options = RenderOptions {
        spp,
        seed,
        threads: None,
        progress: false,
        ..RenderOptions::default()
    };
    let film = render(scene, integrator, &options).film;
    let (image, variance) = (film.image(), film.variance_image());
    let n = image.pixels.len() as f64;
    // Channels are equal in a grey furnace: use the first, as independent pixels.
    let mean = image.pixels.iter().map(|c| c.x as f64).sum::<f64>() / n;
    let var_of_mean = variance.pixels.iter().map(|c| c.x as f64).sum::<f64>() / (n * n);
    (mean, var_of_mean.sqrt())
}

fn small(name: &str) -> Scene {
    let mut scene = Scene::builtin(name).unwrap();
    scene.set_resolution(16, 16);
    scene
}

fn assert_z(what: &str, (mean, se): (f64, f64), exact: f64) {
    let z = (mean - exact) / se.max(1e-9);
    assert!(
        z.abs() < 5.0,
        "{what}: mean {mean:.6} vs exact {exact} (standard error {se:.2e}, z = {z:.1})"
    );
}

#[test]
fn furnace_converges_to_one_minus_half_to_the_depth() {
    let scene = small("furnace");
    for strategy in [
        DirectStrategy::Mis,
        DirectStrategy::BrdfOnly,
        DirectStrategy::LightOnly,
    ] {
        for depth in [1u32, 2, 3, 6] {
            let pt = PathTracer {
                max_depth: Some(depth),
                rr_depth: 100,
                strategy,
            };
            let exact = 1.0 - 0.5f64.powi(depth as i32);
            let got = mean_and_standard_error(&scene, &pt, 64, 17);
            if depth == 1 {
                // Only L_e is seen: no randomness at all.
                assert!(
                    (got.0 - 0.5).abs() < 1e-6,
                    "{strategy:?} depth 1: {}",
                    got.0
                );
            } else {
                assert_z(&format!("{strategy:?}, max depth {depth}"), got, exact);
            }
        }
        let unlimited = PathTracer {
            max_depth: None,
            rr_depth: 3,
            strategy,
        };
        assert_z(
            &format!("{strategy:?}, unlimited depth"),
            mean_and_standard_error(&scene, &unlimited, 128, 5),
            1.0,
        );
    }
}

#[test]
fn white_furnace_sphere_is_invisible() {
    let scene = small("white-furnace");
    for strategy in [
        DirectStrategy::Mis,
        DirectStrategy::BrdfOnly,
        DirectStrategy::LightOnly,
    ] {
        let pt = PathTracer {
            max_depth: None,
            rr_depth: 5,
            strategy,
        };
        assert_z(
            &format!("{strategy:?}"),
            mean_and_standard_error(&scene, &pt, 64, 3),
            1.0,
        );
    }
}

#[test]
fn naive_recursion_with_roulette_gives_the_furnace_value() {
    let scene = small("furnace");
    // Unlimited depth: split in two once, then single paths that roulette
    // ends (a last factor of 2 would be refused: with q = ρ = 0.5 a ray
    // would have one child on average, a tree that never stops growing).
    let naive = NaiveRecursive::try_new(vec![2, 1], None, Some(1), None).unwrap();
    assert_z(
        "naive, branching 2,1, roulette",
        mean_and_standard_error(&scene, &naive, 32, 8),
        1.0,
    );
    let naive = NaiveRecursive::new(vec![3, 2], Some(4));
    assert_z(
        "naive, branching 3,2, max depth 4",
        mean_and_standard_error(&scene, &naive, 32, 8),
        1.0 - 0.5f64.powi(4),
    );
}

/// Russian roulette judges a branch of naive recursion by what it carries,
/// not by its share `1/N` of the split: in the furnace (every ray hits,
/// every Lambert weight is exactly ρ = 0.5), branching 16, 4, 1 with roulette
/// from depth 2 keeps each of the 64 second-level branches with
/// `q = ρ·ρ = 0.25` and each later one with `q = ρ`, so a sample traces
/// `1 + 16 + 64·0.25·(1 + 1) = 49` rays on average (standard deviation 8.9
/// per sample: 8192 samples give a standard error of 0.1; tolerance 0.5).
/// And the split pays: its per-sample variance times its rays is below that
/// of the same recursion without branching (measured: a third of it).
///
/// What it catches: a survival probability computed from the product that
/// holds every level's `1/N` — then `q = ρ²/16 = 1/64` right after the
/// split, 18 rays per sample, and the roulette undid the branching: at
/// equal rays its variance was 5.6 times the unsplit recursion's, 17 times
/// the fixed split's.
#[test]
fn naive_roulette_keeps_the_branches_of_a_split() {
    let scene = small("furnace");
    let options = RenderOptions {
        spp: 32,
        seed: 9,
        threads: None,
        progress: false,
        ..RenderOptions::default()
    };
    let samples = (scene.camera.width * scene.camera.height * options.spp) as f64;
    let run = |branching: Vec<u32>| {
        let naive = NaiveRecursive::try_new(branching, None, Some(2), None).unwrap();
        let film = render(&scene, &naive, &options).film;
        let variance = raytracer::metrics::mean(&film.variance_image()).x as f64;
        let rays = naive.rays_traced() as f64 / samples;
        (
            variance * samples / (scene.camera.width * scene.camera.height) as f64,
            rays,
        )
    };
    let (split_var, split_rays) = run(vec![16, 4, 1]);
    let (path_var, path_rays) = run(vec![1]);
    eprintln!(
        "split 16,4,1: {split_rays:.2} rays per sample, variance × rays {:.3e}; unsplit: {path_rays:.2} rays, {:.3e}",
        split_var * split_rays,
        path_var * path_rays
    );
    assert!(
        (split_rays - 49.0).abs() < 0.5,
        "{split_rays} rays per sample, expected 49"
    );
    assert!(
        split_var * split_rays < path_var * path_rays,
        "the split costs variance at equal rays: {} vs {}",
        split_var * split_rays,
        path_var * path_rays
    );
}

/// The lecture's throughput cutoff is biased: it drops light, and the
/// furnace shows it. Each level multiplies the product of weights by
/// ρ/N = 0.5/2 (cosine sampling makes every weight exactly ρ), so with a
/// cutoff of 0.2 the hits at depth 2 (product 1/16) no longer recurse: only
/// three terms of the series remain, and the image converges to 1 − 0.5³
/// instead of 1.
#[test]
fn naive_cutoff_is_biased() {
    let scene = small("furnace");
    let naive = NaiveRecursive::try_new(vec![2], None, None, Some(0.2)).unwrap();
    assert_z(
        "naive with cutoff 0.2",
        mean_and_standard_error(&scene, &naive, 32, 8),
        0.875,
    );
}

/// In a closed scene every ray hits a surface, so naive recursion traces
/// exactly `Σ_{d<D} Π_{k<d} N_k` rays per pixel sample: the N^D explosion of
/// the lecture, counted.
#[test]
fn naive_recursion_traces_exactly_the_formula_in_a_closed_scene() {
    let scene = small("furnace");
    for (branching, depth) in [(vec![3u32], 3u32), (vec![4, 2], 4), (vec![2], 5)] {
        let naive = NaiveRecursive::new(branching.clone(), Some(depth));
        let options = RenderOptions {
            spp: 2,
            seed: 1,
            threads: None,
            progress: false,
            ..RenderOptions::default()
        };
        render(&scene, &naive, &options);
        let samples = 16 * 16 * 2;
        let expected = naive.rays_per_sample_bound().unwrap();
        assert_eq!(
            naive.rays_traced(),
            expected * samples,
            "branching {branching:?}, depth {depth}"
        );
    }
    assert_eq!(
        NaiveRecursive::new(vec![3], Some(3)).rays_per_sample_bound(),
        Some(1 + 3 + 9)
    );
    assert_eq!(
        NaiveRecursive::new(vec![4, 2], Some(4)).rays_per_sample_bound(),
        Some(1 + 4 + 8 + 16)
    );
}
