//! One progressive render of a page: one image (the Render and BRDF tabs)
//! or two (the eyes of the Stereo tab), each rendered on a thread of its own
//! by `raytracer::render::render_pixels_watched`, with a snapshot of the
//! picture about four times a second.
//!
//! A job stops when its page asks for another one: the stop flag is seen
//! before every pixel sample, and inside long samples (naive recursion),
//! so the threads end within moments and the time they took is reported.
//! Stopping never changes the samples: the finished picture at N spp is the
//! picture of `lesson11 render --spp N`, bit for bit.

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, Condvar, Mutex, MutexGuard};
use std::time::{Duration, Instant};

use raytracer::film::Image;
use raytracer::integrator::Integrator;
use raytracer::render::{Progress, RenderOptions, render_pixels_watched};
use raytracer::scene::Scene;
use serde::Serialize;

/// How often a running render publishes its picture (about 4 times a second).
pub const SNAPSHOT_EVERY: Duration = Duration::from_millis(250);

/// What to render: one scene per eye (one for a plain picture), one
/// integrator, one set of options.
pub struct JobSpec {
    /// "render", "stereo" or "brdf": the tab that asked.
    pub kind: &'static str,
    /// The command line that renders the same pictures (shown on the page).
    pub command: String,
    pub eyes: Vec<Scene>,
    pub integrator: Box<dyn Integrator + Send>,
    pub options: RenderOptions,
}

/// The latest picture of one eye and how far it has come.
#[derive(Clone, Default)]
pub struct Snapshot {
    pub image: Option<Arc<Image>>,
    /// Samples on the film when the picture was taken.
    pub samples: u64,
    /// Samples per pixel of the passes complete then (every pixel has them).
    pub complete_spp: u32,
    pub elapsed: Duration,
    /// It ended before computing every sample.
    pub interrupted: bool,
    /// Samples dropped as NaN, infinite or negative.
    pub nonfinite: u64,
}

struct State {
    eyes: Vec<Snapshot>,
    /// Counts the snapshots published: the page asks for a newer one.
    version: u64,
    /// Render threads still running.
    running: usize,
    cancelled_at: Option<Instant>,
    /// From the stop request to the end of the last thread.
    stopped_after: Option<Duration>,
}

/// A progressive render and its snapshots.
pub struct Job {
    pub id: u64,
    pub kind: &'static str,
    pub command: String,
    pub width: u32,
    pub height: u32,
    pub target_spp: u32,
    seed: u64,
    /// The integrator (the path inspector records its samples).
    integrator: Arc<dyn Integrator + Send>,
    /// The scene of each eye.
    scenes: Vec<Arc<Scene>>,
    stop: Arc<AtomicBool>,
    state: Mutex<State>,
    changed: Condvar,
}

/// What the page reads about a job (`/api/status`).
#[derive(Serialize)]
pub struct JobStatus {
    pub id: u64,
    pub kind: &'static str,
    pub command: String,
    pub width: u32,
    pub height: u32,
    pub target_spp: u32,
    /// Average samples per pixel so far (of the eye that is behind).
    pub spp: f64,
    /// Samples per pixel that every pixel has (of the eye that is behind).
    pub complete_spp: u32,
    pub samples: u64,
    pub samples_per_second: f64,
    pub elapsed: f64,
    pub done: bool,
    pub interrupted: bool,
    pub nonfinite: u64,
    pub version: u64,
    /// Milliseconds from the stop request to the end of the render, once stopped.
    pub stopped_after_ms: Option<f64>,
}

fn lock<T>(m: &Mutex<T>) -> MutexGuard<'_, T> {
    // A panic elsewhere must not take the lab down: the state stays readable.
    m.lock().unwrap_or_else(|e| e.into_inner())
}

impl Job {
    /// Starts the render threads (`running` counts them for the whole lab).
    pub fn start(id: u64, spec: JobSpec, running: &Arc<AtomicUsize>) -> Result<Arc<Job>, String> {
        let scenes: Vec<Arc<Scene>> = spec.eyes.into_iter().map(Arc::new).collect();
        let first = scenes.first().ok_or("a job without a picture")?;
        let job = Arc::new(Job {
            id,
            kind: spec.kind,
            command: spec.command,
            width: first.camera.width,
            height: first.camera.height,
            target_spp: spec.options.spp,
            seed: spec.options.seed,
            integrator: Arc::from(spec.integrator),
            scenes: scenes.clone(),
            stop: Arc::new(AtomicBool::new(false)),
            state: Mutex::new(State {
                eyes: vec![Snapshot::default(); scenes.len()],
                version: 0,
                running: scenes.len(),
                cancelled_at: None,
                stopped_after: None,
            }),
            changed: Condvar::new(),
        });
        let integrator = job.integrator.clone();
        for (eye, scene) in scenes.into_iter().enumerate() {
            let (job2, integrator, options) =
                (job.clone(), integrator.clone(), spec.options.clone());
            running.fetch_add(1, Ordering::SeqCst);
            let counter = running.clone();
            let spawned = std::thread::Builder::new()
                .name(format!("lab-render-{id}-{eye}"))
                .spawn(move || {
                    job2.render(eye, &scene, integrator.as_ref(), &options);
                    counter.fetch_sub(1, Ordering::SeqCst);
                });
            if let Err(e) = spawned {
                running.fetch_sub(1, Ordering::SeqCst);
                job.cancel();
                return Err(format!("cannot start a render thread: {e}"));
            }
        }
        Ok(job)
    }

