//! The biased algorithms of the lecture (photon mapping, SPPM, instant
//! radiosity, irradiance caching): exact where their bias vanishes, and
//! biased, or consistent, as each is known to be.
//!
//! Their pixels are not independent samples (every pixel reads the same
//! photons, VPLs or cache records), so a film's per-pixel variance says
//! nothing about the error of an image mean. Each furnace check therefore
//! renders `K` = 12 independent runs (seeds for the camera and the light
//! side alike) and t-tests the mean of their image means against the exact
//! value: |t| < 6.5 with 11 degrees of freedom has a false-failure
//! probability of 4.5e-5 per check.

use std::sync::atomic::AtomicBool;

use raytracer::film::Image;
use raytracer::integrator::{
    InstantRadiosity, Integrator, IrradianceCache, IrradianceCacheSettings, PathTracer,
    PhotonMapping, PhotonSettings, VplSettings,
};
use raytracer::math::Color;
use raytracer::metrics::{mean, tile_means, tile_variances};
use raytracer::render::sppm::SppmSettings;
use raytracer::render::sppm::render_sppm_with_stop;
use raytracer::render::{RenderOptions, render};
use raytracer::scene::Scene;

const RUNS: u64 = 12;
const T_MAX: f64 = 6.5;

fn options(spp: u32, seed: u64) -> RenderOptions {
    RenderOptions {
        spp,
        seed,
        threads: None,
        progress: false,
        ..RenderOptions::default()
    }
}

fn small(name: &str, w: u32, h: u32) -> Scene {
    let mut scene = Scene::builtin(name).unwrap();
    scene.set_resolution(w, h);
    scene
}

fn image(scene: &Scene, integrator: &dyn Integrator, spp: u32, seed: u64) -> Image {
    render(scene, integrator, &options(spp, seed)).film.image()
}

/// The t statistic of `values` against `exact`, and their mean.
fn t_stat(values: &[f64], exact: f64) -> (f64, f64) {
    let n = values.len() as f64;
    let m = values.iter().sum::<f64>() / n;
    let var = values.iter().map(|v| (v - m) * (v - m)).sum::<f64>() / (n - 1.0);
    ((m - exact) / (var / n).sqrt().max(1e-9), m)
}

fn assert_furnace(what: &str, exact: f64, run: impl Fn(u64) -> Image) {
    let means: Vec<f64> = (0..RUNS).map(|s| mean(&run(s)).x as f64).collect();
    let (t, m) = t_stat(&means, exact);
    eprintln!("{what}: {m:.5} vs {exact:.5} (t = {t:.2})");
    assert!(
        t.abs() < T_MAX,
        "{what}: mean {m:.5} vs exact {exact:.5}, t = {t:.1}"
    );
}

fn photon_settings(max_depth: u32, seed: u64) -> PhotonSettings {
    PhotonSettings {
        photons: 20_000,
        k: 30,
        max_depth: Some(max_depth),
        rr_depth: 100,
        seed: 1000 + seed,
        ..PhotonSettings::default()
    }
}

/// Photon mapping in the closed furnace (albedo 0.5, emission 0.5): the
/// radiance is uniform, so the density estimate has no bias and every pixel
/// is `1 − 0.5^D` — read from the global map, by final gathering, and with
/// a fixed radius.
#[test]
fn photon_mapping_gives_the_furnace_exactly() {
    let scene = small("furnace", 16, 16);
    let never = AtomicBool::new(false);
    for depth in [2u32, 3, 5] {
        let exact = 1.0 - 0.5f64.powi(depth as i32);
        assert_furnace(&format!("photon, D = {depth}"), exact, |s| {
            let pm = PhotonMapping::build(&scene, photon_settings(depth, s), &never).unwrap();
            image(&scene, &pm, 4, s)
        });
    }
    assert_furnace(
        "photon, final gathering, D = 4",
        1.0 - 0.5f64.powi(4),
        |s| {
            let settings = PhotonSettings {
                final_gather: 4,
                ..photon_settings(4, s)
            };
            let pm = PhotonMapping::build(&scene, settings, &never).unwrap();
            image(&scene, &pm, 2, s)
        },
    );
    assert_furnace("photon, radius 0.1, D = 4", 1.0 - 0.5f64.powi(4), |s| {
        let settings = PhotonSettings {
            radius: Some(0.1),
            ..photon_settings(4, s)
        };
        let pm = PhotonMapping::build(&scene, settings, &never).unwrap();
        image(&scene, &pm, 2, s)
    });
}

