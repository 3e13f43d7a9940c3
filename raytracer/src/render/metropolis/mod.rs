//! Metropolis light transport in primary sample space (Kelemen,
//! Szirmay-Kalos, Antal and Csonka 2002; Veach and Guibas 1997 for the
//! Metropolis idea): many independent Markov chains over paths, rendered in
//! parallel and reproducibly.
//!
//! Lecture topic: "Metropolis light transport", the last of the unbiased
//! algorithms the lecture names. Path, light and bidirectional tracing draw
//! every path independently; Metropolis keeps a *current* path and proposes
//! a change to it, so that once a bright path is found (light through the
//! gap of a door), its neighbours are explored instead of being found again
//! by chance.
//!
//! # Which sampler, and why
//!
//! A path is the image of the random numbers `u ∈ [0, 1)^∞` an integrator
//! draws ([`PrimarySample`](crate::sampling::PrimarySample)); the chains move
//! those numbers and let the integrator build the path. Any [`Integrator`]
//! can serve; `lesson11 render --integrator mlt` runs the chains over
//! **bidirectional path tracing** ([`crate::integrator::Bdpt`], all its
//! strategies under MIS at once), as Kelemen et al. did and as pbrt-v4's
//! `MLTIntegrator` does, because:
//!
//! - a large step is one independent sample of the underlying integrator,
//!   and so is every bootstrap path: with BDPT they find the light that
//!   comes through a gap (its light subpaths pass the gap on their own),
//!   where most path-tracing samples of `door` bring nothing. The bootstrap's
//!   `b̂` and the chains' first states are only as good as that sampler;
//! - a small step moves the numbers of both subpaths at once, so a chain
//!   that found a light path through the gap walks along it on both sides.
//!   The camera subpath, the light subpath and the connections read
//!   [`Stream`](crate::sampling::Stream)s of their own (as in pbrt-v4's
//!   `MLTSampler`): a small step that makes the camera subpath longer or
//!   shorter still moves the light subpath's numbers only a little, where
//!   one sequence for all would have handed it other numbers and redrawn it
//!   (22.6 % of small steps on `cornell` at unlimited depth).
//!
//! The price is a dearer sample (a BDPT sample costs several path-tracing
//! samples); `lesson11 bench` prints both. pbrt-v4 instead picks one
//! strategy `(s, t)` per sample (Hachisuka et al.'s multiplexed MLT); we keep
//! the renderer's BDPT unchanged, which is simpler and shares its tests.
//!
//! # The estimator
//!
//! A state `x` gives contributions `g_j(x)` to pixels `j` (its own pixel and
//! the splats of `t = 1`) and the scalar `f(x) = Σ_j Y(g_j(x))`, the
//! luminance it brings. With `b = ∫ f(u) du` the mean of `f`, a chain in
//! equilibrium visits `x` with density `f(x) / b`, so
//! `I_j = W·H ∫ g_j = W·H · b · E_{f/b}[g_j / f]`: each chain splats `g/f`
//! ([`chain`]) and its image is scaled by `W·H · b̂ / N` after `N` steps.
//!
//! **Why it is unbiased, with the right normalization.** The bootstrap
//! ([`bootstrap`]) draws `n` independent paths, estimates
//! `b̂ = (1/n) Σ f(u_i)` and starts each chain at `u_i` with probability
//! `f(u_i) / Σ f`. Then for every function `φ`,
//! `E[b̂ · φ(x_0)] = E[(1/n) Σ_i f(u_i) φ(u_i)] = ∫ f φ`. The Metropolis step
//! leaves `f` invariant (detailed balance: `f(x) T(x→y) a(x→y)` is symmetric
//! in `x, y` for a symmetric proposal `T` and `a = min(1, f(y)/f(x))`), so
//! the same holds for every later state: `E[b̂ · φ(x_t)] = ∫ f φ`. With
//! `φ = g_j / f` every step's splat has mean `∫ g_j = I_j / (W·H)`: each
//! chain's image is unbiased after any number of steps — no burn-in to
//! throw away — provided `b̂` comes from the same bootstrap that chose the
//! start. (A chain started anywhere else, or scaled by another `b̂`, would be
//! biased until it forgot its start.) The expected-value splat replaces the
//! next state's `g/f` by its mean over the accept coin, which keeps the mean.
//!
//! **Why its noise looks different.** Consecutive states are neighbours
//! (small steps) or the same path again (a rejection), so a chain's errors
//! come in streaks and blobs the size of a path's footprint, not pixel by
//! pixel: not all noise is white. Per-pixel sample variances would miss it;
//! the noise is estimated from *independent chains* instead: the film gets
//! one sample per pixel per chain (that chain's estimate), so its mean is the
//! image and its variance image is the spread of the chains over their
//! number ([`crate::film::Film::variance_image`]), and the result keeps each
//! chain's tile means for tests of whole tiles. All chains share `b̂`: the
//! chains' spread is the noise *given* `b̂`, whose own relative error
//! ([`Bootstrap::relative_error`]) scales the whole image at once.
//!
//! # Determinism and interruption
//!
//! Chain `c`'s numbers come from `(seed, c, step)` through derived seeds
//! (its start, its step kinds and acceptances, its large and small steps);
//! bootstrap path `i` from `(seed, i)`. The bootstrap is added up in index
//! order and the chains are merged into the film in chain order (a reorder
//! buffer, as in [`super::render_pixels`]), so the image is the same bit for
//! bit on any number of threads. The number of chains is an option, not the
//! number of threads. On Ctrl-C (or [`super::request_interrupt`]) each chain
//! stops after its current step and is merged with the steps it made (its
//! image is unbiased at any length); chains not yet started are left out.
//! Interrupted during the bootstrap, the render returns no chain.
//!
//! # Watching
//!
//! [`render_metropolis_watched`] shows a watcher the film after the
//! bootstrap and after every chain it merges (a progressive front-end's
//! snapshots). Since chains are merged in chain order, the film after `k`
//! chains is the same whatever the threads, and after the last one it is
//! the render's film, bit for bit.

