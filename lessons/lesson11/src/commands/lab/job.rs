//! One progressive render of a page: one image (the Render and BRDF tabs)
//! or two (the eyes of the Stereo tab), on a thread of the job's own, with
//! a snapshot of the picture about four times a second.
//!
//! The job's thread does everything that takes time, in this order, so
//! that the request that started it returns at once and the next one can
//! stop it in any phase:
//!
//! - **building**: photon maps, virtual point lights or irradiance records
//!   ([`crate::integrators::BiasedPlan::build`]), ended by the job's stop
//!   flag;
//! - **rendering**: pixel samples by `raytracer::render::render_pixels_watched`
//!   (one thread per eye), SPPM pass by pass
//!   (`raytracer::render::sppm::render_sppm_watched`, a snapshot after a
//!   pass), or Metropolis light transport chain by chain
//!   (`raytracer::render::metropolis::render_metropolis_watched`, a
//!   snapshot as chains are merged: `--spp` counts mutations per pixel).
//!
//! A job stops when its page asks for another one: the stop flag is seen
//! between batches of photon paths, before every pixel sample and inside
//! long samples (naive recursion), after every Metropolis step, so the
//! thread ends within moments and the time it took is reported. Stopping
//! never changes the samples: the finished picture at N spp (N passes, N
//! mutations per pixel) is the picture of `lesson11 render --spp N`, bit for
//! bit, since both come from the same plan ([`IntegratorPlan`]).

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, Condvar, Mutex, MutexGuard, OnceLock};
use std::time::{Duration, Instant};

use raytracer::film::Image;
use raytracer::integrator::{Bdpt, Integrator};
use raytracer::render::metropolis::{MetropolisProgress, render_metropolis_watched};
use raytracer::render::sppm::SppmSettings;
use raytracer::render::sppm::{SppmProgress, render_sppm_watched};
use raytracer::render::{Metropolis, Progress, RenderOptions, render_pixels_watched};
use raytracer::scene::Scene;
use raytracer::wavefront::WavefrontPathTracer;
use serde::Serialize;

use raytracer::math::{Color, UVec2};

use super::preview::coarse_preview;
use super::settings::one_line;
use crate::integrators::{BiasedPlan, IntegratorPlan};

/// How often a running render publishes its picture (about 4 times a second).
pub const SNAPSHOT_EVERY: Duration = Duration::from_millis(250);

/// Lets a render's watcher publish at most once per [`SNAPSHOT_EVERY`].
#[derive(Default)]
struct Throttle {
    last: Option<Instant>,
}

impl Throttle {
    /// True the first time and whenever `SNAPSHOT_EVERY` has passed since
    /// the last true (the clock then starts again).
    fn due(&mut self) -> bool {
        if self.last.is_some_and(|t| t.elapsed() < SNAPSHOT_EVERY) {
            return false;
        }
        self.last = Some(Instant::now());
        true
    }
}

/// What to render: one scene per eye (one for a plain picture), one
/// integrator's plan, one set of options.
pub struct JobSpec {
    /// "render", "stereo" or "brdf": the tab that asked.
    pub kind: &'static str,
    /// The command line that renders the same pictures (shown on the page).
    pub command: String,
    pub eyes: Vec<Scene>,
    /// The scene a build is made for, if not the first eye's (the stereo
    /// rig's centre, as `lesson11 stereo` builds it).
    pub build_for: Option<Scene>,
    /// Checked, not built: the job's thread builds what takes time.
    pub plan: IntegratorPlan,
    pub options: RenderOptions,
    /// The "Your code" tab: the student's integrator (eye 0) beside the
    /// renderer's of the same estimator (eye 1), instead of `plan`.
    pub student: Option<StudentPair>,
    /// The Race tab: integrators that render the same scene at once, each
    /// on a thread of its own, measured against a reference, instead of
    /// `plan`.
    pub race: Option<Racers>,
    /// `--engine wavefront`: the path tracer on the wavefront engine (the
    /// same samples; the inspector records them with `path`).
    pub wavefront: Option<WavefrontPathTracer>,
}

/// An equal-time race (`race.rs`).
pub struct Racers {
    pub integrators: Vec<Box<dyn Integrator + Send>>,
    /// How long each renders.
    pub seconds: f64,
    /// The image each snapshot's RMSE is measured against.
    pub reference: Arc<Image>,
    /// The reference's own noise: no error measured with it goes below.
    pub floor: f64,
}