fn vpl(
    scene: &Scene,
    paths: u64,
    clamp: f32,
    max_depth: Option<u32>,
    seed: u64,
) -> InstantRadiosity {
    let settings = VplSettings {
        paths,
        clamp,
        max_depth,
        rr_depth: 5,
        seed: 2000 + seed,
    };
    InstantRadiosity::build(scene, settings, &AtomicBool::new(false)).unwrap()
}

/// Instant radiosity without clamping in the closed furnace: `1 − 0.5^D`.
/// Every VPL can be gathered: one `k` segments from the light takes a
/// camera path of at least one segment and the connection, `k + 2 ≤ D`.
/// (The light paths were traced one vertex too far: at D = 3 almost half
/// the VPLs could never be used.)
#[test]
fn every_vpl_fits_within_the_max_depth() {
    let scene = small("cornell", 8, 8);
    for d in [2u32, 3, 5] {
        let ir = vpl(&scene, 64, 0.0, Some(d), 1);
        assert!(d == 2 || !ir.vpls().is_empty(), "D = {d}: no VPL at all");
        for v in ir.vpls() {
            assert!(
                v.segments + 2 <= d,
                "D = {d}: a VPL {} segments from the light can never be gathered",
                v.segments
            );
        }
    }
}

#[test]
fn unclamped_vpl_gives_the_furnace_exactly() {
    let scene = small("furnace", 16, 16);
    for depth in [2u32, 3, 5] {
        let exact = 1.0 - 0.5f64.powi(depth as i32);
        assert_furnace(&format!("vpl, D = {depth}"), exact, |s| {
            image(&scene, &vpl(&scene, 64, 0.0, Some(depth), s), 2, s)
        });
    }
}

/// The Cornell box (32×32, D = 5): the tiles of unclamped instant radiosity,
/// averaged over K = 16 independent VPL sets (64 light paths each), agree
/// with a 512-spp path tracer tile by tile; clamped at g_max = 0.5 the
/// image is darker.
///
/// Each of the 16 tiles (8×8 pixels) × 3 channels is a t-test of the runs'
/// tile means against the path tracer's (whose standard error is added):
/// |t| < 7 with 15 degrees of freedom fails by chance with probability
/// 4e-6 each, < 2e-4 for all 48 (measured: worst |t| = 3.6). Clamping
/// removes light only where G > 0.5, i.e. where x and the VPL are within
/// about 1.4 of each other facing one another (the box is 2 wide): the
/// whole image loses 5.2% (at g_max = 2 it loses 1.8%); the test demands
/// 3–10%, and no tile may come out brighter than the unclamped mean by
/// more than 5 of its standard errors.
#[test]
fn unclamped_vpl_agrees_with_the_path_tracer_and_clamping_darkens() {
    let scene = small("cornell", 32, 32);
    let depth = Some(5);
    let pt = PathTracer {
        max_depth: depth,
        ..PathTracer::default()
    };
    let reference = render(&scene, &pt, &options(512, 7)).film;
    let (ref_tiles, ref_var) = (
        tile_means(&reference.image(), 8),
        tile_variances(&reference.variance_image(), 8),
    );
    let runs = 16u64;
    let per_run = |clamp: f32| -> Vec<Vec<Color>> {
        (0..runs)
            .map(|s| tile_means(&image(&scene, &vpl(&scene, 64, clamp, depth, s), 4, s), 8))
            .collect()
    };
    let (free, clamped) = (per_run(0.0), per_run(0.5));
    let stats = |runs: &[Vec<Color>], t: usize, c: usize| {
        let v: Vec<f64> = runs.iter().map(|r| r[t][c] as f64).collect();
        let n = v.len() as f64;
        let m = v.iter().sum::<f64>() / n;
        let var = v.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / (n - 1.0);
        (m, var / n)
    };
    let mut worst = 0.0f64;
    for t in 0..ref_tiles.len() {
        for c in 0..3 {
            let (m, var) = stats(&free, t, c);
            let z = (m - ref_tiles[t][c] as f64) / (var + ref_var[t][c] as f64).sqrt().max(1e-9);
            worst = worst.max(z.abs());
            assert!(
                z.abs() < 7.0,
                "tile {t}, channel {c}: vpl {m:.4} vs path {:.4} (t = {z:.1})",
                ref_tiles[t][c]
            );
            let (mc, var_c) = stats(&clamped, t, c);
            assert!(
                mc <= m + 5.0 * (var + var_c).sqrt() + 1e-6,
                "tile {t}, channel {c}: clamped {mc:.4} brighter than unclamped {m:.4}"
            );
        }
    }
    let total = |runs: &[Vec<Color>]| -> f64 {
        runs.iter().flatten().map(|c| c.element_sum() as f64).sum()
    };
    let loss = 1.0 - total(&clamped) / total(&free);
    eprintln!(
        "vpl vs path: worst |t| {worst:.2}; clamping at 0.5 loses {:.1}%",
        100.0 * loss
    );
    assert!(
        (0.03..0.10).contains(&loss),
        "clamping lost {:.1}%",
        100.0 * loss
    );
}