pub mod bootstrap;
pub mod chain;
pub mod merger;
pub mod parameters;

pub use bootstrap::Bootstrap;
pub use chain::{SplatWeights, acceptance, expected_value_splat};
pub use parameters::{Metropolis, ParameterError};

use super::{INTERRUPTED, RenderOptions, RenderStats, human, on_threads, progress_bar};
use crate::film::Film;
use crate::integrator::{Integrator, stop};
use crate::math::Color;
use crate::sampling::Sampler;
use crate::sampling::rng::mix64;
use crate::scene::Scene;
use chain::{ChainRun, ChainStreams, Moves, run_chain};
use indicatif::ProgressBar;
use merger::Merger;
use std::sync::Mutex;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::time::{Duration, Instant};

/// A finished (or interrupted) Metropolis render.
#[derive(Clone, Debug)]
pub struct MetropolisResult {
    /// One sample per pixel per chain (that chain's estimate): its image is
    /// the render, its variance image the chains' spread over their number.
    pub film: Film,
    /// `samples` counts mutations (steps); `elapsed` includes the bootstrap.
    pub stats: RenderStats,
    /// `None` if the render was interrupted during the bootstrap.
    pub bootstrap: Option<Bootstrap>,
    /// The chains merged into the film.
    pub chains: u32,
    /// Accepted steps over all steps.
    pub acceptance_rate: f64,
    /// Seconds of the bootstrap (included in `stats.elapsed`).
    pub bootstrap_seconds: f64,
    /// For each merged chain, in chain order, the mean of its image over
    /// each `tile_size × tile_size` tile, in the order of
    /// [`crate::metrics::tile_means`].
    pub chain_tile_means: Vec<Vec<Color>>,
}

/// Derived seeds of the streams of one render (named with every other
/// stream in [`crate::integrator::dimensions`]).
use crate::integrator::dimensions::{
    METROPOLIS_BOOTSTRAP_STREAM as BOOTSTRAP_STREAM, METROPOLIS_CONTROL_STREAM as CONTROL_STREAM,
    METROPOLIS_LARGE_STREAM as LARGE_STREAM, METROPOLIS_SMALL_STREAM as SMALL_STREAM,
    METROPOLIS_START_STREAM as START_STREAM,
};

fn stream(seed: u64, name: u64) -> u64 {
    mix64(seed ^ mix64(name.wrapping_mul(0x9e37_79b9_7f4a_7c15)))
}

/// Where a chain starts: which bootstrap path is chosen with `u`.
const START: crate::sampling::Draw<1> =
    crate::sampling::Draw::new("bootstrap path a chain starts at");

/// Renders `scene` by Metropolis light transport over `integrator`'s primary
/// sample space with `options.spp` mutations per pixel. Stops early on
/// Ctrl-C once [`super::install_interrupt_handler`] was called.
///
/// # Panics
/// If `metropolis` fails [`Metropolis::check`] (front-ends check first).
pub fn render_metropolis(
    scene: &Scene,
    integrator: &dyn Integrator,
    options: &RenderOptions,
    metropolis: &Metropolis,
) -> MetropolisResult {
    render_metropolis_with_stop(scene, integrator, options, metropolis, &INTERRUPTED)
}

