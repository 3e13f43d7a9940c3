//! Light tracing and bidirectional path tracing against known answers and
//! against the path tracer.
//!
//! All renders use fixed seeds. Each statistical check states its tolerance
//! and its false-failure probability under the normal approximation.

use raytracer::film::Film;
use raytracer::integrator::{Bdpt, Integrator, LightTracer, PathTracer};
use raytracer::metrics::{z_test, z_threshold};
use raytracer::render::{RenderOptions, render, render_pixels, render_strategies};
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

/// A film whose pixel sample `k` of pixel `j` is everything pixel sample
/// `(j, k)` of `integrator` produced — its own value plus all its splats,
/// wherever they landed. Its image mean `(1/(W·H)) Σ_j (1/N_j) Σ_k X_{j,k}`
/// is then `(1/M) Σ (per-path totals)`, the same number as the mean of the
/// real film (whose splat scale is `W·H/M`), but its pixel samples are
/// independent, so the film's variance image gives an honest standard
/// error of the whole-image mean. (On the real film one light path splats
/// into several pixels, and the per-pixel variances ignore those
/// covariances.)
fn path_totals_film(scene: &Scene, integrator: &dyn Integrator, spp: u32, seed: u64) -> Film {
    let (w, h) = (scene.camera.width, scene.camera.height);
    render_pixels(w, h, &options(spp, seed, None), |pixel, sampler, splats| {
        let start = splats.len();
        let mut value = integrator.sample(scene, pixel, sampler, splats);
        for s in &splats[start..] {
            value += s.value;
        }
        splats.truncate(start);
        value
    })
    .film
}

/// Whole-image mean (first channel: the furnace is grey) and its standard
/// error, `√(Σ_j Var_j) / n` for independent pixel means.
fn image_mean(film: &Film) -> (f64, f64) {
    let (image, variance) = (film.image(), film.variance_image());
    let n = image.pixels.len() as f64;
    let mean = image.pixels.iter().map(|c| c.x as f64).sum::<f64>() / n;
    let var: f64 = variance.pixels.iter().map(|c| c.x as f64).sum();
    (mean, var.sqrt() / n)
}

/// 5 standard errors (+1e-5 for rounding): false-failure probability
/// < 6e-7 per check (normal approximation; each mean averages ≥ 8k paths).
fn assert_z(what: &str, (mean, se): (f64, f64), exact: f64) {
    let ok = (mean - exact).abs() <= 5.0 * se + 1e-5;
    eprintln!("{what}: {mean:.5} ± {se:.5} (exact {exact})");
    assert!(
        ok,
        "{what}: mean {mean:.6} vs exact {exact} (standard error {se:.2e})"
    );
}

/// Checks `integrator` on the furnace: the per-path-total mean against the
/// exact value, and the real film (splats scaled by the film) against that
/// mean — the same random numbers, so they agree to rounding (1e-4 relative).
fn check_furnace(what: &str, scene: &Scene, integrator: &dyn Integrator, spp: u32, exact: f64) {
    let totals = image_mean(&path_totals_film(scene, integrator, spp, 11));
    assert_z(what, totals, exact);
    let (real, _) = image_mean(&film(scene, integrator, spp, 11));
    assert!(
        (real - totals.0).abs() <= 1e-4 * exact,
        "{what}: film mean {real} vs per-path totals {}",
        totals.0
    );
}

/// The emitting furnace (L_e = 0.5, albedo 0.5) is exactly `1 − 0.5^D` at
/// max depth D and 1 unlimited, for light tracing and BDPT alike.
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
        // 256 spp: standard error ≈ 0.009, so an error of one depth level
        // (≥ 0.0625 at D ≤ 3) would be ≥ 7σ.
        check_furnace(
            &format!("light tracing, max depth {depth:?}"),
            &scene,
            &lt,
            256,
            exact,
        );
        check_furnace(
            &format!("bdpt, max depth {depth:?}"),
            &scene,
            &bdpt,
            32,
            exact,
        );
    }
}