fn sppm_image(scene: &Scene, settings: &SppmSettings, passes: u32, seed: u64) -> Image {
    render_sppm_with_stop(
        scene,
        settings,
        &options(passes, seed),
        &AtomicBool::new(false),
    )
    .image
}

/// SPPM in the closed furnace: `1 − 0.5^D` (the box kernel over a uniform
/// photon density has no bias; the radius reduction keeps it so).
#[test]
fn sppm_gives_the_furnace_exactly() {
    let scene = small("furnace", 16, 16);
    for depth in [2u32, 4] {
        let settings = SppmSettings {
            photons: 4000,
            max_depth: Some(depth),
            rr_depth: 100,
            ..SppmSettings::default()
        };
        let exact = 1.0 - 0.5f64.powi(depth as i32);
        assert_furnace(&format!("sppm, D = {depth}"), exact, |s| {
            sppm_image(&scene, &settings, 4, 3000 + s)
        });
    }
}

/// Mitsuba's reference of the Cornell box (256×256) averaged over 8×8
/// blocks: the expected value of each pixel of a 32×32 render (box filter).
fn mitsuba_32() -> Image {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/cornell-mitsuba.exr");
    let full = Image::read_exr(&path).unwrap();
    Image::from_fn(32, 32, |x, y| {
        let mut sum = Color::ZERO;
        for j in 0..8 {
            for i in 0..8 {
                sum += full.get(8 * x + i, 8 * y + j);
            }
        }
        sum / 64.0
    })
}

/// SPPM is consistent: on the Cornell box (32×32, Mitsuba's max depth 65)
/// its bias against Mitsuba's reference falls from 4 to 16 to 64 passes.
///
/// The bias is made visible with a large initial radius (0.5, a quarter of
/// the box): then the blur dominates the noise. Each pass count is rendered
/// with 8 seeds (3 000 photon paths per pass) and their tile means averaged
/// (4×4 tiles of 8×8 pixels; the two tiles holding the light are left out,
/// as their error is the anti-aliasing noise of the light's edge, 18.6 vs
/// 0.5 in one pixel). The RMS of the tiles' relative errors must fall
/// monotonically (measured 4.2%, 3.2%, 2.5%) and after 64 passes every tile
/// must be within 9% (measured 5.4%). The seeds are fixed, so the numbers
/// do not change from run to run; under other random numbers (10 other sets
/// of 8 seeds measured) the first step fell by 1.04 ± 0.36 points and the
/// second by 0.80 ± 0.14, the worst tile stayed below 5.5%: a false failure
/// after a change of the random numbers has a probability of about 0.2%
/// (the first step's 2.9 standard deviations).
#[test]
fn sppm_bias_falls_with_the_passes_on_mitsubas_cornell_box() {
    let scene = small("cornell", 32, 32);
    let refimg = mitsuba_32();
    let reference = tile_means(&refimg, 8);
    let lum = |c: Color| raytracer::math::luminance(c) as f64;
    let lit: Vec<bool> = (0..16)
        .map(|t| {
            let (tx, ty) = (t % 4, t / 4);
            (0..64).any(|k| lum(refimg.get(tx * 8 + k % 8, ty * 8 + k / 8)) > 2.0)
        })
        .collect();
    assert_eq!(
        lit.iter().filter(|l| **l).count(),
        2,
        "the light spans two tiles"
    );
    let settings = SppmSettings {
        photons: 3_000,
        radius: Some(0.5),
        max_depth: Some(65),
        rr_depth: 5,
        ..SppmSettings::default()
    };
    let mut rms = Vec::new();
    for passes in [4, 16, 64] {
        let mut tiles = vec![Color::ZERO; 16];
        for seed in 0..8u64 {
            let img = sppm_image(&scene, &settings, passes, 100 + seed);
            for (a, t) in tiles.iter_mut().zip(tile_means(&img, 8)) {
                *a += t / 8.0;
            }
        }
        let errors: Vec<f64> = (0..16)
            .filter(|&t| !lit[t])
            .map(|t| lum(tiles[t]) / lum(reference[t]) - 1.0)
            .collect();
        let worst = errors.iter().fold(0.0f64, |m, e| m.max(e.abs()));
        let r = (errors.iter().map(|e| e * e).sum::<f64>() / errors.len() as f64).sqrt();
        eprintln!(
            "sppm {passes:2} passes: RMS {:.2}%, worst tile {:.2}%",
            100.0 * r,
            100.0 * worst
        );
        rms.push(r);
        if passes == 64 {
            assert!(
                worst < 0.09,
                "after 64 passes a tile is {:.1}% off",
                100.0 * worst
            );
        }
    }
    assert!(
        rms[0] > rms[1] && rms[1] > rms[2],
        "the bias does not fall: {rms:?}"
    );
}