/// [`render_metropolis`] that watches its own stop flag.
pub fn render_metropolis_with_stop(
    scene: &Scene,
    integrator: &dyn Integrator,
    options: &RenderOptions,
    metropolis: &Metropolis,
    stop: &AtomicBool,
) -> MetropolisResult {
    render_metropolis_watched(scene, integrator, options, metropolis, stop, &mut |_| {})
}

/// How far a Metropolis render has come, as [`render_metropolis_watched`]
/// shows it: once after the bootstrap (no chain merged yet), then after
/// every chain merged, in chain order.
pub struct MetropolisProgress<'a> {
    /// The merged chains, one sample per pixel each: its image is the
    /// estimate of those chains (unbiased after any number of them).
    pub film: &'a Film,
    /// The bootstrap that scales every chain and started them.
    pub bootstrap: &'a Bootstrap,
    /// Chains merged so far (those that made at least one step).
    pub chains: u32,
    /// Mutations (steps) of the merged chains, and how many were accepted.
    pub mutations: u64,
    pub accepted: u64,
    /// Wall-clock time since the render started (bootstrap included).
    pub elapsed: Duration,
}

/// [`render_metropolis_with_stop`] that shows `watch` the film after the
/// bootstrap and after every merged chain. `watch` runs while the chain
/// workers wait to merge: it should be quick (copy the image, not encode it).
///
/// # Panics
/// If `metropolis` fails [`Metropolis::check`] (front-ends check first).
pub fn render_metropolis_watched(
    scene: &Scene,
    integrator: &dyn Integrator,
    options: &RenderOptions,
    metropolis: &Metropolis,
    stop: &AtomicBool,
    watch: &mut (dyn FnMut(&MetropolisProgress) + Send),
) -> MetropolisResult {
    let start = Instant::now();
    let (w, h) = (scene.camera.width, scene.camera.height);
    let mutations = options.spp as u64 * w as u64 * h as u64;
    if let Err(e) = metropolis.check(mutations) {
        panic!("{e}");
    }
    let paths = metropolis.bootstrap_paths(w, h);
    let bar = progress_bar(options, paths + mutations, "paths and mutations");
    let seed = options.seed;
    let mut merged = None;
    let mut boot = None;
    let mut bootstrap_seconds = 0.0;
    let threads = on_threads(options.threads, || {
        let tick = |n| bar.inc(n);
        let b = bootstrap::bootstrap(
            scene,
            integrator,
            stream(seed, BOOTSTRAP_STREAM),
            paths,
            stop,
            &tick,
        );
        // Timed whether or not it ran to its end: an interrupted bootstrap
        // of 3 s was reported as "a 0.00 s bootstrap".
        bootstrap_seconds = start.elapsed().as_secs_f64();
        let Some(b) = b else {
            return;
        };
        let workers = rayon::current_num_threads()
            .min(metropolis.chains as usize)
            .max(1);
        let job = ChainJob {
            scene,
            integrator,
            metropolis,
            seed,
            bootstrap: &b,
            mutations,
            stop,
            next_chain: AtomicU64::new(0),
            ahead: 2 * workers as u64,
            merger: Mutex::new(Merger::new(w, h, options.tile_size.max(1), b.b)),
            bar: &bar,
            watch: Mutex::new(&mut *watch),
            start,
        };
        job.show(&job.merger.lock().expect("a chain worker panicked"));
        rayon::scope(|s| {
            for _ in 0..workers {
                s.spawn(|_| job.work());
            }
        });
        merged = Some(job.merger.into_inner().expect("a chain worker panicked"));
        boot = Some(b);
    });
    bar.finish_and_clear();
    let merger = merged.unwrap_or_else(|| Merger::new(w, h, 1, 0.0));
    let nonfinite = merger.nonfinite + boot.as_ref().map_or(0, |b| b.nonfinite);
    let stats = RenderStats {
        elapsed: start.elapsed(),
        samples: merger.steps,
        interrupted: merger.steps < mutations,
        nonfinite,
    };
    let result = MetropolisResult {
        film: merger.film,
        stats,
        bootstrap: boot,
        chains: merger.chains,
        acceptance_rate: merger.accepted as f64 / merger.steps.max(1) as f64,
        bootstrap_seconds,
        chain_tile_means: merger.tile_means,
    };
    if options.progress {
        eprintln!("{}", summary(options, metropolis, &result, threads));
    }
    result
}

/// Everything the chain workers share.
struct ChainJob<'a> {
    scene: &'a Scene,
    integrator: &'a dyn Integrator,
    metropolis: &'a Metropolis,
    seed: u64,
    bootstrap: &'a Bootstrap,
    mutations: u64,
    stop: &'a AtomicBool,
    next_chain: AtomicU64,
    /// How far ahead of the next chain to merge a worker may start one.
    ahead: u64,
    merger: Mutex<Merger>,
    bar: &'a ProgressBar,
    /// Shown every merge (see [`render_metropolis_watched`]).
    watch: Mutex<&'a mut (dyn FnMut(&MetropolisProgress) + Send)>,
    start: Instant,
}

