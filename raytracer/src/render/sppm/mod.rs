//! The pass loop of stochastic progressive photon mapping.
//!
//! Lecture topic: "Algorithms for Global Illumination" — SPPM, the
//! consistent form of photon mapping (what one pixel and one pass compute
//! is [`estimator`], beside this file: the algorithm's one home). It does not fit the loop over independent
//! pixel samples of [`super::render`]: each pass needs every pixel's visible
//! point before its photons can be gathered, and every pixel keeps state
//! (radius, count, flux) from pass to pass. So it has a loop of its own:
//!
//! ```text
//!   for pass i in 0..P:
//!       visible points of every pixel          (parallel over pixels)
//!       N_p photon paths, in a photon map      (parallel over batches)
//!       each pixel gathers and updates r, N, τ (parallel over pixels)
//! ```
//!
//! **Determinism.** Pixel `j` of pass `i` draws from `Sampler::new(seed, j,
//! i)`, the photons of a pass come in batch order, and each pixel sums its
//! photons in the map's fixed order: the image is the same bit for bit on
//! any number of threads.
//!
//! **Interruption.** The stop flag (Ctrl-C) is checked between the steps of
//! a pass, by every pixel of the camera pass and by the photon tracing; a
//! pass cut short is dropped whole, so the image is that of the finished
//! passes (`passes` says how many).
//!
//! **Watching.** [`render_sppm_watched`] shows a watcher every finished
//! pass (a progressive front-end's snapshots): after pass `k` the image is,
//! bit for bit, the image of a render of `k` passes with the same seed.
//!
//! **Memory.** Per pixel its state and one visible point; per pass one
//! photon map, freed before the next: bounded by the photons of one pass.
//! `peak_bytes` reports what the largest pass held.

use std::io::IsTerminal;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rayon::prelude::*;

use super::{INTERRUPTED, RenderOptions, RenderStats, thread_limit};
use crate::film::Image;
use crate::integrator::visible_point::GatherPoint;
use estimator::{PixelState, camera_pass, gather, photon_pass};

pub mod estimator;
use crate::math::{Color, UVec2};
use crate::scene::Scene;
pub use estimator::SppmSettings;

/// A finished (or interrupted) SPPM render.
#[derive(Clone, Debug)]
pub struct SppmResult {
    pub image: Image,
    /// `samples` counts one per pixel and finished pass.
    pub stats: RenderStats,
    /// Passes finished (the image's `P`).
    pub passes: u32,
    pub initial_radius: f32,
    /// The mean radius over the pixels at the end.
    pub final_radius: f32,
    /// The most bytes one pass held: pixel states, visible points, photons.
    pub peak_bytes: usize,
    /// Photons stored in the largest pass.
    pub peak_photons: usize,
}

/// Renders `scene` with SPPM: `options.spp` passes of `settings.photons`
/// photon paths each. Stops early on Ctrl-C once the interrupt handler is
/// installed (see [`super::install_interrupt_handler`]).
pub fn render_sppm(scene: &Scene, settings: &SppmSettings, options: &RenderOptions) -> SppmResult {
    render_sppm_with_stop(scene, settings, options, &INTERRUPTED)
}

/// [`render_sppm`] watching its own stop flag.
pub fn render_sppm_with_stop(
    scene: &Scene,
    settings: &SppmSettings,
    options: &RenderOptions,
    stop: &AtomicBool,
) -> SppmResult {
    render_sppm_watched(scene, settings, options, stop, &mut |_| {})
}

/// How far an SPPM render has come, as [`render_sppm_watched`] shows it
/// after each finished pass.
pub struct SppmProgress<'a> {
    states: &'a [PixelState],
    width: u32,
    height: u32,
    photons: u64,
    /// Passes finished so far.
    pub passes: u32,
    /// Wall-clock time since the render started.
    pub elapsed: Duration,
}

impl SppmProgress<'_> {
    /// The image of the passes finished so far: bit for bit the image of a
    /// render of [`Self::passes`] passes with the same settings and seed
    /// (computed on demand, one radiance per pixel).
    pub fn image(&self) -> Image {
        let w = self.width;
        Image::from_fn(w, self.height, |x, y| {
            self.states[(y * w + x) as usize].radiance(self.passes, self.photons)
        })
    }
}