fn ic(scene: &Scene, error: f32, rays: u32, max_depth: Option<u32>, seed: u64) -> IrradianceCache {
    ic_with(scene, error, rays, max_depth, seed, false)
}

fn ic_with(
    scene: &Scene,
    error: f32,
    rays: u32,
    max_depth: Option<u32>,
    seed: u64,
    gradients: bool,
) -> IrradianceCache {
    let settings = IrradianceCacheSettings {
        error,
        rays,
        max_depth,
        rr_depth: 5,
        seed: 4000 + seed,
        gradients,
    };
    IrradianceCache::build(scene, settings, &AtomicBool::new(false)).unwrap()
}

/// Irradiance caching in the closed furnace: the irradiance is the same
/// everywhere, so interpolation (at a = 0.5) adds no error and every pixel
/// is `1 − 0.5^D` within the records' own noise. (Here that noise is nil:
/// inside a sphere `cos θ_x cos θ_y / d² = 1/(4R²)` for any two points, so
/// every light sample and every cosine-sampled bounce gives the same value;
/// the t-test then demands the exact value to float precision.)
#[test]
fn irradiance_caching_gives_the_furnace_within_its_noise() {
    let scene = small("furnace", 16, 16);
    for depth in [2u32, 4] {
        let exact = 1.0 - 0.5f64.powi(depth as i32);
        assert_furnace(&format!("irradiance cache, D = {depth}"), exact, |s| {
            image(&scene, &ic(&scene, 0.5, 32, Some(depth), s), 2, s)
        });
    }
}

/// A bright closed furnace: the builtin furnace with albedo 0.98 and
/// emission 0.02, so that every pixel is `L_e/(1 − ρ) = 1` but only after
/// many bounces (0.98⁶⁴ = 0.27 of it lies beyond the 64th). Unlimited depth
/// means unlimited: roulette, not a cap, ends the paths.
fn bright_furnace(w: u32, h: u32) -> Scene {
    furnace_of_albedo(0.98, w, h)
}

/// The builtin furnace with albedo `rho` and emission `1 − rho`: every
/// pixel is 1.
fn furnace_of_albedo(rho: f32, w: u32, h: u32) -> Scene {
    let text = raytracer::scene::builtin::builtin("furnace")
        .unwrap()
        .toml
        .replace("albedo = 0.5", &format!("albedo = {rho}"))
        .replace("emission = 0.5", &format!("emission = {}", 1.0 - rho));
    assert!(text.contains(&format!("albedo = {rho}")));
    let origin = raytracer::scene::SceneOrigin::Dir {
        name: "bright-furnace".into(),
        dir: std::env::temp_dir(),
    };
    let parts = raytracer::scene::load_str(&text, &origin).unwrap();
    let mut scene = Scene::build("bright-furnace", parts);
    scene.set_resolution(w, h);
    scene
}

/// Irradiance caching with unlimited depth in the bright furnace gives 1:
/// its records' paths were cut after 64 bounces (0.74 then, 37 standard
/// errors low), which a furnace of albedo 0.5 or depth ≤ 5 cannot show.
/// Twelve runs, the t-test of [`assert_furnace`].
#[test]
fn irradiance_caching_gives_the_bright_furnace_at_unlimited_depth() {
    let scene = bright_furnace(8, 8);
    assert_furnace("irradiance cache, bright furnace, D = ∞", 1.0, |s| {
        image(&scene, &ic(&scene, 0.5, 16, None, s), 1, s)
    });
}

