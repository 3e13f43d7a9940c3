//! The wavefront path tracer: the lecture's path tracer run as a second
//! engine, all of a unit's paths in lockstep, one stage at a time.
//!
//! Lecture topic: path tracing (the estimator is [`PathTracer`]'s, with MIS
//! by the power heuristic and Russian roulette); this module is about how
//! production renderers and GPUs run it fast (pbrt-v4's wavefront
//! integrator, Laine et al., "Megakernels Considered Harmful", 2013).
//!
//! # One path at a time, or all of them a step at a time
//!
//! `path` follows one path from the camera to its end: trace, shade, sample
//! a light, trace its shadow ray, sample the BRDF, trace again. Every step
//! waits on the one before, and each touches different data (BVH nodes,
//! triangles, the material, the light), so the processor mostly waits on
//! memory and on branches it cannot predict. This engine takes a unit of
//! the render loop (by default a 16×16 tile × 16 samples: 4096 paths), 256
//! paths at a time (a *wave*, whose queues fit in the caches: waves of 256
//! took 0.95× the CPU time of one wave of 4096, same image), and runs each
//! *stage* over all the wave's live paths before the next stage starts:
//!
//! ```text
//!   camera ──► ┌──────────────────────────────────────────────────────┐
//!              │ closest hits ──► shade ──► shadow rays ──► compact    │ ×depth
//!              └──────────────────────────────────────────────────────┘
//!                                     └─► film (slots in raster order)
//! ```
//!
//! - **Memory layout.** Paths live in a [`PathQueue`]:
//!   structure of arrays, one array per field (rays, throughputs, radiance,
//!   samplers, ...). A stage streams through the arrays it needs and no
//!   other, and consecutive paths sit in consecutive cache lines.
//! - **Lanes.** A stage does the same thing to thousands of paths, so the
//!   same code and the same BVH nodes stay hot, and rays can be tested
//!   several at a time, one per SIMD lane.
//! - **Divergence.** Paths that hit glass and paths that hit a wall want
//!   different code. Running stage by stage keeps each branch's code together
//!   instead of interleaving it per path.
//! - **Compaction.** Paths end at different depths (roulette, escaping rays).
//!   After each bounce the live list drops the ended ones
//!   ([`PathQueue::compact`]), so later bounces
//!   loop over survivors only and no lane idles on a dead path.
//!
//! # Where the time goes
//!
//! On the Cornell box (`lesson11 bench` prints this profile; 2 threads,
//! 256×256, max depth 65), per stage:
//!
//! | stage | share of the time | work per sample |
//! |---|---|---|
//! | closest hits | 51–54% | 3.83 rays |
//! | shading (emission, light sample, BRDF sample, roulette) | 29–31% | 3.83 hits |
//! | shadow rays | 12–14% | 2.26 rays |
//! | camera rays and film | 2–4% | 1 ray, 1 sample |
//! | compaction | 1–2% | — |
//!
//! As written, each stage runs the lecture's scalar code path by path, so
//! the engine is about as fast as `path` (measured: 0.96× its CPU time, with
//! the camera rays as 16-ray packets, the samples of a pixel); the
//! lockstep gains come once a stage's loop runs several paths per SIMD
//! lane, which the queues' layout is made for (see the README's
//! performance section for the next steps).
//!
//! # The same estimator
//!
//! Each path has its own counter-based sampler, `Sampler::new(seed, pixel,
//! k)` as in the per-sample loop, and draws its numbers in `path`'s order
//! (`shade.rs`); shadow rays are traced later but draw nothing, and each
//! path's radiance is summed in the same order. The film receives the
//! samples in the per-sample loop's order. So the engine renders the image
//! `path` renders, bit for bit for a given seed, whatever the thread count
//! (`tests/wavefront.rs` checks both, and agreement by z-tests with an
//! independent seed).
//!
//! What it does not run is refused with one line ([`Unsupported`]): the
//! BRDF-only and light-only variants of `path`. It records no paths: the
//! lab's inspector records with `path`, which computes the same samples.

mod camera;
pub mod queue;
mod shade;
mod trace;