/// The furnace with albedo 0.98 and `L_e = 0.02`: still exactly
/// `L_e/(1 − ρ) = 1`, but the light's paths are long — Russian roulette
/// (from 5 bounces, survival capped at 0.95) lets a twentieth of them go on
/// past 63 bounces, and the terms of 64 bounces and more hold `0.98⁶⁴ = 27 %`
/// of the light (`ρ^k` of it after `k` bounces). Light tracing and BDPT once kept at most 64 vertices per
/// subpath whatever the max depth said: light tracing then gave 0.721 ±
/// 0.009 here, 32 standard errors off (BDPT loses less, only the strategies of paths
/// longer than its subpaths; its standard error here is about 7 %). Now the
/// max depth is their only limit, as for the path tracer. Tolerance as in
/// [`assert_z`] (5 standard errors, false failure < 6e-7 per check).
#[test]
fn no_vertex_cap_in_a_bright_furnace() {
    let mut parts = raytracer::scene::load_builtin("furnace").unwrap();
    let object = &mut parts.objects[0];
    object.emitter.as_mut().unwrap().radiance = raytracer::math::Color::splat(0.02);
    parts.brdfs[object.brdf as usize] = raytracer::brdf::Brdf::Lambert(raytracer::brdf::Lambert {
        albedo: raytracer::brdf::Texture::Constant(raytracer::math::Color::splat(0.98)),
    });
    let mut scene = Scene::build("bright furnace", parts);
    scene.set_resolution(8, 8);
    let lt = LightTracer {
        max_depth: None,
        rr_depth: 5,
    };
    let bdpt = Bdpt {
        max_depth: None,
        rr_depth: 5,
        ..Bdpt::default()
    };
    let pt = PathTracer::default();
    assert_z(
        "path tracing, albedo 0.98",
        image_mean(&film(&scene, &pt, 256, 12)),
        1.0,
    );
    assert_z(
        "light tracing, albedo 0.98",
        image_mean(&path_totals_film(&scene, &lt, 512, 13)),
        1.0,
    );
    assert_z(
        "bdpt, albedo 0.98",
        image_mean(&path_totals_film(&scene, &bdpt, 64, 14)),
        1.0,
    );
}

/// Path, light and bidirectional tracing render the same Cornell box at max
/// depth `depth` (32×32, 64 spp): a tile-by-tile z-test (8×8 tiles, 16 tiles ×
/// 3 channels × 3 pairs) with the films' own variances. Threshold: Šidák-style
/// for a family-wise false-failure probability of 1e-4 over all 144 tests
/// (≈ 4.9σ). Caveat: light-path splats of one path that land in the same tile
/// are correlated and the film's per-pixel variances ignore that; measured
/// max |z| ≈ 3 at every depth, so the threshold has room. No exception is
/// needed in the Cornell box: it has no specular surface, and the pixels
/// that see the light get it from the light vertex's own `t = 1` connection.
fn cornell_agrees(depth: u32) {
    let scene = small("cornell", 32);
    let pt = PathTracer {
        max_depth: Some(depth),
        ..PathTracer::default()
    };
    let lt = LightTracer {
        max_depth: Some(depth),
        rr_depth: 5,
    };
    let bdpt = Bdpt {
        max_depth: Some(depth),
        ..Bdpt::default()
    };
    let films = [
        film(&scene, &pt, 64, 21),
        film(&scene, &lt, 64, 22),
        film(&scene, &bdpt, 64, 23),
    ];
    let names = ["path", "light", "bdpt"];
    let threshold = z_threshold(16 * 3 * 3, 1e-4) as f32;
    for (a, b) in [(0, 1), (0, 2), (1, 2)] {
        let (fa, fb) = (&films[a], &films[b]);
        let z = z_test(
            &fa.image(),
            &fa.variance_image(),
            &fb.image(),
            &fb.variance_image(),
            8,
        );
        eprintln!(
            "depth {depth}: {} vs {}: max |z| = {:.2} (threshold {threshold:.2})",
            names[a], names[b], z.max_abs_z
        );
        assert!(
            z.max_abs_z < threshold,
            "depth {depth}: {} and {} disagree in tile {:?}: |z| = {}",
            names[a],
            names[b],
            z.worst_tile,
            z.max_abs_z
        );
    }
}

#[test]
fn cornell_agrees_at_depth_2() {
    cornell_agrees(2);
}

#[test]
fn cornell_agrees_at_depth_3() {
    cornell_agrees(3);
}

#[test]
fn cornell_agrees_at_depth_5() {
    cornell_agrees(5);
}