/// Twelve runs of `run` in a furnace whose exact value is 1:
/// [`assert_furnace`]'s t-test against 1, and the mean within 3 % of 1.
///
/// Why not the bright furnace of albedo 0.98: Russian roulette survives
/// with at most 0.95, so a path's weight grows by 0.98/0.95 per bounce and
/// the estimate's second moment sums `(0.98²/0.95)^k`, which diverges:
/// infinite variance, no fixed bound can be met by any number of runs
/// (irradiance caching's twelve runs there vary by ±10 %). At albedo 0.95
/// the ratio is 0.95: finite variance, and 3.8 % of the light still lies
/// beyond the 64th bounce (0.95⁶⁴), which a depth cap would remove.
/// Why 3 % and not the 2 % the issue names: at the settings below the
/// runs' standard error of the mean is 0.6–0.9 %, so 2 % would be 2–3 of
/// them (a false failure in about 1 run of 100); 3 % is at least 3.4 of
/// them (about 1e-3 if the tails were Gaussian; these weights' tails are
/// heavier), and still below the 3.8 % a cap at 64 bounces would lose.
fn assert_bright_furnace(what: &str, run: impl Fn(u64) -> Image) {
    let means: Vec<f64> = (0..RUNS).map(|s| mean(&run(s)).x as f64).collect();
    let (t, m) = t_stat(&means, 1.0);
    eprintln!(
        "{what}: {m:.5} vs 1 (t = {t:.2}, standard error {:.5})",
        (m - 1.0) / t
    );
    assert!(
        t.abs() < T_MAX && (m - 1.0).abs() < 0.03,
        "{what}: mean {m:.5} vs exact 1, t = {t:.1}"
    );
}

/// Photon mapping at unlimited depth in the furnace of albedo 0.95 (see
/// [`assert_bright_furnace`]): the photons' paths end by roulette alone,
/// and the density estimate of a uniform radiance has no bias (on the
/// sphere's inner wall the area within chord distance `r` is exactly
/// `π r²`), so the image is 1. Passed before this test was written: it
/// guards unlimited depth, it found no defect. Cost: about 2 s.
#[test]
fn photon_mapping_gives_the_bright_furnace_at_unlimited_depth() {
    let scene = furnace_of_albedo(0.95, 8, 8);
    let never = AtomicBool::new(false);
    assert_bright_furnace("photon, furnace of albedo 0.95, D = ∞", |s| {
        let settings = PhotonSettings {
            photons: 16_000,
            k: 30,
            max_depth: None,
            rr_depth: 5,
            seed: 7000 + s,
            ..PhotonSettings::default()
        };
        let pm = PhotonMapping::build(&scene, settings, &never).unwrap();
        image(&scene, &pm, 1, s)
    });
}

/// SPPM at unlimited depth in the furnace of albedo 0.95: 1, as photon
/// mapping. Cost: about 2 s.
#[test]
fn sppm_gives_the_bright_furnace_at_unlimited_depth() {
    let scene = furnace_of_albedo(0.95, 8, 8);
    let settings = SppmSettings {
        photons: 4000,
        max_depth: None,
        rr_depth: 5,
        ..SppmSettings::default()
    };
    assert_bright_furnace("sppm, furnace of albedo 0.95, D = ∞", |s| {
        sppm_image(&scene, &settings, 8, 5000 + s)
    });
}

/// Instant radiosity at unlimited depth in the furnace of albedo 0.95:
/// every VPL, however many bounces from the light, is gathered (on the
/// sphere `G = 1/(4r²)` everywhere: no clamping question, no splotches).
/// Cost: about 2 s.
#[test]
fn vpl_gives_the_bright_furnace_at_unlimited_depth() {
    let scene = furnace_of_albedo(0.95, 4, 4);
    assert_bright_furnace("vpl, furnace of albedo 0.95, D = ∞", |s| {
        image(&scene, &vpl(&scene, 2048, 0.0, None, s), 1, s)
    });
}

