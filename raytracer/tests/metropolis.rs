//! Metropolis light transport against exact answers and against the path
//! tracer.
//!
//! The noise of a Metropolis image is measured with independent chains,
//! never with per-pixel sample variances (consecutive states of a chain are
//! correlated): every check takes, per tile, the mean and the spread of the
//! chains' own tile means ([`MetropolisResult::chain_tile_means`]), and adds
//! the variance of the bootstrap's `b̂`, which scales the whole image at
//! once. Fixed seeds; each check states its threshold and its false-failure
//! probability. The chains' variances are estimated from `K − 1 = 63`
//! degrees of freedom, so the thresholds come from Student's t, not the
//! normal (P(|t₆₃| > 5.5) = 7.4e-7, P(|t₆₃| > 6) = 1.1e-7), assuming the
//! chains' tile means are about normal (each averages ≥ 256 steps).

use raytracer::integrator::{Bdpt, Integrator, PathTracer};
use raytracer::math::{Color, luminance};
use raytracer::metrics::{tile_means, tile_variances};
use raytracer::render::metropolis::{Metropolis, MetropolisResult};
use raytracer::render::{RenderOptions, render, render_metropolis};
use raytracer::scene::Scene;

const CHAINS: u32 = 64;

fn options(spp: u32, seed: u64, tile_size: u32) -> RenderOptions {
    RenderOptions {
        spp,
        seed,
        threads: None,
        tile_size,
        progress: false,
        label: String::from("test"),
    }
}

fn small(name: &str, w: u32, h: u32) -> Scene {
    let mut scene = Scene::builtin(name).unwrap();
    scene.set_resolution(w, h);
    scene
}

fn mlt(
    scene: &Scene,
    integrator: &dyn Integrator,
    spp: u32,
    seed: u64,
    tile: u32,
    bootstrap: u32,
) -> MetropolisResult {
    let metropolis = Metropolis {
        chains: CHAINS,
        bootstrap: Some(bootstrap),
        ..Metropolis::default()
    };
    let r = render_metropolis(scene, integrator, &options(spp, seed, tile), &metropolis);
    assert!(!r.stats.interrupted);
    assert_eq!(r.chains, CHAINS);
    r
}

/// Per tile and channel: the mean of the chains' tile means and the
/// variance of that mean, `s² / K` over the chains plus `(m · rel(b̂))²`.
fn chain_tiles(r: &MetropolisResult) -> Vec<(Color, [f64; 3])> {
    let k = r.chain_tile_means.len() as f64;
    let rel = r.bootstrap.as_ref().unwrap().relative_error();
    (0..r.chain_tile_means[0].len())
        .map(|t| {
            let mut out = (Color::ZERO, [0.0; 3]);
            for c in 0..3 {
                let values: Vec<f64> = r.chain_tile_means.iter().map(|m| m[t][c] as f64).collect();
                let mean = values.iter().sum::<f64>() / k;
                let s2 = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (k - 1.0);
                out.0[c] = mean as f32;
                out.1[c] = s2 / k + (mean * rel).powi(2);
            }
            out
        })
        .collect()
}

/// The image mean per channel and its variance, from the chains' image
/// means (tiles of equal size) and `b̂`.
fn image_mean(r: &MetropolisResult) -> (Color, [f64; 3]) {
    let k = r.chain_tile_means.len() as f64;
    let rel = r.bootstrap.as_ref().unwrap().relative_error();
    let means: Vec<Color> = r
        .chain_tile_means
        .iter()
        .map(|tiles| tiles.iter().copied().sum::<Color>() / tiles.len() as f32)
        .collect();
    let mut out = (Color::ZERO, [0.0; 3]);
    for c in 0..3 {
        let mean = means.iter().map(|m| m[c] as f64).sum::<f64>() / k;
        let s2 = means
            .iter()
            .map(|m| (m[c] as f64 - mean).powi(2))
            .sum::<f64>()
            / (k - 1.0);
        out.0[c] = mean as f32;
        out.1[c] = s2 / k + (mean * rel).powi(2);
    }
    out
}