/// The caustic under the glass ball: light → glass → glass → floor → camera.
/// A path tracer cannot find it (its paths would have to hit a point light
/// after refracting); light tracing joins the floor point to the lens, and
/// BDPT does the same with its `t = 1` strategies. The caustic is located as
/// the brightest 4×4 block of floor pixels in the light-tracing image
/// (64×48, 64 spp); there light tracing and BDPT must be far brighter than
/// the path tracer (ratio > 3; measured 6.4 for light tracing and 6.7 for BDPT) and agree with each
/// other within 5 standard errors of the block means (false failure < 6e-7,
/// neglecting the small covariance of splats within a block).
#[test]
fn caustic_is_found_by_light_tracing_and_bdpt_only() {
    let mut scene = Scene::builtin("caustic").unwrap();
    scene.set_resolution(64, 48);
    let (w, h) = (64u32, 48u32);
    let depth = Some(6);
    let pt = PathTracer {
        max_depth: depth,
        ..PathTracer::default()
    };
    let lt = LightTracer {
        max_depth: depth,
        rr_depth: 5,
    };
    let bdpt = Bdpt {
        max_depth: depth,
        ..Bdpt::default()
    };
    let f_pt = film(&scene, &pt, 64, 31);
    let f_lt = film(&scene, &lt, 64, 32);
    let f_bd = film(&scene, &bdpt, 64, 33);
    let (i_pt, i_lt, i_bd) = (f_pt.image(), f_lt.image(), f_bd.image());
    let (v_lt, v_bd) = (f_lt.variance_image(), f_bd.variance_image());
    // Which pixels see the floor (through their centre).
    let floor = |x: u32, y: u32| {
        let ray = scene.camera.generate_ray(
            raytracer::math::Vec2::new(x as f32 + 0.5, y as f32 + 0.5),
            Default::default(),
        );
        scene
            .intersect(&ray)
            .is_some_and(|it| scene.objects[it.shape as usize].name == "floor")
    };
    let block = |img: &raytracer::film::Image, bx: u32, by: u32| -> f64 {
        let mut sum = 0.0;
        for y in by..by + 4 {
            for x in bx..bx + 4 {
                sum += raytracer::math::luminance(img.get(x, y)) as f64;
            }
        }
        sum / 16.0
    };
    let mut best = None;
    for by in 0..h - 3 {
        for bx in 0..w - 3 {
            if (by..by + 4).all(|y| (bx..bx + 4).all(|x| floor(x, y))) {
                let v = block(&i_lt, bx, by);
                if best.is_none_or(|(b, _, _)| v > b) {
                    best = Some((v, bx, by));
                }
            }
        }
    }
    let (lt_mean, bx, by) = best.expect("the floor is visible");
    let (pt_mean, bd_mean) = (block(&i_pt, bx, by), block(&i_bd, bx, by));
    let (var_lt, var_bd) = (block(&v_lt, bx, by) / 16.0, block(&v_bd, bx, by) / 16.0);
    eprintln!(
        "caustic block ({bx}, {by}): path {pt_mean:.3}, light {lt_mean:.3} ± {:.3}, bdpt {bd_mean:.3} ± {:.3}",
        var_lt.sqrt(),
        var_bd.sqrt()
    );
    assert!(lt_mean > 3.0 * pt_mean, "light {lt_mean} vs path {pt_mean}");
    assert!(bd_mean > 3.0 * pt_mean, "bdpt {bd_mean} vs path {pt_mean}");
    assert!(
        (lt_mean - bd_mean).abs() <= 5.0 * (var_lt + var_bd).sqrt(),
        "light {lt_mean} and bdpt {bd_mean} disagree on the caustic"
    );
}

/// Light tracing and BDPT images (splats included) are the same to the last
/// bit with 1 and 2 threads: the render loop merges tiles, and their splats,
/// in a fixed order.
#[test]
fn light_tracing_and_bdpt_are_deterministic() {
    let scene = small("cornell", 24);
    let lt = LightTracer::default();
    let bdpt = Bdpt::default();
    for integrator in [&lt as &dyn Integrator, &bdpt] {
        let run = |threads| {
            let o = RenderOptions {
                tile_size: 8,
                ..options(16, 5, Some(threads))
            };
            render(&scene, integrator, &o).film
        };
        let (one, two) = (run(1), run(2));
        assert!(
            one == two,
            "{}: films differ with 1 and 2 threads",
            integrator.name()
        );
        let (a, b) = (one.image(), two.image());
        assert!(
            a.pixels
                .iter()
                .zip(&b.pixels)
                .all(|(x, y)| x.to_array().map(f32::to_bits) == y.to_array().map(f32::to_bits))
        );
    }
}

/// The per-strategy images of the furnace at max depth 2 (16×16, 64 spp):
/// each unweighted strategy `(s, t)` alone estimates all paths of `s + t`
/// vertices, `0.5^{s+t−1}` (0.5 seen directly, 0.25 after one bounce), and
/// the weighted images add up to `1 − 0.5² = 0.75`. Tolerance 0.07 absolute:
/// 5 standard errors of the noisiest strategy (light tracing `t = 1`,
/// measured standard error ≈ 0.013 of the image mean), false failure < 6e-7
/// per check; the weighted sum is far less noisy (BDPT: ≈ 2e-4).
#[test]
fn strategy_images_add_up() {
    let scene = small("furnace", 16);
    let images = render_strategies(&scene, &options(64, 41, None), 2);
    let keys: Vec<(u32, u32)> = images.iter().map(|(k, _, _)| *k).collect();
    assert_eq!(keys, [(1, 1), (0, 2), (2, 1), (1, 2), (0, 3)]);
    let mut total = 0.0;
    for ((s, t), weighted, unweighted) in &images {
        let exact = 0.5f64.powi((s + t - 1) as i32);
        let w = raytracer::metrics::mean(weighted).x as f64;
        let u = raytracer::metrics::mean(unweighted).x as f64;
        eprintln!("(s, t) = ({s}, {t}): weighted {w:.4}, unweighted {u:.4} (exact {exact})");
        assert!(
            (u - exact).abs() < 0.07,
            "({s}, {t}) unweighted {u} vs {exact}"
        );
        total += w;
    }
    assert!(
        (total - 0.75).abs() < 0.01,
        "weighted strategies sum to {total}"
    );
}