    /// One eye's render, publishing snapshots as it goes and the film at the end.
    ///
    /// It runs on a thread pool of its own (one thread per core): a render
    /// keeps every thread of its pool busy until it ends, and the global
    /// pool must stay free for the next request's scene (its BVH is built
    /// in parallel). The picture does not depend on the threads.
    fn render(
        &self,
        eye: usize,
        scene: &Scene,
        integrator: &dyn Integrator,
        options: &RenderOptions,
    ) {
        let (w, h) = (scene.camera.width, scene.camera.height);
        let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
        let options = &RenderOptions {
            threads: Some(cores),
            ..options.clone()
        };
        let mut last: Option<Instant> = None;
        let mut watch = |p: &Progress| {
            if last.is_some_and(|t| t.elapsed() < SNAPSHOT_EVERY) {
                return;
            }
            last = Some(Instant::now());
            self.publish(
                eye,
                Snapshot {
                    image: Some(Arc::new(p.film.image())),
                    samples: p.film.total_samples(),
                    complete_spp: p.complete_spp,
                    elapsed: p.elapsed,
                    interrupted: false,
                    nonfinite: p.film.nonfinite_count(),
                },
            );
        };
        let result = render_pixels_watched(
            w,
            h,
            options,
            &self.stop,
            |pixel, sampler, splats| integrator.sample(scene, pixel, sampler, splats),
            &mut watch,
        );
        let complete = if result.stats.interrupted {
            lock(&self.state).eyes[eye].complete_spp
        } else {
            options.spp
        };
        self.publish(
            eye,
            Snapshot {
                image: Some(Arc::new(result.film.image())),
                samples: result.stats.samples,
                complete_spp: complete,
                elapsed: result.stats.elapsed,
                interrupted: result.stats.interrupted,
                nonfinite: result.stats.nonfinite,
            },
        );
        let mut state = lock(&self.state);
        state.running -= 1;
        if state.running == 0 {
            state.stopped_after = state.cancelled_at.map(|t| t.elapsed());
        }
        drop(state);
        self.changed.notify_all();
    }

    fn publish(&self, eye: usize, snapshot: Snapshot) {
        let mut state = lock(&self.state);
        state.eyes[eye] = snapshot;
        state.version += 1;
        drop(state);
        self.changed.notify_all();
    }

    /// The scene of a plain render (the Render tab), which the inspector traces.
    pub fn scene(&self) -> Option<Arc<Scene>> {
        (self.kind == "render").then(|| self.scenes[0].clone())
    }

    /// The integrator that renders the picture.
    pub fn integrator(&self) -> &dyn Integrator {
        self.integrator.as_ref()
    }

    pub fn seed(&self) -> u64 {
        self.seed
    }

    /// Asks the render threads to stop (they end within moments).
    pub fn cancel(&self) {
        let mut state = lock(&self.state);
        if state.cancelled_at.is_none() && state.running > 0 {
            state.cancelled_at = Some(Instant::now());
        }
        self.stop.store(true, Ordering::SeqCst);
    }

    /// Waits until a snapshot newer than `version` is out, the job has
    /// ended, or `timeout` passed (a long poll: the page hears of a new
    /// picture at once, without asking over and over).
    pub fn wait_newer(&self, version: u64, timeout: Duration) {
        let state = lock(&self.state);
        let _ = self
            .changed
            .wait_timeout_while(state, timeout, |s| s.version <= version && s.running > 0);
    }

    /// The latest pictures, one per eye (`None` before the first snapshot).
    pub fn images(&self) -> Vec<Option<Arc<Image>>> {
        lock(&self.state)
            .eyes
            .iter()
            .map(|e| e.image.clone())
            .collect()
    }

    /// The job as the page reads it.
    pub fn status(&self) -> JobStatus {
        let state = lock(&self.state);
        let pixels = (self.width as f64 * self.height as f64).max(1.0);
        let behind = state
            .eyes
            .iter()
            .min_by_key(|e| e.samples)
            .cloned()
            .unwrap_or_default();
        let samples: u64 = state.eyes.iter().map(|e| e.samples).sum();
        let elapsed = state
            .eyes
            .iter()
            .map(|e| e.elapsed)
            .max()
            .unwrap_or_default()
            .as_secs_f64();
        JobStatus {
            id: self.id,
            kind: self.kind,
            command: self.command.clone(),
            width: self.width,
            height: self.height,
            target_spp: self.target_spp,
            spp: behind.samples as f64 / pixels,
            complete_spp: behind.complete_spp,
            samples,
            samples_per_second: if elapsed > 0.0 {
                samples as f64 / elapsed
            } else {
                0.0
            },
            elapsed,
            done: state.running == 0,
            interrupted: state.eyes.iter().any(|e| e.interrupted),
            nonfinite: state.eyes.iter().map(|e| e.nonfinite).sum(),
            version: state.version,
            stopped_after_ms: state.stopped_after.map(|d| d.as_secs_f64() * 1e3),
        }
    }
}