/// One racer's line of the plot.
#[derive(Clone, Serialize)]
pub struct RaceLine {
    pub integrator: &'static str,
    /// (seconds, RMSE) at each snapshot.
    pub points: Vec<[f64; 2]>,
}

/// The student's integrator and the renderer's beside it, made on the
/// job's thread (the exercises' integrators are not `Send`).
pub struct StudentPair {
    /// The exercise (`ex13_mis`), named in messages.
    pub exercise: &'static str,
    pub make: Box<dyn FnOnce() -> IntegratorPair + Send>,
}

/// The student's integrator and the renderer's, in that order.
pub type IntegratorPair = (Box<dyn Integrator>, Box<dyn Integrator>);

/// The latest picture of one eye and how far it has come.
#[derive(Clone, Default)]
pub struct Snapshot {
    pub image: Option<Arc<Image>>,
    /// Samples on the film when the picture was taken (pixel passes of
    /// SPPM, mutations of Metropolis).
    pub samples: u64,
    /// Samples per pixel of the passes complete then (every pixel has them).
    pub complete_spp: u32,
    /// Time the render of this eye had taken then.
    pub elapsed: Duration,
    /// Samples dropped as NaN, infinite or negative.
    pub nonfinite: u64,
    /// The variance of each pixel's mean (the "Your code" tab's z-map).
    pub variance: Option<Arc<Image>>,
    /// What the page shows while the first pass is incomplete
    /// ([`super::preview::coarse_preview`]); `None`: `image` itself.
    pub preview: Option<Arc<Image>>,
}

/// What a job is doing.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Phase {
    /// Photon maps, VPLs or irradiance records are being made.
    Building,
    Rendering,
    Done,
}

/// What the work left for the job's thread is.
enum Work {
    /// Pixel samples of the integrator the job already holds.
    Samples,
    /// Pixel samples once the plan is built.
    Build(BiasedPlan),
    Sppm(SppmSettings),
    Metropolis(Bdpt, Metropolis),
    /// The student's integrator beside the renderer's.
    Student(StudentPair),
    Race(Vec<Box<dyn Integrator + Send>>, f64),
}

struct State {
    eyes: Vec<Snapshot>,
    /// Counts the changes the page should see (snapshots, phases, notes).
    version: u64,
    phase: Phase,
    /// One line on the render (the build's summary, the chains merged, …).
    note: Option<String>,
    /// Why the render failed (a build that could not be made).
    error: Option<String>,
    /// It ended before rendering everything (stopped).
    interrupted: bool,
    ended: Option<Instant>,
    cancelled_at: Option<Instant>,
    /// The phase the stop request came in.
    cancelled_in: Option<Phase>,
    /// The race's lines, one per eye.
    race: Vec<RaceLine>,
    /// From the stop request to the end of the job's thread.
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
    /// What `spp` counts, and what a sample is.
    units: (&'static str, &'static str),
    /// The integrator of pixel samples, once built (the path inspector
    /// records its samples).
    integrator: OnceLock<Arc<dyn Integrator + Send>>,
    wavefront: Option<WavefrontPathTracer>,
    /// Why the render has no pixel samples to inspect (SPPM, Metropolis),
    /// in English and Bulgarian.
    no_samples: Option<(&'static str, &'static str)>,
    /// The language of the page that started it (of its notes and errors).
    language: lang::Lang,
    /// What the build makes ("the photon maps"), if there is one.
    building: Option<&'static str>,
    /// The scene of each eye.
    scenes: Vec<Arc<Scene>>,
    /// See [`JobSpec::build_for`].
    build_for: Option<Scene>,
    /// The exercise of the "Your code" tab ([`JobSpec::student`]).
    exercise: Option<&'static str>,
    /// The race's reference and its noise floor ([`JobSpec::race`]).
    race_reference: Option<(Arc<Image>, f64)>,
    started: Instant,
    stop: AtomicBool,
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
    /// What `spp` and `target_spp` count: "spp", "passes" (SPPM) or
    /// "mutations per pixel" (Metropolis).
    pub unit: &'static str,
    /// What `samples` counts: "samples", "pixel passes" or "mutations".
    pub samples_unit: &'static str,
    /// Average samples per pixel so far (of the eye that is behind).
    pub spp: f64,
    /// Samples per pixel that every pixel has (of the eye that is behind).
    pub complete_spp: u32,
    pub samples: u64,
    pub samples_per_second: f64,
    /// Seconds since the job started (until it ended), its build included.
    pub elapsed: f64,
    pub phase: Phase,
    /// Whether there is a picture to show yet.
    pub picture: bool,
    pub note: Option<String>,
    pub error: Option<String>,
    pub done: bool,
    pub interrupted: bool,
    pub nonfinite: u64,
    /// The same, eye by eye (the student's integrator is eye 0 of its tab).
    pub nonfinite_by_eye: Vec<u64>,
    /// The race's lines (RMSE against time), and the reference's noise floor.
    pub race: Option<(Vec<RaceLine>, f64)>,
    pub version: u64,
    /// The phase the render was in when it was asked to stop.
    pub cancelled_in: Option<Phase>,
    /// Milliseconds from the stop request to the end of the render, once stopped.
    pub stopped_after_ms: Option<f64>,
}