/// The path tracer's Cornell box at 32×32, D = 4, 1024 spp (seed 9): the
/// reference of the irradiance-cache tests, rendered once for all of them.
fn cornell_32_d4_reference() -> &'static Image {
    static REFERENCE: std::sync::OnceLock<Image> = std::sync::OnceLock::new();
    REFERENCE.get_or_init(|| {
        let pt = PathTracer {
            max_depth: Some(4),
            ..PathTracer::default()
        };
        image(&small("cornell", 32, 32), &pt, 1024, 9)
    })
}

/// As `a` shrinks, irradiance caching approaches the path tracer (Cornell
/// box 32×32, D = 4, both with the same light sampling for direct light):
/// the RMSE against a 1024-spp path tracer (off the light and its edge,
/// where the anti-aliasing noise of an 18.6-bright pixel would dominate,
/// and without the 1% largest pixel errors: the direct light's rare
/// fireflies on the ceiling beside the lamp, the same for every `a`, took
/// the RMSE to 0.085 for some seeds and hid the differences) falls from
/// a = 1 to 0.4 to 0.1 (more records, less interpolation), and the record
/// count grows. With 256 rays per record the records' noise is below the
/// interpolation error at these thresholds. Measured (fixed seeds): 88,
/// 252, 793 records and RMSE 0.0131, 0.0075, 0.0063; over 15 other seed
/// pairs the last step fell by 0.00144 ± 0.00027, 5 standard deviations
/// (a false failure under other random numbers: below 1e-6).
#[test]
fn irradiance_caching_approaches_the_path_tracer_as_a_shrinks() {
    let scene = small("cornell", 32, 32);
    let depth = Some(4);
    let reference = cornell_32_d4_reference();
    let mut last = (f32::MAX, 0usize);
    for a in [1.0f32, 0.4, 0.1] {
        let cache = ic(&scene, a, 256, depth, 1);
        let img = image(&scene, &cache, 16, 2);
        let e = trimmed_rmse_off_the_light(&img, reference);
        eprintln!(
            "irradiance cache a = {a}: {} records, RMSE {e:.4}",
            cache.records().len()
        );
        assert!(e < last.0, "a = {a}: RMSE {e} not below {}", last.0);
        assert!(
            cache.records().len() > last.1,
            "a = {a}: records do not grow"
        );
        last = (e, cache.records().len());
    }
}

/// Irradiance gradients in the closed furnace: every ray brings back the
/// same radiance, so every difference `L_jk − L_j'k'` of the translational
/// gradient is zero, and the rotational gradient's `Σ_k v(φ_k)` over
/// sectors evenly spread around the normal is zero too. The records'
/// gradients must be nil to float precision (each `|∇_r E_i|` and
/// `R_i |∇_t E_i|` below 1e-4 `E_i`; measured below 1e-6), and the image
/// `1 − 0.5^D` as without gradients (the t-test of the furnace checks
/// above).
#[test]
fn irradiance_gradients_vanish_in_the_furnace() {
    let scene = small("furnace", 16, 16);
    let worst = std::cell::Cell::new(0.0f32);
    for depth in [2u32, 4] {
        let exact = 1.0 - 0.5f64.powi(depth as i32);
        assert_furnace(
            &format!("irradiance cache with gradients, D = {depth}"),
            exact,
            |s| {
                let cache = ic_with(&scene, 0.5, 32, Some(depth), s, true);
                assert_eq!(cache.gradients().len(), cache.records().len());
                for (r, g) in cache.records().iter().zip(cache.gradients()) {
                    for c in 0..3 {
                        let sizes = [g.rotation[c].length(), g.translation[c].length() * r.r];
                        if r.e[c] > 0.0 {
                            worst.set(worst.get().max(sizes[0].max(sizes[1]) / r.e[c]));
                        }
                        assert!(
                            sizes.iter().all(|&x| x <= 1e-4 * r.e[c]),
                            "a record's gradients {g:?} at E {}",
                            r.e
                        );
                    }
                }
                image(&scene, &cache, 2, s)
            },
        );
    }
    eprintln!("furnace: largest |gradient| / E {:.2e}", worst.get());
}