use std::cell::RefCell;
use std::fmt;
use std::sync::Mutex;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use crate::film::FilmTile;
use crate::integrator::{DirectStrategy, Integrator, PathTracer};
use crate::math::{Color, UVec2};
use crate::render::{Progress, RenderOptions, RenderResult, Unit, render_units_watched};
use crate::scene::Scene;
use queue::{PathQueue, ShadowQueue};
use shade::Depths;
use trace::Tracer;

/// What the wavefront engine cannot render yet, in one line.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Unsupported(pub String);

impl fmt::Display for Unsupported {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for Unsupported {}

/// The wavefront path tracer, with [`PathTracer`]'s depth settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WavefrontPathTracer {
    /// Maximum depth (Mitsuba's convention); `None` = unlimited.
    pub max_depth: Option<u32>,
    /// Russian roulette starts once this many bounces have been made.
    pub rr_depth: u32,
    /// Trace each stage's rays as one stream through the BVH
    /// ([`crate::geometry::stream`]) instead of one ray after the other (the
    /// same hits). Off by default: on the Cornell box's 30 primitives it
    /// costs more than it saves (see the README's performance section).
    pub streams: bool,
}

impl Default for WavefrontPathTracer {
    fn default() -> Self {
        let p = PathTracer::default();
        WavefrontPathTracer {
            max_depth: p.max_depth,
            rr_depth: p.rr_depth,
            streams: false,
        }
    }
}

/// Time spent in each stage (summed over threads), and the work done.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct StageTimes {
    /// Camera rays, and the film at the end.
    pub camera_and_film: Duration,
    /// Closest-hit traversal of the live paths' rays.
    pub closest_hits: Duration,
    /// Emission, light sample, BRDF sample, roulette.
    pub shade: Duration,
    /// Shadow rays (any hit).
    pub shadow_rays: Duration,
    /// Compaction of the live list.
    pub compact: Duration,
    /// Rays traced for closest hits, and shadow rays.
    pub rays: u64,
    pub shadow_ray_count: u64,
}

impl StageTimes {
    fn add(&mut self, o: &StageTimes) {
        self.camera_and_film += o.camera_and_film;
        self.closest_hits += o.closest_hits;
        self.shade += o.shade;
        self.shadow_rays += o.shadow_rays;
        self.compact += o.compact;
        self.rays += o.rays;
        self.shadow_ray_count += o.shadow_ray_count;
    }

    /// All stages.
    pub fn total(&self) -> Duration {
        self.camera_and_film + self.closest_hits + self.shade + self.shadow_rays + self.compact
    }
}

/// The queues of one worker thread, kept from unit to unit.
#[derive(Default)]
struct Workspace {
    paths: PathQueue,
    shadows: ShadowQueue,
    tracer: Tracer,
    pixels: Vec<UVec2>,
    /// Each path's radiance, in the unit's order.
    radiance: Vec<Color>,
    times: StageTimes,
}

/// Paths traced in lockstep: a unit's paths are run this many at a time, so
/// that the queues of a wave stay in the processor's caches.
const WAVE: usize = 256;

thread_local! {
    static WORKSPACE: RefCell<Workspace> = RefCell::default();
}

impl WavefrontPathTracer {
    /// The engine for `path`'s settings, or why it cannot run them.
    pub fn from_path(path: &PathTracer) -> Result<Self, Unsupported> {
        if path.strategy != DirectStrategy::Mis {
            return Err(Unsupported(format!(
                "the wavefront engine runs `path` with MIS only, not the {} variant: use the scalar engine",
                path_name(path.strategy)
            )));
        }
        Ok(WavefrontPathTracer {
            max_depth: path.max_depth,
            rr_depth: path.rr_depth,
            streams: false,
        })
    }

    /// Renders `scene` as [`crate::render::render`] renders it with `path`.
    pub fn render(&self, scene: &Scene, options: &RenderOptions) -> RenderResult {
        self.render_watched(scene, options, crate::render::interrupt_flag(), &mut |_| {})
    }