fn lock<T>(m: &Mutex<T>) -> MutexGuard<'_, T> {
    // A panic elsewhere must not take the lab down: the state stays readable.
    m.lock().unwrap_or_else(|e| e.into_inner())
}

/// Why the inspector has nothing to show for SPPM.
pub const SPPM_NO_SAMPLES: &str = "sppm's picture is made of passes of visible points and photons, \
     not of pixel samples, so there are no paths of one sample to show (photon mapping does not \
     record its paths either; path, direct, naive, light and bdpt do)";

/// Why the inspector has nothing to show for Metropolis.
const MLT_NO_SAMPLES: &str = "mlt's picture is made of Markov chains that mutate paths, not of \
     independent pixel samples, so there are no paths of one sample to show (bdpt shows the \
     paths its chains mutate)";

const SPPM_NO_SAMPLES_BG: &str = "картината на sppm се прави от проходи с видими точки и фотони, \
     а не от проби на пиксел, затова няма пътища на една проба за показване (photon mapping също \
     не записва пътищата си; path, direct, naive, light и bdpt ги записват)";

const MLT_NO_SAMPLES_BG: &str = "картината на mlt се прави от марковски вериги, които изменят \
     пътища, а не от независими проби на пиксел, затова няма пътища на една проба за показване \
     (bdpt показва пътищата, които веригите му изменят)";

/// What a build makes, in Bulgarian (the names of `BiasedPlan::what`).
fn building_bg(what: &str) -> &str {
    match what {
        "the photon maps" => "фотонните карти",
        "the virtual point lights" => "виртуалните точкови светлини (VPL)",
        "the irradiance cache" => "кеша на irradiance (облъчеността)",
        other => other,
    }
}