/// Gradients make interpolation more accurate at the same `a`: on the
/// Cornell box (as in the test above: 32×32, D = 4, the RMSE against a
/// 1024-spp path tracer off the light, 16 spp) with 256 rays per record
/// without gradients and 9 × 28 = 252 stratified ones with, for 4 record
/// and render seeds. The mean RMSE with gradients must be below 0.85 of
/// the mean without at a = 1 and below 0.95 of it at a = 0.6 and 0.4, and
/// every single run with gradients below its run without. Measured (fixed
/// seeds): mean RMSE 0.0150 → 0.0113 (ratio 0.76) at a = 1, 0.0098 →
/// 0.0084 (0.85) at a = 0.6, 0.0092 → 0.0081 (0.88) at a = 0.4; single runs'
/// ratios 0.71–0.90. The gain shrinks with `a` because the error left at
/// small `a` (0.0073 at a = 0.1 by this untrimmed RMSE) is not interpolation's, and gradients do
/// not remove it. The single runs' ratios spread by 0.06 (a = 1)
/// to 0.02 (a = 0.4) from seed to seed (5 seeds measured), so each margin
/// is at least 3 standard deviations of a 4-seed mean away (a false
/// failure under other random numbers: about 1e-3).
#[test]
fn irradiance_gradients_lower_the_error_at_equal_a() {
    let scene = small("cornell", 32, 32);
    let depth = Some(4);
    let reference = cornell_32_d4_reference();
    for (a, margin) in [(1.0f32, 0.85), (0.6, 0.95), (0.4, 0.95)] {
        let (mut sum_without, mut sum_with) = (0.0, 0.0);
        for seed in [11u64, 21, 31, 41] {
            let rmse = |gradients: bool| {
                let cache = ic_with(&scene, a, 256, depth, seed, gradients);
                rmse_off_the_light(&image(&scene, &cache, 16, seed + 1), reference)
            };
            let (without, with) = (rmse(false), rmse(true));
            eprintln!(
                "irradiance cache a = {a}, seed {seed}: RMSE {without:.4} without gradients, {with:.4} with"
            );
            assert!(
                with < without,
                "a = {a}, seed {seed}: RMSE with gradients {with:.4}, without {without:.4}"
            );
            sum_without += without;
            sum_with += with;
        }
        let ratio = sum_with / sum_without;
        eprintln!("irradiance cache a = {a}: mean RMSE with / without gradients {ratio:.3}");
        assert!(
            ratio < margin,
            "a = {a}: mean RMSE with gradients {:.4} is {ratio:.2} of without ({:.4}), not below {margin}",
            sum_with / 4.0,
            sum_without / 4.0
        );
    }
}

/// The gradients are made in the records' own parallel build: the same bits
/// on 1 and 3 threads.
#[test]
fn irradiance_gradients_do_not_depend_on_the_threads() {
    let scene = small("cornell", 24, 24);
    let build = |n: usize| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .unwrap()
            .install(|| ic_with(&scene, 0.5, 32, Some(4), 1, true))
    };
    let (c1, c3) = (build(1), build(3));
    assert_eq!(c1.records(), c3.records());
    assert_eq!(c1.gradients(), c3.gradients());
    assert!(
        c1.gradients()
            .iter()
            .any(|g| g.translation[0].length() > 0.0)
    );
}

/// [`rmse_off_the_light`] without the 1% largest pixel errors.
fn trimmed_rmse_off_the_light(img: &Image, reference: &Image) -> f32 {
    let mut errors: Vec<f64> = img
        .pixels
        .iter()
        .zip(&reference.pixels)
        .filter(|(_, b)| raytracer::math::luminance(**b) < 1.0)
        .map(|(a, b)| (*a - *b).length_squared() as f64 / 3.0)
        .collect();
    errors.sort_by(f64::total_cmp);
    let kept = &errors[..errors.len() - errors.len() / 100];
    (kept.iter().sum::<f64>() / kept.len().max(1) as f64).sqrt() as f32
}

/// The RMSE over the pixels whose reference luminance is below 1 (not the
/// light, nor pixels that partly see it).
fn rmse_off_the_light(img: &Image, reference: &Image) -> f32 {
    let (mut sum, mut n) = (0.0f64, 0usize);
    for (a, b) in img.pixels.iter().zip(&reference.pixels) {
        if raytracer::math::luminance(*b) < 1.0 {
            sum += (*a - *b).length_squared() as f64 / 3.0;
            n += 1;
        }
    }
    (sum / n.max(1) as f64).sqrt() as f32
}