/// The closed emitting furnace (`L_e = 0.5`, albedo 0.5, 16×16) is exactly
/// `1 − 0.5^D` in every pixel at max depth D, for Metropolis over BDPT and
/// over the path tracer:
/// - `b̂` (the mean luminance of all paths) within 5.5 of its standard
///   errors of the exact value (a normal tail of 4e-8, 8 checks);
/// - the image's mean luminance equals `b̂` to 1e-5 (every step splats one
///   unit of luminance: this holds for any image, and fails if a weight is
///   wrong);
/// - each of the 16 tiles (4×4) within 6 standard errors of the exact value,
///   with the chains' noise and `b̂`'s: 16 × 8 = 128 tests, false failure
///   < 1.4e-5 in all.
#[test]
fn furnace_gives_one_minus_half_to_the_depth() {
    let scene = small("furnace", 16, 16);
    for depth in [1u32, 2, 3, 5] {
        let exact = 1.0 - 0.5f64.powi(depth as i32);
        let bdpt = Bdpt {
            max_depth: Some(depth),
            rr_depth: 3,
            ..Bdpt::default()
        };
        let path = PathTracer {
            max_depth: Some(depth),
            rr_depth: 3,
            ..PathTracer::default()
        };
        let cases: [(&str, &dyn Integrator); 2] = [("bdpt", &bdpt), ("path", &path)];
        for (name, integrator) in cases {
            let r = mlt(&scene, integrator, 64, 40 + depth as u64, 4, 4096);
            let b = r.bootstrap.as_ref().unwrap();
            let se = b.b_variance.sqrt();
            eprintln!(
                "furnace D = {depth}, over {name}: b = {:.5} ± {se:.5} (exact {exact:.5}), acceptance {:.2}",
                b.b, r.acceptance_rate
            );
            assert!(
                (b.b - exact).abs() <= 5.5 * se + 1e-6,
                "D = {depth}, {name}: b = {} vs {exact} (standard error {se})",
                b.b
            );
            let image = r.film.image();
            let mean = image
                .pixels
                .iter()
                .map(|&c| luminance(c) as f64)
                .sum::<f64>()
                / image.pixels.len() as f64;
            assert!(
                (mean / b.b - 1.0).abs() < 1e-5,
                "D = {depth}, {name}: image mean {mean} vs b = {}",
                b.b
            );
            for (t, (m, var)) in chain_tiles(&r).iter().enumerate() {
                let z = (m.x as f64 - exact) / var[0].sqrt();
                assert!(
                    z.abs() < 6.0,
                    "D = {depth}, {name}: tile {t}: {} vs {exact} (z = {z:.2})",
                    m.x
                );
            }
        }
    }
}

/// The path tracer's image of the Cornell box at max depth 5 (32×32,
/// 1024 spp, independent samples: its tile variances from the film).
fn cornell_path(scene: &Scene, depth: u32) -> (raytracer::film::Image, raytracer::film::Image) {
    let pt = PathTracer {
        max_depth: Some(depth),
        ..PathTracer::default()
    };
    let film = render(scene, &pt, &options(1024, 61, 8)).film;
    (film.image(), film.variance_image())
}

/// Metropolis over BDPT agrees with the path tracer on the Cornell box at
/// max depth 5 (32×32, 64 mutations per pixel in 64 chains, a bootstrap of
/// 4096 paths):
/// - in the image mean, per channel, with the variance of the chains'
///   image means, of `b̂` (about 2 % here: the brightness of the whole
///   Metropolis image is only as good as the bootstrap) and of the path
///   tracer's mean; |z| < 5.5, 3 tests, false failure < 2.2e-6;
/// - tile by tile (16 tiles of 8×8, 3 channels) with the chains' spread per
///   tile, `b̂`'s and the path tracer's tile variance; |z| < 6, 48 tests,
///   false failure < 5.3e-6.
///
/// It can fail: the same Metropolis image against a path tracer stopped two
/// bounces earlier (max depth 3, about 10 % darker) is rejected.
#[test]
fn cornell_agrees_with_the_path_tracer() {
    let scene = small("cornell", 32, 32);
    let bdpt = Bdpt {
        max_depth: Some(5),
        ..Bdpt::default()
    };
    let r = mlt(&scene, &bdpt, 64, 62, 8, 4096);
    let check = |(reference, reference_var): &(raytracer::film::Image, raytracer::film::Image)| {
        let (m, var) = image_mean(&r);
        let ref_mean = tile_means(reference, reference.width)[0];
        let ref_var = tile_variances(reference_var, reference.width)[0];
        let mut worst_mean = 0.0f64;
        for c in 0..3 {
            let z = (m[c] as f64 - ref_mean[c] as f64) / (var[c] + ref_var[c] as f64).sqrt();
            worst_mean = worst_mean.max(z.abs());
        }
        let (ref_tiles, ref_tile_vars) =
            (tile_means(reference, 8), tile_variances(reference_var, 8));
        let mut worst_tile = (0.0f64, 0);
        for (t, (m, var)) in chain_tiles(&r).iter().enumerate() {
            for c in 0..3 {
                let z = (m[c] as f64 - ref_tiles[t][c] as f64)
                    / (var[c] + ref_tile_vars[t][c] as f64).sqrt();
                if z.abs() > worst_tile.0 {
                    worst_tile = (z.abs(), t);
                }
            }
        }
        (worst_mean, worst_tile)
    };
    let b = r.bootstrap.as_ref().unwrap();
    let (mean_z, (tile_z, tile)) = check(&cornell_path(&scene, 5));
    eprintln!(
        "cornell D = 5: b = {:.4} ± {:.2} %, acceptance {:.2}; max |z| image mean {mean_z:.2}, tiles {tile_z:.2} (tile {tile})",
        b.b,
        100.0 * b.relative_error(),
        r.acceptance_rate
    );
    assert!(mean_z < 5.5, "the image means disagree: |z| = {mean_z}");
    assert!(tile_z < 6.0, "tile {tile} disagrees: |z| = {tile_z}");
    let (mean_z, (tile_z, _)) = check(&cornell_path(&scene, 3));
    eprintln!("against max depth 3: max |z| image mean {mean_z:.2}, tiles {tile_z:.2}");
    assert!(
        mean_z >= 5.5 || tile_z >= 6.0,
        "the test cannot tell depth 5 from depth 3"
    );
}