impl Job {
    /// Starts the job's thread (`running` counts the running jobs of the
    /// whole lab). Only quick work happens here: the thread does the rest.
    pub fn start(id: u64, spec: JobSpec, running: &Arc<AtomicUsize>) -> Result<Arc<Job>, String> {
        let scenes: Vec<Arc<Scene>> = spec.eyes.into_iter().map(Arc::new).collect();
        let first = scenes.first().ok_or("a job without a picture")?;
        let integrator = OnceLock::new();
        let exercise = spec.student.as_ref().map(|p| p.exercise);
        let race_reference = spec.race.as_ref().map(|r| (r.reference.clone(), r.floor));
        let race_lines: Vec<RaceLine> = spec.race.as_ref().map_or(Vec::new(), |r| {
            r.integrators
                .iter()
                .map(|i| RaceLine {
                    integrator: i.name(),
                    points: Vec::new(),
                })
                .collect()
        });
        let (work, units, no_samples, building) = match spec.plan {
            _ if spec.race.is_some() => {
                let r = spec.race.expect("checked");
                (
                    Work::Race(r.integrators, r.seconds),
                    ("spp", "samples"),
                    None,
                    None,
                )
            }
            _ if spec.student.is_some() => (
                Work::Student(spec.student.expect("checked")),
                ("spp", "samples"),
                None,
                None,
            ),
            IntegratorPlan::Ready(i) => {
                let _ = integrator.set(Arc::from(i));
                (Work::Samples, ("spp", "samples"), None, None)
            }
            IntegratorPlan::Biased(plan) => {
                let what = plan.what();
                (Work::Build(plan), ("spp", "samples"), None, Some(what))
            }
            IntegratorPlan::Sppm(s) => (
                Work::Sppm(s),
                ("passes", "pixel passes"),
                Some((SPPM_NO_SAMPLES, SPPM_NO_SAMPLES_BG)),
                None,
            ),
            IntegratorPlan::Metropolis(b, m) => (
                Work::Metropolis(b, m),
                ("mutations per pixel", "mutations"),
                Some((MLT_NO_SAMPLES, MLT_NO_SAMPLES_BG)),
                None,
            ),
        };
        if no_samples.is_some() && scenes.len() != 1 {
            return Err(lang::pick(
                "sppm and mlt render one picture (the Render tab), not a stereo pair",
                "sppm и mlt рендерират една картина (раздела „Рендер“), а не стереодвойка",
            )
            .into());
        }
        let language = lang::current();
        let job = Arc::new(Job {
            id,
            language,
            kind: spec.kind,
            command: spec.command,
            width: first.camera.width,
            height: first.camera.height,
            target_spp: spec.options.spp,
            seed: spec.options.seed,
            units,
            integrator,
            wavefront: spec.wavefront,
            no_samples,
            building,
            scenes: scenes.clone(),
            build_for: spec.build_for,
            exercise,
            race_reference,
            started: Instant::now(),
            stop: AtomicBool::new(false),
            state: Mutex::new(State {
                eyes: vec![Snapshot::default(); scenes.len()],
                version: 0,
                phase: if building.is_some() {
                    Phase::Building
                } else {
                    Phase::Rendering
                },
                note: building.map(|what| {
                    language.pick(
                        format!("building {what}…"),
                        format!("строи {}…", building_bg(what)),
                    )
                }),
                error: None,
                interrupted: false,
                ended: None,
                cancelled_at: None,
                cancelled_in: None,
                stopped_after: None,
                race: race_lines,
            }),
            changed: Condvar::new(),
        });
        running.fetch_add(1, Ordering::SeqCst);
        let (job2, counter, options) = (job.clone(), running.clone(), spec.options);
        let spawned = std::thread::Builder::new()
            .name(format!("lab-job-{id}"))
            .spawn(move || {
                // The build's summary and the errors in the page's language.
                lang::with(job2.language, || {
                    let outcome = job2.run(work, options);
                    job2.finish(outcome, &counter);
                });
            });
        if let Err(e) = spawned {
            running.fetch_sub(1, Ordering::SeqCst);
            return Err(format!("cannot start a render thread: {e}"));
        }
        Ok(job)
    }

    /// The job's thread: the build if there is one, then the render.
    /// `Ok(true)`: every sample was rendered; `Ok(false)`: stopped before.
    ///
    /// It runs on thread pools of its own (one thread per core): a render
    /// keeps every thread of its pool busy until it ends, and the global
    /// pool must stay free for the next request's scene (its BVH is built
    /// in parallel). The picture does not depend on the threads.
    fn run(&self, work: Work, options: RenderOptions) -> Result<bool, String> {
        let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
        let options = RenderOptions {
            threads: Some(cores),
            ..options
        };
        let integrator = match work {
            Work::Sppm(settings) => return Ok(self.render_sppm(&settings, &options)),
            Work::Metropolis(bdpt, metropolis) => {
                return Ok(self.render_metropolis(&bdpt, &metropolis, &options));
            }
            Work::Student(pair) => return Ok(self.render_student(pair, &options)),
            Work::Race(racers, seconds) => return Ok(self.render_race(&racers, seconds, &options)),
            Work::Samples => match self.integrator.get() {
                Some(i) => i.clone(),
                None => return Err("the render has no integrator".into()),
            },
            Work::Build(plan) => {
                let scene = self.build_for.as_ref().unwrap_or(&self.scenes[0]);
                let (integrator, summary) = plan
                    .build(scene, &options, &self.stop)
                    .map_err(|e| one_line(&e))?;
                if self.stopped() {
                    // The summary says how far the build came.
                    self.update(|s| s.note = Some(summary));
                    return Ok(false);
                }
                let integrator: Arc<dyn Integrator + Send> = Arc::from(integrator);
                let _ = self.integrator.set(integrator.clone());
                self.update(|s| {
                    s.phase = Phase::Rendering;
                    s.note = Some(summary);
                });
                integrator
            }
        };
        Ok(self.render_eyes(integrator.as_ref(), &options))
    }

