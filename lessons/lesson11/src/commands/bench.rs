//! `lesson11 bench`: the figures behind every speed claim of the README.
//!
//! Ctrl-C stops it within moments, in every part: a figure cut short is not
//! printed (it would measure the stop, not the renderer), and the command
//! ends with an error saying that the figures above are all it measured.

pub mod biased;
pub mod interrupted;
pub mod mitsuba;
pub mod rays;

use std::path::PathBuf;

use anyhow::{Result, bail};
use clap::Args;
use raytracer::integrator::{Bdpt, Direct, DirectStrategy, Integrator, LightTracer, PathTracer};
use raytracer::render::{Metropolis, RenderOptions, render, render_metropolis};
use raytracer::scene::Scene;
use raytracer::wavefront::WavefrontPathTracer;

use interrupted::stop_if_interrupted;

/// Measure primary-ray throughput on large meshes, direct-lighting and path
/// tracing samples per second on the Cornell box (256×256) with the ratio to
/// Mitsuba 3 when one is installed, and the unbiased integrators' samples
/// (Metropolis: mutations) per second on the door scene. Run it with
/// --release.
#[derive(Args, Debug)]
pub struct BenchArgs {
    /// Thread counts to measure (comma separated; default: 1 and all cores).
    #[arg(long, value_delimiter = ',')]
    pub threads: Vec<usize>,
    /// Samples per pixel of the Cornell box measurement.
    #[arg(long, default_value_t = 64)]
    pub spp: u32,
    /// Skip the ray-throughput part.
    #[arg(long)]
    pub no_rays: bool,
    /// Skip the biased integrators' part (photons, photon map, SPPM, VPL).
    #[arg(long)]
    pub no_biased: bool,
    /// Seconds per algorithm in the equal-time comparison (0 skips it).
    #[arg(long, default_value_t = 2.0)]
    pub equal_time: f64,
    /// A Python with Mitsuba 3 installed, to print the ratio of our path
    /// tracer to Mitsuba's on the Cornell box (default: the environment
    /// variable LESSON11_MITSUBA_PYTHON, else `python3` if it has Mitsuba).
    #[arg(long, value_name = "PYTHON")]
    pub mitsuba: Option<PathBuf>,
}

/// Checks the options before any measurement starts.
fn check(args: &BenchArgs) -> Result<()> {
    if args.spp == 0 {
        bail!("--spp must be at least 1");
    }
    for &n in &args.threads {
        crate::options::check_threads(Some(n))?;
    }
    if !(args.equal_time.is_finite() && args.equal_time >= 0.0) {
        bail!(
            "--equal-time must be a number of seconds ≥ 0 (0 skips the comparison), got {}",
            args.equal_time
        );
    }
    Ok(())
}

pub fn run(args: &BenchArgs) -> Result<()> {
    check(args)?;
    if cfg!(debug_assertions) {
        crate::console::say!(
            "note: this is not a --release build; figures will be lower than the README's"
        );
    }
    let all = std::thread::available_parallelism().map_or(1, |n| n.get());
    let threads = if args.threads.is_empty() {
        let mut t = vec![1, all];
        t.dedup();
        t
    } else {
        args.threads.clone()
    };
    if !args.no_rays {
        rays::run(&threads)?;
    }
    let scene = Scene::builtin("cornell")?;
    let direct = Direct;
    let path = PathTracer {
        max_depth: Some(65),
        rr_depth: 5,
        strategy: DirectStrategy::Mis,
    };
    let cases: [(&str, &dyn Integrator); 2] = [
        ("direct lighting (light + BRDF sampling, MIS)", &direct),
        (
            "path tracing, max depth 65, roulette from depth 5 (Mitsuba's settings)",
            &path,
        ),
    ];
    for (k, (what, integrator)) in cases.into_iter().enumerate() {
        crate::console::say!("\n`cornell` 256×256, {} spp: {what}", args.spp);
        crate::console::say!("  {:>8} {:>10} {:>14}", "threads", "seconds", "M samples/s");
        let mut last = 0.0;
        for &n in &threads {
            let options = RenderOptions {
                spp: args.spp,
                seed: 1,
                threads: Some(n),
                progress: false,
                ..RenderOptions::default()
            };
            let result = render(&scene, integrator, &options);
            stop_if_interrupted(result.stats.interrupted)?;
            crate::console::say!(
                "  {:>8} {:>10.3} {:>14.3}",
                n,
                result.stats.elapsed.as_secs_f64(),
                result.stats.samples_per_second() / 1e6
            );
            last = result.stats.samples_per_second();
        }
        // The path tracer (the second case) on the wavefront engine, then
        // both against their peer.
        if k == 1 {
            let n = *threads.last().expect("at least one thread count");
            let wavefront = wavefront_rows(&scene, &path, args.spp, &threads)?;
            stop_if_interrupted(false)?;
            let ours = [("path", last), ("path on the wavefront engine", wavefront)];
            let line = mitsuba::compare(args.mitsuba.as_ref(), args.spp, &ours, n);
            stop_if_interrupted(line.is_none())?;
            crate::console::say!("{}", line.unwrap_or_default());
        }
    }
    door(16, &threads)?;
    if !args.no_biased {
        biased::run(&threads)?;
    }
    if args.equal_time > 0.0 {
        crate::console::say!(
            "\nEqual time ({} s each, 128 pixels wide): RMSE against an independent reference \
             (Mitsuba's Cornell box at max depth 65, the stored door at max depth 5 and caustic at \
             max depth 8, else our bidirectional path tracer with another seed at 512 spp and max \
             depth 5)",
            args.equal_time
        );
        for name in ["cornell", "door", "caustic"] {
            let mut scene = Scene::builtin(name)?;
            let (w, h) = (scene.settings.width, scene.settings.height);
            scene.set_resolution(128, (h * 128 / w).max(1));
            let base = RenderOptions {
                seed: 7,
                progress: false,
                ..RenderOptions::default()
            };
            let (reference, max_depth) =
                crate::reference::independent(Some(name), &scene, &base, 5, 512);
            stop_if_interrupted(false)?;
            // The floor over the pixels equal_time's RMSE counts: off the lights.
            let floor = crate::equal_time::masked_noise_floor(
                &reference,
                &crate::equal_time::off_the_light(&reference.mean),
            );
            crate::console::say!(
                "  {name}: max depth {max_depth}, reference {} (noise floor {floor:.5})",
                reference.source
            );
            crate::equal_time::equal_time(
                &scene,
                &base,
                args.equal_time,
                &reference,
                max_depth,
                crate::equal_time::Also {
                    naive: name == "cornell",
                    metropolis: name == "door",
                },
            );
            stop_if_interrupted(false)?;
        }
    }
    Ok(())
}