/// [`render_sppm_with_stop`] that shows `watch` the render after every
/// finished pass. `watch` runs between passes, while no thread works: it
/// should be quick (take the image, not encode it).
pub fn render_sppm_watched(
    scene: &Scene,
    settings: &SppmSettings,
    options: &RenderOptions,
    stop: &AtomicBool,
    watch: &mut (dyn FnMut(&SppmProgress) + Send),
) -> SppmResult {
    let mut run = || passes(scene, settings, options, stop, watch);
    match options.threads.map(|n| n.clamp(1, thread_limit())) {
        None => run(),
        Some(n) => match rayon::ThreadPoolBuilder::new().num_threads(n).build() {
            Ok(pool) => pool.install(run),
            Err(e) => {
                eprintln!("warning: cannot start {n} render threads ({e}); using the global pool");
                run()
            }
        },
    }
}

fn passes(
    scene: &Scene,
    settings: &SppmSettings,
    options: &RenderOptions,
    stop: &AtomicBool,
    watch: &mut (dyn FnMut(&SppmProgress) + Send),
) -> SppmResult {
    let start = Instant::now();
    let (w, h) = (scene.camera.width, scene.camera.height);
    let pixels = w as usize * h as usize;
    let r0 = settings.initial_radius(scene);
    let mut states = vec![PixelState::new(r0); pixels];
    let bar = progress_bar(options);
    let (mut done, mut peak_bytes, mut peak_photons) = (0u32, 0usize, 0usize);
    let stopped = || stop.load(Ordering::Relaxed);
    for pass in 0..options.spp {
        if stopped() {
            break;
        }
        let points: Vec<(Color, Option<GatherPoint>)> = (0..pixels)
            .into_par_iter()
            .map(|j| {
                if stopped() {
                    // The pass is dropped below.
                    return (Color::ZERO, None);
                }
                let pixel = UVec2::new(j as u32 % w.max(1), j as u32 / w.max(1));
                camera_pass(scene, settings, options.seed, pixel, j as u64, pass)
            })
            .collect();
        if stopped() {
            break;
        }
        let max_r = states.iter().fold(0.0f32, |m, s| m.max(s.r));
        let (map, paths) = photon_pass(scene, settings, options.seed, pass, max_r, stop);
        if paths == 0 || stopped() {
            break;
        }
        states
            .par_iter_mut()
            .zip(points.par_iter())
            .for_each(|(s, (direct, point))| {
                s.direct += *direct;
                if let Some(p) = point {
                    let (m, phi) = gather(scene, settings, &map, p, s.r);
                    s.update(m, phi, settings.alpha);
                }
            });
        let bytes = map.bytes()
            + pixels
                * (std::mem::size_of::<PixelState>()
                    + std::mem::size_of::<(Color, Option<GatherPoint>)>());
        peak_bytes = peak_bytes.max(bytes);
        peak_photons = peak_photons.max(map.len());
        done += 1;
        bar.inc(1);
        watch(&SppmProgress {
            states: &states,
            width: w,
            height: h,
            photons: settings.photons,
            passes: done,
            elapsed: start.elapsed(),
        });
    }
    bar.finish_and_clear();
    let image = Image::from_fn(w, h, |x, y| {
        states[(y * w + x) as usize].radiance(done, settings.photons)
    });
    let final_radius = states.iter().map(|s| s.r as f64).sum::<f64>() / pixels.max(1) as f64;
    let stats = RenderStats {
        elapsed: start.elapsed(),
        samples: pixels as u64 * done as u64,
        interrupted: done < options.spp,
        nonfinite: 0,
    };
    if options.progress {
        eprintln!(
            "{}: {w}×{h}, {done} of {} SPPM passes of {} photon paths in {:.2} s ({:.3} s/pass), \
             radius {r0:.4} → {final_radius:.4}, peak {:.1} MiB ({peak_photons} photons × 40 bytes + grid and pixels){}",
            options.label,
            options.spp,
            settings.photons,
            stats.elapsed.as_secs_f64(),
            stats.elapsed.as_secs_f64() / done.max(1) as f64,
            peak_bytes as f64 / (1 << 20) as f64,
            if stats.interrupted {
                ", INTERRUPTED"
            } else {
                ""
            }
        );
    }
    SppmResult {
        image,
        stats,
        passes: done,
        initial_radius: r0,
        final_radius: final_radius as f32,
        peak_bytes,
        peak_photons,
    }
}

/// A progress bar counting passes; hidden unless requested and stderr is a
/// terminal.
fn progress_bar(options: &RenderOptions) -> ProgressBar {
    if !options.progress || !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let style =
        ProgressStyle::with_template("{prefix} {wide_bar} {pos}/{len} SPPM passes, ETA {eta}")
            .unwrap_or_else(|_| ProgressStyle::default_bar());
    ProgressBar::with_draw_target(Some(options.spp as u64), ProgressDrawTarget::stderr())
        .with_style(style)
        .with_prefix(options.label.clone())
}