    /// [`Self::render`], with the time each stage took, summed over the
    /// worker threads (for `lesson11 bench` and the table in the module doc).
    pub fn render_profiled(
        &self,
        scene: &Scene,
        options: &RenderOptions,
    ) -> (RenderResult, StageTimes) {
        let total = Mutex::new(StageTimes::default());
        let (w, h) = (scene.camera.width, scene.camera.height);
        let unit = |unit: &Unit, tile: &mut FilmTile, stop: &AtomicBool| {
            WORKSPACE.with(|ws| {
                let ws = &mut ws.borrow_mut();
                ws.times = StageTimes::default();
                let done = self.render_unit(scene, unit, tile, stop, ws);
                total
                    .lock()
                    .expect("a render worker panicked")
                    .add(&ws.times);
                done
            })
        };
        let stop = crate::render::interrupt_flag();
        let result = render_units_watched(w, h, options, stop, unit, &mut |_| {});
        (
            result,
            total.into_inner().expect("a render worker panicked"),
        )
    }

    /// [`Self::render`] with a stop flag and a watcher, as
    /// [`crate::render::render_pixels_watched`].
    pub fn render_watched(
        &self,
        scene: &Scene,
        options: &RenderOptions,
        stop: &AtomicBool,
        watch: &mut (dyn FnMut(&Progress) + Send),
    ) -> RenderResult {
        let (w, h) = (scene.camera.width, scene.camera.height);
        let unit = |unit: &Unit, tile: &mut FilmTile, stop: &AtomicBool| {
            WORKSPACE.with(|ws| self.render_unit(scene, unit, tile, stop, &mut ws.borrow_mut()))
        };
        render_units_watched(w, h, options, stop, unit, watch)
    }

    /// All paths of `unit`, stage by stage; returns the samples added to
    /// `tile` (all of them, or none if a stop was requested).
    fn render_unit(
        &self,
        scene: &Scene,
        unit: &Unit,
        tile: &mut FilmTile,
        stop: &AtomicBool,
        ws: &mut Workspace,
    ) -> u64 {
        let depths = Depths {
            max_depth: self.max_depth.unwrap_or(u32::MAX),
            rr_depth: self.rr_depth,
        };
        let per_pixel = unit.samples.len();
        ws.pixels.clear();
        ws.pixels.extend(unit.pixels());
        let paths = ws.pixels.len() * per_pixel;
        ws.radiance.clear();
        let mut clock = Instant::now();
        let mut lap = |stage: &mut Duration| {
            let now = Instant::now();
            *stage += now - clock;
            clock = now;
        };
        let t = &mut ws.times;
        // The unit's paths, a wave of `WAVE` at a time.
        for first in (0..paths).step_by(WAVE) {
            let count = WAVE.min(paths - first);
            let (pixels, samples) = (&ws.pixels, &unit.samples);
            let samplers = (first..first + count).map(|i| {
                let k = samples.start + (i % per_pixel) as u32;
                unit.sampler(pixels[i / per_pixel], k)
            });
            ws.paths.reset(samplers);
            if depths.max_depth > 0 {
                camera::generate(scene, &ws.pixels, per_pixel, first, &mut ws.paths);
                lap(&mut t.camera_and_film);
            }
            while depths.max_depth > 0 && !ws.paths.live.is_empty() {
                if stop.load(Ordering::Relaxed) {
                    return 0;
                }
                t.rays += ws.paths.live.len() as u64;
                let camera = ws.paths.prev.first().is_some_and(Option::is_none)
                    && ws.paths.live.len() == ws.paths.len();
                ws.tracer
                    .closest_hits(scene, self.streams, camera, &mut ws.paths);
                lap(&mut t.closest_hits);
                shade::shade(scene, depths, &mut ws.paths, &mut ws.shadows);
                lap(&mut t.shade);
                t.shadow_ray_count += ws.shadows.len() as u64;
                ws.tracer
                    .shadow_rays(scene, self.streams, &ws.shadows, &mut ws.paths);
                lap(&mut t.shadow_rays);
                ws.paths.compact();
                lap(&mut t.compact);
            }
            ws.radiance.extend_from_slice(&ws.paths.l);
        }
        for (i, &l) in ws.radiance.iter().enumerate() {
            tile.add_sample(ws.pixels[i / per_pixel], l);
        }
        lap(&mut t.camera_and_film);
        paths as u64
    }
}

fn path_name(strategy: DirectStrategy) -> &'static str {
    let path = PathTracer {
        strategy,
        ..PathTracer::default()
    };
    path.name()
}