    fn stopped(&self) -> bool {
        self.stop.load(Ordering::Relaxed)
    }

    /// The student's integrator (eye 0) and the renderer's of the same
    /// estimator (eye 1) at once, as `lesson11 render --student` renders
    /// them: the renderer's with seed + 1 (the two may draw the same numbers
    /// in the same order, and correlated pictures would hide a difference).
    /// A panic in the student's code stops both with its message.
    fn render_student(&self, pair: StudentPair, options: &RenderOptions) -> bool {
        let (student, reference) = (pair.make)();
        let other = RenderOptions {
            seed: options.seed.wrapping_add(1),
            ..options.clone()
        };
        let (mine, theirs) = (&self.scenes[0], &self.scenes[1]);
        std::thread::scope(|s| {
            let reference = s.spawn(|| self.render_eye(1, theirs, reference.as_ref(), &other));
            let student = self.render_eye(0, mine, student.as_ref(), options);
            student & reference.join().unwrap_or(false)
        })
    }

    /// Every racer at once, each on one thread of its own, until `seconds`
    /// have passed (or all are done); true unless stopped by the page.
    fn render_race(
        &self,
        racers: &[Box<dyn Integrator + Send>],
        seconds: f64,
        options: &RenderOptions,
    ) -> bool {
        let one = RenderOptions {
            threads: Some(1),
            ..options.clone()
        };
        let finished = AtomicBool::new(false);
        let mut timed_out = false;
        std::thread::scope(|s| {
            let timer = s.spawn(|| {
                let end = Instant::now() + Duration::from_secs_f64(seconds);
                while Instant::now() < end {
                    if finished.load(Ordering::Relaxed) || self.stopped() {
                        return false;
                    }
                    std::thread::sleep(Duration::from_millis(20));
                }
                self.stop.store(true, Ordering::SeqCst);
                true
            });
            let threads: Vec<_> = racers
                .iter()
                .enumerate()
                .map(|(eye, racer)| {
                    let (scene, one) = (&self.scenes[eye], &one);
                    s.spawn(move || self.render_eye(eye, scene, racer.as_ref(), one))
                })
                .collect();
            for t in threads {
                let _ = t.join();
            }
            finished.store(true, Ordering::Relaxed);
            timed_out = timer.join().unwrap_or(false);
        });
        timed_out || !self.stopped()
    }

