//! The biased integrators' figures for `lesson11 bench`: photons traced and
//! stored per second, the photon-map build of 1 M photons (target: under a
//! second on two cores), SPPM seconds per pass on `cornell` 256², and VPL
//! gathers per second — beside the path tracer's samples per second, each on
//! the same thread counts. Ctrl-C stops each part (photon tracing, SPPM,
//! VPLs, renders) within moments; the row it cut short is not printed.

use std::time::Instant;

use anyhow::Result;
use raytracer::integrator::photon::{Photon, PhotonTracing, trace_photons};
use raytracer::integrator::photon_map::{PhotonMap, radius_for};
use raytracer::integrator::{InstantRadiosity, PathTracer, VplSettings};
use raytracer::render::sppm::SppmSettings;
use raytracer::render::sppm::render_sppm_with_stop;
use raytracer::render::{RenderOptions, interrupt_flag, render};
use raytracer::scene::Scene;

use super::interrupted::stop_if_interrupted;

/// Light paths traced for the photon figures.
const PHOTON_PATHS: u64 = 400_000;
/// Photons in the timed map build.
const MAP_PHOTONS: usize = 1_000_000;
/// SPPM passes timed (after the first, which is timed too: all are alike).
const SPPM_PASSES: u32 = 4;
/// VPL light paths (each leaves a VPL at every diffuse vertex).
const VPL_PATHS: u64 = 64;

/// Prints the figures, each on `threads` threads.
pub fn run(threads: &[usize]) -> Result<()> {
    let scene = Scene::builtin("cornell")?;
    let stop = interrupt_flag();
    let sppm_settings = SppmSettings {
        max_depth: Some(65),
        rr_depth: 5,
        ..SppmSettings::default()
    };
    crate::console::say!(
        "\nBiased integrators on `cornell` (256×256, max depth 65, roulette from depth 5), \
         beside the path tracer:"
    );
    crate::console::say!(
        "  {:>8} {:>12} {:>14} {:>12} {:>12} {:>13} {:>14}",
        "threads",
        "k paths/s",
        "M photons/s",
        "map 1M (s)",
        "SPPM s/pass",
        "M gathers/s",
        "M path spp/s"
    );
    for &n in threads {
        let pool = rayon::ThreadPoolBuilder::new().num_threads(n).build()?;
        let tracing = PhotonTracing {
            paths: PHOTON_PATHS,
            max_depth: Some(65),
            rr_depth: 5,
            seed: 1,
            stream: 0,
        };
        let (secs, stored) = pool.install(|| {
            let t = Instant::now();
            let traced = trace_photons(&scene, &tracing, stop);
            let secs = t.elapsed().as_secs_f64();
            let mut all: Vec<Photon> = traced.direct;
            all.extend(traced.caustic);
            all.extend(traced.indirect);
            (secs, all)
        });
        stop_if_interrupted(false)?;
        let photons_per_s = stored.len() as f64 / secs;
        let paths_per_s = PHOTON_PATHS as f64 / secs;
        // 1 M photons: the stored ones, repeated as needed; the cell size of
        // a k = 50 search over as many photons, as photon mapping builds it.
        let million: Vec<Photon> = stored.iter().cycle().take(MAP_PHOTONS).copied().collect();
        let cell = radius_for(&million, 50, 2.0);
        let build = pool.install(|| {
            let t = Instant::now();
            let map = PhotonMap::build(million, cell);
            let secs = t.elapsed().as_secs_f64();
            assert_eq!(map.len(), MAP_PHOTONS);
            secs
        });
        let options = |spp| RenderOptions {
            spp,
            seed: 1,
            threads: Some(n),
            progress: false,
            ..RenderOptions::default()
        };
        let sppm = render_sppm_with_stop(&scene, &sppm_settings, &options(SPPM_PASSES), stop);
        stop_if_interrupted(sppm.stats.interrupted)?;
        let per_pass = sppm.stats.elapsed.as_secs_f64() / sppm.passes.max(1) as f64;
        let vpl = pool.install(|| {
            InstantRadiosity::build(
                &scene,
                VplSettings {
                    paths: VPL_PATHS,
                    max_depth: Some(65),
                    rr_depth: 5,
                    ..VplSettings::default()
                },
                stop,
            )
        });
        let vpl = vpl.map_err(anyhow::Error::msg)?;
        stop_if_interrupted(vpl.interrupted)?;
        let r = render(&scene, &vpl, &options(1));
        stop_if_interrupted(r.stats.interrupted)?;
        let gathers =
            r.stats.samples as f64 * vpl.vpls().len() as f64 / r.stats.elapsed.as_secs_f64();
        let path = render(
            &scene,
            &PathTracer {
                max_depth: Some(65),
                rr_depth: 5,
                ..PathTracer::default()
            },
            &options(16),
        );
        stop_if_interrupted(path.stats.interrupted)?;
        crate::console::say!(
            "  {:>8} {:>12.1} {:>14.3} {:>12.3} {:>12.3} {:>13.3} {:>14.3}",
            n,
            paths_per_s / 1e3,
            photons_per_s / 1e6,
            build,
            per_pass,
            gathers / 1e6,
            path.stats.samples_per_second() / 1e6
        );
    }
    crate::console::say!(
        "  (photons: {PHOTON_PATHS} light paths traced, every photon stored at a diffuse hit \
         counted; map: a uniform grid over {MAP_PHOTONS} photons, target under 1 s on 2 cores; \
         SPPM: {} photon paths per pass, camera pass included, {SPPM_PASSES} passes; gathers: \
         connections of a camera hit to one of the VPLs of {VPL_PATHS} light paths, with its \
         shadow ray; path: 16 spp)",
        sppm_settings.photons
    );
    Ok(())
}