/// The same Metropolis image over BDPT, bit for bit, on 1, 2 and 3 threads
/// (the chains are keyed by their index, not by the thread that runs them,
/// and merged in chain order), and another seed gives another image.
#[test]
fn the_image_does_not_depend_on_the_thread_count() {
    let scene = small("door", 16, 12);
    let bdpt = Bdpt {
        max_depth: Some(5),
        ..Bdpt::default()
    };
    let metropolis = Metropolis {
        chains: 7,
        ..Metropolis::default()
    };
    let run = |threads, seed| {
        let o = RenderOptions {
            threads: Some(threads),
            ..options(8, seed, 4)
        };
        render_metropolis(&scene, &bdpt, &o, &metropolis)
    };
    let one = run(1, 3);
    assert!(
        one.film
            .image()
            .pixels
            .iter()
            .any(|c| c.max_element() > 0.0)
    );
    for threads in [2, 3] {
        let r = run(threads, 3);
        assert!(r.film == one.film, "{threads} threads: the films differ");
        assert_eq!(r.chain_tile_means, one.chain_tile_means);
        assert_eq!(r.bootstrap.unwrap().b, one.bootstrap.as_ref().unwrap().b);
    }
    assert!(run(2, 4).film != one.film, "the seed is ignored");
}

/// The wrapped distance between two numbers of the unit circle `[0, 1)`.
fn wrapped(a: f32, b: f32) -> f32 {
    let d = (a - b).abs();
    d.min(1.0 - d)
}

/// A small step of deviation σ moves every number of every stream by a
/// normal step of deviation σ, however many numbers another stream reads
/// before or after it: the camera stream reads 7 numbers in the state and
/// 11 in the proposal (a longer camera subpath), the connection stream 4
/// and 6, the light stream 9 in both, and each number read twice moves by
/// less than 7σ (a normal tail of 2.6e-12, 20 numbers: false failure
/// < 6e-11). Read in one sequence instead, the light stream's numbers would
/// be the camera's numbers 7 to 15 and then new ones: redrawn, not moved.
#[test]
fn a_small_step_moves_each_streams_numbers_a_little() {
    use raytracer::sampling::{PrimarySample, Sampler, Stream};
    let sigma = 0.01;
    let mut sampler = Sampler::primary(PrimarySample::new(11, 12, 0, sigma));
    let read = |sampler: &mut Sampler, counts: [usize; 3]| {
        sampler.set_dimension(0);
        [Stream::Camera, Stream::Light, Stream::Connection]
            .iter()
            .zip(counts)
            .map(|(&stream, n)| {
                sampler.start_stream(stream);
                (0..n).map(|_| sampler.next_1d()).collect::<Vec<f32>>()
            })
            .collect::<Vec<_>>()
    };
    let before = read(&mut sampler, [7, 9, 4]);
    sampler.primary_sample().unwrap().propose_small(13, 12, 1);
    let after = read(&mut sampler, [11, 9, 6]);
    for (stream, (b, a)) in before.iter().zip(&after).enumerate() {
        for (k, (x, y)) in b.iter().zip(a).enumerate() {
            assert!(
                wrapped(*x, *y) < 7.0 * sigma && x != y,
                "stream {stream}, number {k}: {x} became {y}"
            );
        }
    }
    // Rejected, the state reads its own numbers again.
    sampler.primary_sample().unwrap().reject();
    assert_eq!(read(&mut sampler, [7, 9, 4]), before);
}

