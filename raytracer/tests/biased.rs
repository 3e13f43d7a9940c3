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
use raytracer::integrator::{Integrator, PhotonMapping, PhotonSettings};
use raytracer::metrics::mean;
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