/// Photon mapping finds the caustic under the glass ball, as light tracing
/// does and a path tracer cannot (its paths would have to hit the point
/// light after refracting): in the brightest 4×4 block of floor pixels of
/// the photon-mapping image (64×48, 100 000 photon paths, k = 50), photon
/// mapping is more than 1.5 times brighter than the path tracer (measured
/// 0.79 vs 0.22: 3.6×; a photon map without the caustic would be about as
/// dark as the path tracer), and holds more than 30% of what light tracing
/// finds in the same block (measured 0.79 of 1.30: photon mapping blurs the
/// spot over its search disk, the lecture's bias at a caustic's edge). The
/// seeds are fixed; under 11 other sets of seeds the two ratios ranged over
/// 3.3–13.7 and 0.52–1.54, their logarithms 2.9 standard deviations above
/// the thresholds' (a false failure under other random numbers: about 0.2%
/// each).
#[test]
fn photon_mapping_finds_the_caustic() {
    use raytracer::integrator::LightTracer;
    let scene = small("caustic", 64, 48);
    let depth = Some(6);
    let pm = PhotonMapping::build(
        &scene,
        PhotonSettings {
            photons: 100_000,
            max_depth: depth,
            seed: 3,
            ..PhotonSettings::default()
        },
        &AtomicBool::new(false),
    )
    .unwrap();
    let pt = PathTracer {
        max_depth: depth,
        ..PathTracer::default()
    };
    let lt = LightTracer {
        max_depth: depth,
        rr_depth: 5,
    };
    let (i_pm, i_pt, i_lt) = (
        image(&scene, &pm, 4, 1),
        image(&scene, &pt, 16, 2),
        image(&scene, &lt, 64, 3),
    );
    let floor = |x: u32, y: u32| {
        let ray = scene.camera.generate_ray(
            raytracer::math::Vec2::new(x as f32 + 0.5, y as f32 + 0.5),
            Default::default(),
        );
        scene
            .intersect(&ray)
            .is_some_and(|it| scene.objects[it.shape as usize].name == "floor")
    };
    let block = |img: &Image, bx: u32, by: u32| -> f64 {
        let mut sum = 0.0;
        for y in by..by + 4 {
            for x in bx..bx + 4 {
                sum += raytracer::math::luminance(img.get(x, y)) as f64;
            }
        }
        sum / 16.0
    };
    let mut best = (0.0, 0, 0);
    for by in 0..48 - 3 {
        for bx in 0..64 - 3 {
            if (by..by + 4).all(|y| (bx..bx + 4).all(|x| floor(x, y))) {
                let v = block(&i_pm, bx, by);
                if v > best.0 {
                    best = (v, bx, by);
                }
            }
        }
    }
    let (v_pm, bx, by) = best;
    let (v_pt, v_lt) = (block(&i_pt, bx, by), block(&i_lt, bx, by));
    eprintln!("caustic block ({bx}, {by}): photon {v_pm:.3}, path {v_pt:.3}, light {v_lt:.3}");
    assert!(v_pm > 1.5 * v_pt, "photon {v_pm} vs path {v_pt}");
    assert!(v_pm > 0.3 * v_lt, "photon {v_pm} vs light {v_lt}");
}

/// Instant radiosity and irradiance caching give the same image bit for bit
/// whatever the number of threads: their VPLs and cache records are built
/// on rayon's pool (here of 1 and of 3 threads) and the images rendered with
/// 1 and 3 threads. A build whose result depended on the order threads finish
/// in (a shared vector filled as batches end, records inserted as found)
/// would change the image.
#[test]
fn vpl_and_irradiance_cache_do_not_depend_on_the_threads() {
    let scene = small("cornell", 24, 24);
    let pool = |n: usize| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .unwrap()
    };
    let render_with = |integrator: &dyn Integrator, threads: usize| -> Vec<u32> {
        let options = RenderOptions {
            threads: Some(threads),
            ..options(4, 5)
        };
        render(&scene, integrator, &options).film.image().bits()
    };
    let (v1, v3) = (
        pool(1).install(|| vpl(&scene, 2000, 0.0, Some(4), 1)),
        pool(3).install(|| vpl(&scene, 2000, 0.0, Some(4), 1)),
    );
    assert_eq!(v1.vpls().len(), v3.vpls().len());
    assert_eq!(
        render_with(&v1, 1),
        render_with(&v3, 3),
        "instant radiosity"
    );
    let (c1, c3) = (
        pool(1).install(|| ic(&scene, 0.5, 32, Some(4), 1)),
        pool(3).install(|| ic(&scene, 0.5, 32, Some(4), 1)),
    );
    assert_eq!(c1.records().len(), c3.records().len());
    assert_eq!(render_with(&c1, 1), render_with(&c3, 3), "irradiance cache");
}