    /// A panic in the student's integrator at `pixel`: the job stops and
    /// the page says why (a `todo!()` is an exercise not started).
    fn student_panicked(&self, pixel: UVec2, payload: &(dyn std::any::Any + Send)) {
        let what = payload
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "a panic without a message".into());
        let exercise = self.exercise.unwrap_or("the exercise");
        let message = if what.contains("not yet implemented") {
            self.language.pick(
                format!(
                    "{exercise} is not started yet (todo!() in exercises/src/{exercise}.rs): fill it in, \
                     then start the lab again (it renders the code it was built with)"
                ),
                format!(
                    "{exercise} още не е започната (todo!() в exercises/src/{exercise}.rs): попълнете я \
                     и стартирайте лабораторията отново (тя рендерира кода, с който е компилирана)"
                ),
            )
        } else {
            self.language.pick(
                format!(
                    "your integrator ({exercise}) panicked at pixel ({}, {}): {what}",
                    pixel.x, pixel.y
                ),
                format!(
                    "вашият интегратор ({exercise}) спря с panic в пиксел ({}, {}): {what}",
                    pixel.x, pixel.y
                ),
            )
        };
        self.update(|s| {
            s.error.get_or_insert(message);
        });
        self.stop.store(true, Ordering::SeqCst);
    }

    /// Every eye at once, each on a thread (and a pool) of its own; true if
    /// every one rendered every sample.
    fn render_eyes(&self, integrator: &dyn Integrator, options: &RenderOptions) -> bool {
        if let [scene] = self.scenes.as_slice() {
            return self.render_eye(0, scene, integrator, options);
        }
        std::thread::scope(|s| {
            let threads: Vec<_> = self
                .scenes
                .iter()
                .enumerate()
                .map(|(eye, scene)| {
                    std::thread::Builder::new()
                        .name(format!("lab-render-{}-{eye}", self.id))
                        .spawn_scoped(s, move || self.render_eye(eye, scene, integrator, options))
                        .map_err(|_| (eye, scene))
                })
                .collect();
            let complete: Vec<bool> = threads
                .into_iter()
                .map(|t| match t {
                    Ok(thread) => thread.join().unwrap_or(false),
                    // No thread to be had: render that eye here.
                    Err((eye, scene)) => self.render_eye(eye, scene, integrator, options),
                })
                .collect();
            complete.into_iter().all(|c| c)
        })
    }

    /// One eye's render, publishing snapshots as it goes and the film at
    /// the end; true if it rendered every sample.
    fn render_eye(
        &self,
        eye: usize,
        scene: &Scene,
        integrator: &dyn Integrator,
        options: &RenderOptions,
    ) -> bool {
        let (w, h) = (scene.camera.width, scene.camera.height);
        let mut throttle = Throttle::default();
        // The "Your code" tab: eye 0 is the student's code, whose panic must
        // not take the lab down; both eyes' variances make the z-map.
        let student = self.exercise.is_some();
        let catch = student && eye == 0;
        let mut watch = |p: &Progress| {
            if !throttle.due() {
                return;
            }
            let image = p.film.image();
            let preview = coarse_preview(p.film, &image).map(Arc::new);
            self.publish(
                eye,
                Snapshot {
                    preview,
                    image: Some(Arc::new(image)),
                    samples: p.film.total_samples(),
                    complete_spp: p.complete_spp,
                    elapsed: p.elapsed,
                    nonfinite: p.film.nonfinite_count(),
                    variance: student.then(|| Arc::new(p.film.variance_image())),
                },
                None,
            );
        };
        let result = match &self.wavefront {
            Some(engine) => engine.render_watched(scene, options, &self.stop, &mut watch),
            None => render_pixels_watched(
                w,
                h,
                options,
                &self.stop,
                |pixel, sampler, splats| {
                    if !catch {
                        return integrator.sample(scene, pixel, sampler, splats);
                    }
                    let sample = || integrator.sample(scene, pixel, sampler, splats);
                    std::panic::catch_unwind(std::panic::AssertUnwindSafe(sample)).unwrap_or_else(
                        |payload| {
                            self.student_panicked(pixel, payload.as_ref());
                            Color::ZERO
                        },
                    )
                },
                &mut watch,
            ),
        };
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
                nonfinite: result.stats.nonfinite,
                variance: student.then(|| Arc::new(result.film.variance_image())),
                preview: None,
            },
            None,
        );
        !result.stats.interrupted
    }

    /// SPPM, a snapshot after a pass (at most about 4 a second) and the
    /// image of the finished passes at the end; true if every pass ran.
    fn render_sppm(&self, settings: &SppmSettings, options: &RenderOptions) -> bool {
        let scene = &self.scenes[0];
        let pixels = self.width as u64 * self.height as u64;
        let note = |passes: u32| {
            self.language.pick(
                format!(
                    "SPPM: {passes} of {} passes of {} photon paths",
                    options.spp, settings.photons
                ),
                format!(
                    "SPPM: {passes} от {} прохода по {} фотонни пътя",
                    options.spp, settings.photons
                ),
            )
        };
        let mut throttle = Throttle::default();
        let mut watch = |p: &SppmProgress| {
            if !throttle.due() {
                return;
            }
            self.publish(
                0,
                Snapshot {
                    image: Some(Arc::new(p.image())),
                    samples: pixels * p.passes as u64,
                    complete_spp: p.passes,
                    elapsed: p.elapsed,
                    nonfinite: 0,
                    variance: None,
                    preview: None,
                },
                Some(note(p.passes)),
            );
        };
        let r = render_sppm_watched(scene, settings, options, &self.stop, &mut watch);
        if r.passes > 0 {
            let line = format!(
                "{}, {} {:.4} → {:.4}, {} {:.1} MiB",
                note(r.passes),
                self.language.pick("radius", "радиус"),
                r.initial_radius,
                r.final_radius,
                self.language.pick("peak", "най-много"),
                r.peak_bytes as f64 / (1 << 20) as f64
            );
            self.publish(
                0,
                Snapshot {
                    image: Some(Arc::new(r.image)),
                    samples: r.stats.samples,
                    complete_spp: r.passes,
                    elapsed: r.stats.elapsed,
                    nonfinite: 0,
                    variance: None,
                    preview: None,
                },
                Some(line),
            );
        }
        !r.stats.interrupted
    }

    /// Metropolis light transport over `bdpt`: a snapshot as chains are
    /// merged (at most about 4 a second; the bootstrap comes first and
    /// shows no picture) and the film of the merged chains at the end; true
    /// if every mutation was made.
    fn render_metropolis(
        &self,
        bdpt: &Bdpt,
        metropolis: &Metropolis,
        options: &RenderOptions,
    ) -> bool {
        let scene = &self.scenes[0];
        let pixels = (self.width as u64 * self.height as u64).max(1);
        let template = self.language.pick(
            "Metropolis: b = {b} ± {error} % from {paths} bootstrap paths; {chains} of {all} chains \
             merged, acceptance {accepted} %",
            "Metropolis: b = {b} ± {error} % от {paths} начални пътя; {chains} от {all} вериги \
             обединени, приети {accepted} %",
        );
        let note = |p: &MetropolisProgress| {
            let b = format!("{:.5}", p.bootstrap.b);
            let error = format!("{:.2}", 100.0 * p.bootstrap.relative_error());
            let accepted = format!(
                "{:.0}",
                100.0 * p.accepted as f64 / p.mutations.max(1) as f64
            );
            lang::fill(
                template,
                &[
                    ("b", &b),
                    ("error", &error),
                    ("paths", &p.bootstrap.paths),
                    ("chains", &p.chains),
                    ("all", &metropolis.chains),
                    ("accepted", &accepted),
                ],
            )
        };
        let mut throttle = Throttle::default();
        let mut final_note = None;
        let mut watch = |p: &MetropolisProgress| {
            final_note = Some(note(p));
            if p.chains == 0 {
                // The bootstrap is done, the chains start.
                self.update(|s| s.note = final_note.clone());
                return;
            }
            if !throttle.due() {
                return;
            }
            self.publish(
                0,
                Snapshot {
                    image: Some(Arc::new(p.film.image())),
                    samples: p.mutations,
                    complete_spp: (p.mutations / pixels) as u32,
                    elapsed: p.elapsed,
                    nonfinite: 0,
                    variance: None,
                    preview: None,
                },
                final_note.clone(),
            );
        };
        let r = render_metropolis_watched(scene, bdpt, options, metropolis, &self.stop, &mut watch);
        if r.chains > 0 {
            self.publish(
                0,
                Snapshot {
                    image: Some(Arc::new(r.film.image())),
                    samples: r.stats.samples,
                    complete_spp: if r.stats.interrupted {
                        (r.stats.samples / pixels) as u32
                    } else {
                        options.spp
                    },
                    elapsed: r.stats.elapsed,
                    nonfinite: r.stats.nonfinite,
                    variance: None,
                    preview: None,
                },
                final_note,
            );
        }
        !r.stats.interrupted
    }

    /// The end of the job's thread: the lab's count first (a page that sees
    /// the job done sees it no longer running), then the state.
    fn finish(&self, outcome: Result<bool, String>, running: &AtomicUsize) {
        running.fetch_sub(1, Ordering::SeqCst);
        self.update(|s| {
            s.phase = Phase::Done;
            s.ended = Some(Instant::now());
            match outcome {
                Ok(complete) => s.interrupted = !complete,
                Err(e) => s.error = Some(e),
            }
            s.stopped_after = s.cancelled_at.map(|t| t.elapsed());
        });
    }

    /// Changes the state as `change` says and tells the waiting pages.
    fn update(&self, change: impl FnOnce(&mut State)) {
        let mut state = lock(&self.state);
        change(&mut state);
        state.version += 1;
        drop(state);
        self.changed.notify_all();
    }

    fn publish(&self, eye: usize, snapshot: Snapshot, note: Option<String>) {
        // A racer's error against the reference at this moment, once every
        // pixel has a sample (a pixel without one is black, and in a dark
        // scene black is close: the error of a partial first pass misleads).
        let point = match (&self.race_reference, &snapshot.image) {
            (Some((reference, _)), Some(image)) if snapshot.complete_spp > 0 => Some([
                snapshot.elapsed.as_secs_f64(),
                raytracer::metrics::rmse(image, reference) as f64,
            ]),
            _ => None,
        };
        self.update(|s| {
            if let (Some(p), Some(line)) = (point, s.race.get_mut(eye)) {
                line.points.push(p);
            }
            s.eyes[eye] = snapshot;
            if note.is_some() {
                s.note = note;
            }
        });
    }

    /// The scene of a plain render (the Render tab), which the inspector traces.
    pub fn scene(&self) -> Option<Arc<Scene>> {
        (self.kind == "render").then(|| self.scenes[0].clone())
    }

    /// The integrator whose samples make the picture, or why the inspector
    /// cannot have it (SPPM and Metropolis have none; a build is under way).
    pub fn integrator(&self) -> Result<Arc<dyn Integrator + Send>, String> {
        if let Some(i) = self.integrator.get() {
            return Ok(i.clone());
        }
        if let Some((en, bg)) = self.no_samples {
            return Err(lang::pick(en, bg).into());
        }
        let what = self.building.unwrap_or("its integrator");
        let bg = self.building.map_or("своя интегратор", building_bg);
        Err(if lock(&self.state).phase == Phase::Done {
            lang::pick(
                format!("the render stopped before it had built {what}: start it again"),
                format!("рендерът спря, преди да построи {bg}: започнете го отново"),
            )
        } else {
            lang::pick(
                format!(
                    "the render is still building {what}: the inspector can trace a sample once that is done"
                ),
                format!(
                    "рендерът още строи {bg}: инспекторът може да проследи проба, щом това свърши"
                ),
            )
        })
    }

    pub fn seed(&self) -> u64 {
        self.seed
    }

    /// Asks the job's thread to stop, whatever it is doing (it ends within
    /// moments).
    pub fn cancel(&self) {
        let mut state = lock(&self.state);
        if state.cancelled_at.is_none() && state.phase != Phase::Done {
            state.cancelled_at = Some(Instant::now());
            state.cancelled_in = Some(state.phase);
        }
        self.stop.store(true, Ordering::SeqCst);
    }

    /// Waits until a change newer than `version` is out, the job has ended,
    /// or `timeout` passed (a long poll: the page hears of a new picture at
    /// once, without asking over and over).
    pub fn wait_newer(&self, version: u64, timeout: Duration) {
        let state = lock(&self.state);
        let _ = self.changed.wait_timeout_while(state, timeout, |s| {
            s.version <= version && s.phase != Phase::Done
        });
    }

    /// The latest snapshot of every eye.
    pub fn snapshots(&self) -> Vec<Snapshot> {
        lock(&self.state).eyes.clone()
    }

    /// The pictures the page shows, one per eye: the coarse preview while
    /// the first pass is incomplete, else the picture.
    pub fn shown_images(&self) -> Vec<Option<Arc<Image>>> {
        lock(&self.state)
            .eyes
            .iter()
            .map(|e| e.preview.clone().or_else(|| e.image.clone()))
            .collect()
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
        let rendering = state
            .eyes
            .iter()
            .map(|e| e.elapsed)
            .max()
            .unwrap_or_default()
            .as_secs_f64();
        let elapsed = state
            .ended
            .unwrap_or_else(Instant::now)
            .saturating_duration_since(self.started);
        JobStatus {
            id: self.id,
            kind: self.kind,
            command: self.command.clone(),
            width: self.width,
            height: self.height,
            target_spp: self.target_spp,
            unit: self.units.0,
            samples_unit: self.units.1,
            spp: behind.samples as f64 / pixels,
            complete_spp: behind.complete_spp,
            samples,
            samples_per_second: if rendering > 0.0 {
                samples as f64 / rendering
            } else {
                0.0
            },
            elapsed: elapsed.as_secs_f64(),
            phase: state.phase,
            picture: state.eyes.iter().any(|e| e.image.is_some()),
            note: state.note.clone(),
            error: state.error.clone(),
            done: state.phase == Phase::Done,
            interrupted: state.interrupted,
            nonfinite: state.eyes.iter().map(|e| e.nonfinite).sum(),
            nonfinite_by_eye: state.eyes.iter().map(|e| e.nonfinite).collect(),
            race: self
                .race_reference
                .as_ref()
                .map(|(_, floor)| (state.race.clone(), *floor)),
            version: state.version,
            cancelled_in: state.cancelled_in,
            stopped_after_ms: state.stopped_after.map(|d| d.as_secs_f64() * 1e3),
        }
    }
}