/// The same path tracing figure on the wavefront engine (the same image bit
/// for bit, see `raytracer::wavefront`): one row per thread count; returns
/// the last rate.
fn wavefront_rows(scene: &Scene, path: &PathTracer, spp: u32, threads: &[usize]) -> Result<f64> {
    let engine = WavefrontPathTracer::from_path(path)?;
    crate::console::say!("  the same on the wavefront engine (a tile's paths in lockstep):");
    let (mut last, mut profile) = (0.0, None);
    let streamed = WavefrontPathTracer {
        streams: true,
        ..engine
    };
    for (n, engine) in threads
        .iter()
        .map(|&n| (n, &engine))
        .chain(threads.last().map(|&n| (n, &streamed)))
    {
        let options = RenderOptions {
            spp,
            seed: 1,
            threads: Some(n),
            progress: false,
            ..RenderOptions::default()
        };
        let (result, times) = engine.render_profiled(scene, &options);
        crate::console::say!(
            "  {:>8} {:>10.3} {:>14.3}{}",
            n,
            result.stats.elapsed.as_secs_f64(),
            result.stats.samples_per_second() / 1e6,
            if engine.streams {
                "  (rays traced as streams)"
            } else {
                ""
            }
        );
        if engine.streams {
            break;
        }
        last = result.stats.samples_per_second();
        profile = Some((times, result.stats.samples.max(1)));
    }
    if let Some((t, samples)) = profile {
        let share = |d: std::time::Duration| 100.0 * d.as_secs_f64() / t.total().as_secs_f64();
        crate::console::say!(
            "  where its time goes: closest hits {:.0}%, shading {:.0}%, shadow rays {:.0}%, \
             camera and film {:.0}%, compaction {:.0}%; per sample {:.2} rays and {:.2} shadow rays",
            share(t.closest_hits),
            share(t.shade),
            share(t.shadow_rays),
            share(t.camera_and_film),
            share(t.compact),
            t.rays as f64 / samples as f64,
            t.shadow_ray_count as f64 / samples as f64
        );
    }
    Ok(last)
}

/// Samples per second of path, light and bidirectional tracing on `door`
/// (128×96, max depth 5) beside Metropolis light transport's mutations per
/// second over bidirectional tracing: one mutation is one BDPT sample plus
/// the chain's bookkeeping. Its rate counts the chains' time only; the
/// bootstrap (one BDPT path per pixel) is printed apart.
fn door(spp: u32, threads: &[usize]) -> Result<()> {
    let mut scene = Scene::builtin("door")?;
    let (w, h) = (scene.settings.width, scene.settings.height);
    scene.set_resolution(128, (h * 128 / w).max(1));
    let max_depth = Some(5);
    let path = PathTracer {
        max_depth,
        ..PathTracer::default()
    };
    let light = LightTracer {
        max_depth,
        ..LightTracer::default()
    };
    let bdpt = Bdpt {
        max_depth,
        ..Bdpt::default()
    };
    crate::console::say!(
        "\n`door` {}×{}, max depth 5, {spp} samples (Metropolis: mutations) per pixel",
        scene.camera.width,
        scene.camera.height
    );
    crate::console::say!(
        "  {:>8} {:<34} {:>10} {:>14}",
        "threads",
        "algorithm",
        "seconds",
        "k samples/s"
    );
    for &n in threads {
        let options = RenderOptions {
            spp,
            seed: 1,
            threads: Some(n),
            progress: false,
            ..RenderOptions::default()
        };
        let cases: [(&str, &dyn Integrator); 3] = [
            ("path tracing (MIS)", &path),
            ("light tracing", &light),
            ("bidirectional path tracing", &bdpt),
        ];
        for (what, integrator) in cases {
            let stats = render(&scene, integrator, &options).stats;
            stop_if_interrupted(stats.interrupted)?;
            crate::console::say!(
                "  {:>8} {what:<34} {:>10.3} {:>14.1}",
                n,
                stats.elapsed.as_secs_f64(),
                stats.samples_per_second() / 1e3
            );
        }
        let r = render_metropolis(&scene, &bdpt, &options, &Metropolis::default());
        stop_if_interrupted(r.stats.interrupted)?;
        let chains = r.stats.elapsed.as_secs_f64() - r.bootstrap_seconds;
        crate::console::say!(
            "  {:>8} {:<34} {:>10.3} {:>14.1}   mutations/s; + {:.3} s bootstrap, acceptance {:.0} %",
            n,
            "Metropolis over bidirectional",
            chains,
            r.stats.samples as f64 / chains.max(1e-9) / 1e3,
            r.bootstrap_seconds,
            100.0 * r.acceptance_rate
        );
    }
    Ok(())
}