/// Records where the light subpath of each sample starts: `y_0` on the lamp.
struct LightStart {
    bdpt: Bdpt,
    y0: std::sync::Mutex<Option<[f32; 3]>>,
}

impl Integrator for LightStart {
    fn name(&self) -> &'static str {
        "bdpt"
    }

    fn sample(
        &self,
        scene: &Scene,
        pixel: raytracer::math::UVec2,
        sampler: &mut raytracer::sampling::Sampler,
        splats: &mut Vec<raytracer::film::Splat>,
    ) -> Color {
        use raytracer::integrator::record::{PathRecord, PathRole};
        let mut record = PathRecord::new("bdpt", pixel, 0);
        let value = self
            .bdpt
            .sample_recorded(scene, pixel, sampler, splats, &mut record);
        *self.y0.lock().unwrap() = record
            .paths
            .iter()
            .find(|p| p.role == PathRole::Light)
            .and_then(|p| p.vertices.first())
            .map(|v| v.position);
        value
    }
}

/// Metropolis over BDPT on `cornell` (16×16, unlimited depth, where the
/// camera subpath's length varies from step to step): every small step
/// (σ = 0.01) moves the point where the light subpath leaves the lamp by a
/// small step of its two numbers, read back from `y_0` on the lamp's
/// rectangle (`y_0 = o + u_x e_1 + u_y e_2`): 32 chains of 100 small steps,
/// each number moved by less than 7σ (a normal tail of 2.6e-12, 6400
/// numbers: false failure < 2e-8). With one sequence for the camera and
/// light subpaths, every step that changed how many numbers the camera
/// subpath read redrew the light subpath (measured: 22.6 % of small steps
/// on this scene at 32×32), and this test failed.
#[test]
fn a_small_step_moves_the_light_subpath_a_little() {
    use raytracer::math::{Vec2, Vec3A};
    use raytracer::render::metropolis::acceptance;
    use raytracer::render::metropolis::chain::{PathSample, evaluate};
    use raytracer::sampling::{PrimarySample, Sampler};
    let scene = small("cornell", 16, 16);
    let lamp = scene
        .objects
        .iter()
        .find(|o| o.name == "light")
        .and_then(|o| o.light)
        .map(|i| &scene.lights[i as usize])
        .unwrap();
    let on_lamp = |u: Vec2| lamp.sample_le(u, Vec2::splat(0.5)).unwrap().p;
    let o = on_lamp(Vec2::ZERO);
    let (e1, e2) = (
        2.0 * (on_lamp(Vec2::new(0.5, 0.0)) - o),
        2.0 * (on_lamp(Vec2::new(0.0, 0.5)) - o),
    );
    assert!(e1.dot(e2).abs() < 1e-6 * e1.length_squared(), "a rectangle");
    let numbers = |y0: [f32; 3]| {
        let d = Vec3A::from(y0) - o;
        [
            d.dot(e1) / e1.length_squared(),
            d.dot(e2) / e2.length_squared(),
        ]
    };
    let spy = LightStart {
        bdpt: Bdpt::default(),
        y0: std::sync::Mutex::new(None),
    };
    let sigma = 0.01;
    let (mut steps, mut jumps) = (0, Vec::new());
    let mut splats = Vec::new();
    for c in 0..32u64 {
        let mut sampler = Sampler::primary(PrimarySample::new(21, c, 0, sigma));
        let (mut current, mut proposed) = (PathSample::default(), PathSample::default());
        evaluate(&scene, &spy, &mut sampler, &mut splats, &mut current);
        let mut y0 = spy.y0.lock().unwrap().map(numbers);
        for t in 1..=100 {
            sampler.primary_sample().unwrap().propose_small(22, c, t);
            evaluate(&scene, &spy, &mut sampler, &mut splats, &mut proposed);
            let next = spy.y0.lock().unwrap().map(numbers);
            if let (Some(a), Some(b)) = (y0, next) {
                steps += 1;
                if (0..2).any(|i| wrapped(a[i], b[i]) >= 7.0 * sigma) {
                    jumps.push((c, t, a, b));
                }
            }
            let a = acceptance(current.f, proposed.f);
            let state = sampler.primary_sample().unwrap();
            if Sampler::new(23, c, t).next_1d() < a {
                state.accept();
                std::mem::swap(&mut current, &mut proposed);
                y0 = next;
            } else {
                state.reject();
            }
        }
    }
    assert!(steps > 3000, "{steps} steps with a light subpath");
    assert!(
        jumps.is_empty(),
        "{} of {steps} small steps moved y_0 far, first (chain, step, from, to): {:?}",
        jumps.len(),
        jumps[0]
    );
}