impl ChainJob<'_> {
    /// Steps of chain `c`: an equal share, the first chains one more.
    fn steps(&self, c: u64) -> u64 {
        let k = self.metropolis.chains as u64;
        self.mutations / k + u64::from(c < self.mutations % k)
    }

    /// One worker: runs chains in increasing order until none is left or a
    /// stop is requested; every chain it takes is submitted.
    fn work(&self) {
        let lock = || self.merger.lock().expect("a chain worker panicked");
        let mut run = lock().spare.pop().unwrap_or_default();
        stop::watch(self.stop, || {
            while !self.stop.load(Ordering::Relaxed) {
                let c = self.next_chain.fetch_add(1, Ordering::Relaxed);
                if c >= self.metropolis.chains as u64 {
                    break;
                }
                // At most `ahead` chains wait to be merged (each holds a
                // W·H image): a worker far ahead of the slowest chain waits.
                while c >= lock().next + self.ahead && !self.stop.load(Ordering::Relaxed) {
                    std::thread::sleep(std::time::Duration::from_millis(1));
                }
                self.run(c, &mut run);
                run = lock().submit(c, run, |merger| self.show(merger));
            }
        });
    }

    /// Shows the watcher the film of the chains merged so far (called with
    /// the merger locked, so the watcher sees the merges in order).
    fn show(&self, merger: &Merger) {
        let mut watch = self.watch.lock().expect("a Metropolis watcher panicked");
        watch(&MetropolisProgress {
            film: &merger.film,
            bootstrap: self.bootstrap,
            chains: merger.chains,
            mutations: merger.steps,
            accepted: merger.accepted,
            elapsed: self.start.elapsed(),
        });
    }

    fn run(&self, c: u64, run: &mut ChainRun) {
        let seed = self.seed;
        let u = START.draw(&mut Sampler::new(stream(seed, START_STREAM), c, 0));
        let streams = ChainStreams {
            start: (stream(seed, BOOTSTRAP_STREAM), self.bootstrap.choose(u)),
            index: c,
            control: stream(seed, CONTROL_STREAM),
            large: stream(seed, LARGE_STREAM),
            small: stream(seed, SMALL_STREAM),
        };
        let moves = Moves {
            large_step_probability: self.metropolis.large_step_probability,
            mutation_size: self.metropolis.mutation_size,
        };
        const TICK: u64 = 1024;
        let mut since_tick = 0;
        let mut keep_going = || {
            since_tick += 1;
            if since_tick == TICK {
                self.bar.inc(TICK);
                since_tick = 0;
            }
            !self.stop.load(Ordering::Relaxed)
        };
        let steps = self.steps(c);
        run_chain(
            self.scene,
            self.integrator,
            streams,
            moves,
            steps,
            &mut keep_going,
            run,
        );
        self.bar.inc(run.steps % TICK);
    }
}

/// One line: what was rendered, the bootstrap's `b̂`, the acceptance rate,
/// how fast.
fn summary(
    options: &RenderOptions,
    metropolis: &Metropolis,
    r: &MetropolisResult,
    threads: usize,
) -> String {
    let s = &r.stats;
    let (w, h) = (r.film.width(), r.film.height());
    let chain_seconds = s.elapsed.as_secs_f64() - r.bootstrap_seconds;
    let rate = s.samples as f64 / chain_seconds.max(1e-9);
    let mut line = format!(
        "{}: {w}×{h}, Metropolis, {} mutations per pixel in {} chains (large steps {}, mutation size {})",
        options.label,
        options.spp,
        metropolis.chains,
        metropolis.large_step_probability,
        metropolis.mutation_size,
    );
    if let Some(b) = &r.bootstrap {
        line += &format!(
            ", b = {:.4} ± {:.1} % from {} paths, acceptance {:.0} %",
            b.b,
            100.0 * b.relative_error(),
            human(b.paths as f64),
            100.0 * r.acceptance_rate
        );
    }
    line += &format!(
        ", {} mutations in {:.2} s after a {:.2} s bootstrap ({} mutations/s, {threads} threads)",
        human(s.samples as f64),
        chain_seconds,
        r.bootstrap_seconds,
        human(rate)
    );
    if s.interrupted {
        line += ", INTERRUPTED";
    }
    if s.nonfinite > 0 {
        line += &format!(", {} NaN/inf/negative values dropped", s.nonfinite);
    }
    line
}
