//! The render loop: many pixel samples, in parallel, reproducible bit for bit.
//!
//! A pixel's value is the Monte Carlo estimate `(1/N) Σ_k X_k` of the lecture;
//! this loop draws the samples `X_k` by calling the integrator's sample
//! function for every pixel `N = spp` times and gathers them on a [`Film`].
//!
//! **Determinism.** The random numbers of sample `k` of pixel `(x, y)` come
//! from `Sampler::new(seed, y·width + x, k)`, whichever thread computes it.
//! The work is cut into *units*: a tile of `tile_size²` pixels times a *pass*
//! of [`SAMPLES_PER_PASS`] samples, numbered pass by pass and, within a pass,
//! tile by tile in raster order. Each unit gathers its samples and splats in a
//! private [`FilmTile`], and the tiles are merged into the film strictly in
//! unit order (a small reorder buffer holds units that finished early). So
//! every floating-point addition into the film happens in the same order on 1
//! or 64 threads, and the image is identical to the last bit for the same
//! seed, spp and tile size.
//!
//! Passes make the image converge evenly: an interrupted render is a
//! complete image with fewer samples, not a half-finished one.
//!
//! **Watching.** [`render_pixels_watched`] shows a watcher the film after
//! every merged unit (a progressive front-end's snapshots). When a pass is
//! complete the film is, bit for bit, the film of a render of `16·k` spp: its
//! first units are the same units, merged in the same order.
//!
//! [`render_strategies`] renders the image of each strategy of bidirectional
//! path tracing apart (the lesson's slides).
//!
//! **Interruption.** [`install_interrupt_handler`] makes Ctrl-C, SIGTERM and
//! SIGHUP set a global flag (a second one quits). The loop checks it before
//! every pixel sample, and integrators whose samples can be long (naive
//! recursion, unlimited paths) check it inside a sample through
//! [`crate::integrator::stop`]: such a sample is dropped whole. The loop then
//! stops and keeps every sample already computed: pixels may hold different
//! sample counts (some none at all, [`crate::film::Film::unsampled_pixels`]),
//! each pixel's mean is still right, and `stats.interrupted` is set.
//!
//! **Resources.** [`thread_limit`] caps the worker threads a command line may
//! ask for, and [`memory_needed`] with [`MemoryCap`] lets a front-end refuse
//! an image that would not fit in memory before allocating it.

pub mod metropolis;
pub mod sppm;
pub mod strategies;

pub use metropolis::{Metropolis, MetropolisResult, render_metropolis};
pub use sppm::{SppmResult, render_sppm};
pub use strategies::render_strategies;

use crate::film::{Film, FilmTile, Splat};
use crate::integrator::{Integrator, stop};
use crate::math::{Color, UVec2};
use crate::sampling::Sampler;
use crate::scene::{RenderSettings, Scene};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::collections::VecDeque;
use std::io::IsTerminal;
use std::ops::Range;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Mutex, Once};
use std::time::{Duration, Instant};

/// The number of samples per pixel in one pass over the image. Part of the
/// determinism contract: the grouping of the floating-point sums depends on it.
pub const SAMPLES_PER_PASS: u32 = 16;

/// How to render.
#[derive(Clone, Debug, PartialEq)]
pub struct RenderOptions {
    /// Samples per pixel.
    pub spp: u32,
    /// The seed of every random number.
    pub seed: u64,
    /// Worker threads; `None` uses rayon's global pool (all cores).
    pub threads: Option<usize>,
    /// Tile edge in pixels (part of the determinism contract, like the seed).
    pub tile_size: u32,
    /// Show a progress bar (only if stderr is a terminal) and print a summary.
    pub progress: bool,
    /// A name for the progress bar and the summary.
    pub label: String,
}

impl Default for RenderOptions {
    fn default() -> Self {
        RenderOptions {
            spp: 16,
            seed: 0,
            threads: None,
            tile_size: 16,
            progress: true,
            label: String::from("render"),
        }
    }
}

impl From<&RenderSettings> for RenderOptions {
    /// The options a scene asks for: its samples per pixel and seed, the
    /// defaults for the rest.
    fn from(settings: &RenderSettings) -> Self {
        RenderOptions {
            spp: settings.spp,
            seed: settings.seed,
            ..Default::default()
        }
    }
}

/// What a render cost.
#[derive(Clone, Debug, PartialEq)]
pub struct RenderStats {
    /// Wall-clock time of the loop.
    pub elapsed: Duration,
    /// Pixel samples computed (all of them stored on the film).
    pub samples: u64,
    /// True if the loop stopped before computing every sample.
    pub interrupted: bool,
    /// Samples and splats rejected as NaN, infinite or negative.
    pub nonfinite: u64,
}

impl RenderStats {
    /// Pixel samples per second of wall-clock time (0 if no time elapsed).
    pub fn samples_per_second(&self) -> f64 {
        let t = self.elapsed.as_secs_f64();
        if t > 0.0 {
            self.samples as f64 / t
        } else {
            0.0
        }
    }
}

/// The film and the statistics of a finished (or interrupted) render.
#[derive(Clone, Debug)]
pub struct RenderResult {
    pub film: Film,
    pub stats: RenderStats,
}

pub static INTERRUPTED: AtomicBool = AtomicBool::new(false);
static HANDLER: Once = Once::new();

/// What the first signal says (see [`on_interrupt_say`]).
static INTERRUPT_MESSAGE: Mutex<&str> = Mutex::new(
    "interrupted: stopping and keeping the samples computed so far (interrupt again to quit)",
);

/// Makes Ctrl-C (SIGINT), SIGTERM and SIGHUP request a clean stop of the
/// running render (see [`interrupted`]): the samples computed so far are
/// kept and written. A second signal exits the process at once with status
/// 130 (files are written atomically, so none is left half-written, and the
/// temporaries of those being written are removed first:
/// [`crate::film::output::exit_removing_staged_files`]).
/// Calling it again does nothing. If the handler cannot be installed (another
/// one exists), a warning is printed and the signals keep their default effect.
pub fn install_interrupt_handler() {
    HANDLER.call_once(|| {
        let installed = ctrlc::set_handler(|| {
            if INTERRUPTED.swap(true, Ordering::SeqCst) {
                eprintln!("\n{}", words().interrupted_twice);
                crate::film::output::exit_removing_staged_files(130);
            }
            let message = *INTERRUPT_MESSAGE
                .lock()
                .unwrap_or_else(|poisoned| poisoned.into_inner());
            eprintln!("\n{message}");
        });
        if let Err(e) = installed {
            eprintln!("warning: cannot install the Ctrl-C handler: {e}");
        }
    });
}

/// The words of a render's summary line and progress bar. The renderer
/// knows no language: the program above may hand it its own words once
/// ([`say_in`]), as it hands it what Ctrl-C says ([`on_interrupt_say`]);
/// the numbers and units (spp, s, ×) stay as they are.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Words {
    /// "samples": the unit of work counted.
    pub samples: &'static str,
    /// "in", between the samples and the seconds they took.
    pub took: &'static str,
    /// "threads".
    pub threads: &'static str,
    /// "INTERRUPTED".
    pub interrupted: &'static str,
    /// "NaN/inf/negative values dropped", after their number.
    pub dropped: &'static str,
    /// "interrupted twice: exiting without writing".
    pub interrupted_twice: &'static str,
}

/// The renderer's own words.
pub const ENGLISH: Words = Words {
    samples: "samples",
    took: "in",
    threads: "threads",
    interrupted: "INTERRUPTED",
    dropped: "NaN/inf/negative values dropped",
    interrupted_twice: "interrupted twice: exiting without writing",
};

static WORDS: Mutex<Words> = Mutex::new(ENGLISH);

/// Makes every later summary line and progress bar use `words`.
pub fn say_in(words: Words) {
    *WORDS
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner()) = words;
}

/// The words in use ([`ENGLISH`] unless [`say_in`] chose others).
pub fn words() -> Words {
    *WORDS
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner())
}

/// Makes the first Ctrl-C say `message` instead of the render's "keeping
/// the samples computed so far" (a command that renders nothing, such as
/// watching files, says what a stop means for it).
pub fn on_interrupt_say(message: &'static str) {
    *INTERRUPT_MESSAGE
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner()) = message;
}

/// True once Ctrl-C (or [`request_interrupt`]) asked renders to stop.
pub fn interrupted() -> bool {
    INTERRUPTED.load(Ordering::SeqCst)
}

/// The flag Ctrl-C sets, for work outside the render loop that watches a
/// stop flag of its own (photon tracing, the irradiance cache).
pub fn interrupt_flag() -> &'static AtomicBool {
    &INTERRUPTED
}

/// Clears the interrupt flag (e.g. to go on with the next image of a batch).
pub fn reset_interrupt() {
    INTERRUPTED.store(false, Ordering::SeqCst);
}

/// Sets the interrupt flag as Ctrl-C would (for tests and front-ends).
pub fn request_interrupt() {
    INTERRUPTED.store(true, Ordering::SeqCst);
}

/// Renders a `width × height` image with `options.spp` samples per pixel:
/// `sample(pixel, sampler, splats)` returns one radiance estimate of `pixel`
/// and may push splats (contributions to other pixels, normalized by the film
/// as pbrt's `1/spp`, see [`crate::film`]). Stops early on Ctrl-C once
/// [`install_interrupt_handler`] was called, or after [`request_interrupt`].
pub fn render_pixels<F>(width: u32, height: u32, options: &RenderOptions, sample: F) -> RenderResult
where
    F: Fn(UVec2, &mut Sampler, &mut Vec<Splat>) -> Color + Sync,
{
    render_pixels_with_stop(width, height, options, &INTERRUPTED, sample)
}

/// Renders `scene` with `integrator`: every pixel sample of the scene's
/// camera resolution is one call of [`Integrator::sample`].
pub fn render(scene: &Scene, integrator: &dyn Integrator, options: &RenderOptions) -> RenderResult {
    render_pixels(
        scene.camera.width,
        scene.camera.height,
        options,
        |pixel, sampler, splats| integrator.sample(scene, pixel, sampler, splats),
    )
}

/// [`render_pixels`] that watches its own stop flag instead of the global
/// interrupt flag (a cancel button, or a test that must not disturb others).
pub fn render_pixels_with_stop<F>(
    width: u32,
    height: u32,
    options: &RenderOptions,
    stop: &AtomicBool,
    sample: F,
) -> RenderResult
where
    F: Fn(UVec2, &mut Sampler, &mut Vec<Splat>) -> Color + Sync,
{
    render_pixels_watched(width, height, options, stop, sample, &mut |_| {})
}

/// How far a render has come, as [`render_pixels_watched`] shows it.
pub struct Progress<'a> {
    /// The film with every unit merged so far (pixels of the pass under way
    /// may hold 16 samples more than the others).
    pub film: &'a Film,
    /// Samples per pixel of the passes merged so far: `16 ·` their number, or
    /// the render's spp once its last (maybe partial) pass is merged.
    pub complete_spp: u32,
    /// True when this merge completed a pass (or the render): the film then
    /// equals, bit for bit, the film of a render with `spp = complete_spp`
    /// and the same seed and tile size.
    pub pass_complete: bool,
    /// Wall-clock time since the render started.
    pub elapsed: Duration,
}

/// [`render_pixels_with_stop`] that shows `watch` the film after every unit
/// it merges. `watch` runs while the workers wait to merge their next tiles:
/// it should be quick (copy the image, not encode it).
pub fn render_pixels_watched<F>(
    width: u32,
    height: u32,
    options: &RenderOptions,
    stop: &AtomicBool,
    sample: F,
    watch: &mut (dyn FnMut(&Progress) + Send),
) -> RenderResult
where
    F: Fn(UVec2, &mut Sampler, &mut Vec<Splat>) -> Color + Sync,
{
    let per_sample = |unit: &Unit, tile: &mut FilmTile, stop: &AtomicBool| {
        render_unit_by_samples(unit, tile, stop, &sample)
    };
    render_units_watched(width, height, options, stop, per_sample, watch)
}

/// One unit of work (see the module doc): a tile and a range of sample
/// indices, with what a renderer needs to address its random numbers.
#[derive(Clone, Debug)]
pub struct Unit {
    /// The tile's first pixel and its size.
    pub origin: UVec2,
    pub size: UVec2,
    /// The sample indices `k` of this pass.
    pub samples: Range<u32>,
    /// The render's seed and image width: sample `k` of pixel `(x, y)` draws
    /// from `Sampler::new(seed, y·width + x, k)`.
    pub seed: u64,
    pub width: u32,
}

impl Unit {
    /// The pixels of the tile in raster order.
    pub fn pixels(&self) -> impl Iterator<Item = UVec2> + '_ {
        let (o, s) = (self.origin, self.size);
        (o.y..o.y + s.y).flat_map(move |y| (o.x..o.x + s.x).map(move |x| UVec2::new(x, y)))
    }

    /// The sampler of sample `k` of `pixel`.
    #[inline]
    pub fn sampler(&self, pixel: UVec2, k: u32) -> Sampler {
        let index = pixel.y as u64 * self.width as u64 + pixel.x as u64;
        Sampler::new(self.seed, index, k as u64)
    }
}

/// The render loop of [`render_pixels_watched`] for a renderer that takes a
/// whole unit at a time (the wavefront engine traces all the unit's paths in
/// lockstep): `render_unit(unit, tile, stop)` fills the (reset) tile with the
/// unit's samples and returns how many it took. To keep the determinism
/// contract it must add each pixel's samples in increasing `k`, pixels in
/// raster order, as the per-sample loop does, and may stop early (keeping
/// only whole samples) once `stop` is set.
pub fn render_units_watched<U>(
    width: u32,
    height: u32,
    options: &RenderOptions,
    stop: &AtomicBool,
    render_unit: U,
    watch: &mut (dyn FnMut(&Progress) + Send),
) -> RenderResult
where
    U: Fn(&Unit, &mut FilmTile, &AtomicBool) -> u64 + Sync,
{
    let sample = &render_unit;
    let start = Instant::now();
    let layout = Layout::new(width, height, options.tile_size, options.spp);
    let expected = width as u64 * height as u64 * options.spp as u64;
    let bar = progress_bar(options, expected, words().samples);
    let job = Job {
        layout,
        seed: options.seed,
        sample: &sample,
        stop,
        next_unit: AtomicUsize::new(0),
        merger: Mutex::new(Merger {
            film: Film::new(width, height),
            next: 0,
            pending: VecDeque::new(),
            spare: Vec::new(),
            watch,
            start,
        }),
        bar: &bar,
    };
    let threads = on_threads(options.threads, || {
        let workers = rayon::current_num_threads().min(job.layout.units).max(1);
        rayon::scope(|s| {
            for _ in 0..workers {
                s.spawn(|_| job.work());
            }
        });
    });
    let merger = job.merger.into_inner().expect("a render worker panicked");
    debug_assert!(merger.pending.iter().all(Option::is_none));
    let film = merger.film;
    let stats = RenderStats {
        elapsed: start.elapsed(),
        samples: film.total_samples(),
        interrupted: film.total_samples() < expected,
        nonfinite: film.nonfinite_count(),
    };
    bar.finish_and_clear();
    if options.progress {
        eprintln!("{}", summary(options, width, height, threads, &stats));
    }
    RenderResult { film, stats }
}

/// Runs `run` in a pool of `threads` worker threads (at most
/// [`thread_limit`]), or in rayon's global pool for `None` or if the pool
/// cannot be made (with a warning); returns the number of threads it had.
pub fn on_threads(threads: Option<usize>, run: impl FnOnce() + Send) -> usize {
    match threads.map(|n| n.clamp(1, thread_limit())) {
        None => {
            run();
            rayon::current_num_threads()
        }
        Some(n) => match rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .thread_name(|i| format!("render-{i}"))
            .build()
        {
            Ok(pool) => {
                pool.install(run);
                n
            }
            Err(e) => {
                eprintln!("warning: cannot start {n} render threads ({e}); using the global pool");
                run();
                rayon::current_num_threads()
            }
        },
    }
}

/// The most worker threads a render uses: four per core, and at least 64
/// (more only cost memory and switching; [`render_pixels`] uses at most this
/// many whatever [`RenderOptions::threads`] says).
pub fn thread_limit() -> usize {
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    (4 * cores).max(64)
}

/// Bytes a render of `width × height` pixels needs at its peak, whatever the
/// integrator (`None` if the number does not even fit in 64 bits): the
/// film's sums (`f64` sum and square per channel and a count, 56 bytes), the
/// sums of splats (48), the mean and variance images (12 each), the 8-bit
/// PNG bytes (3) and the EXR writer's copy (12); tiles are small.
pub fn memory_needed(width: u32, height: u32) -> Option<u64> {
    const BYTES_PER_PIXEL: u64 = 56 + 48 + 12 + 12 + 3 + 12;
    (width as u64)
        .checked_mul(height as u64)?
        .checked_mul(BYTES_PER_PIXEL)
}

/// How much memory one command may take, and where that figure comes from.
#[derive(Clone, Debug, PartialEq)]
pub struct MemoryCap {
    pub bytes: u64,
    /// E.g. "half of the 23.4 GiB of physical memory, from /proc/meminfo".
    pub source: String,
}

impl MemoryCap {
    /// Half of the physical memory (`MemTotal` of `/proc/meminfo`) where it
    /// can be read, else a fixed 4 GiB: the other half is left to the system
    /// and to other programs.
    pub fn of_this_machine() -> MemoryCap {
        let total = std::fs::read_to_string("/proc/meminfo")
            .ok()
            .and_then(|text| {
                let line = text.lines().find(|l| l.starts_with("MemTotal:"))?;
                let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
                kib.checked_mul(1024)
            });
        match total {
            Some(total) => MemoryCap {
                bytes: total / 2,
                source: format!(
                    "half of the {} of physical memory, from /proc/meminfo",
                    gib(total)
                ),
            },
            None => MemoryCap {
                bytes: 4 << 30,
                source: "a fixed 4 GiB (no /proc/meminfo to read the physical memory from)"
                    .to_string(),
            },
        }
    }

    /// `Err` with one line naming `what` needs `bytes` (`None`: more than 2⁶⁴)
    /// if that is over the cap.
    pub fn check(&self, what: &str, bytes: Option<u64>) -> Result<(), String> {
        match bytes {
            Some(b) if b <= self.bytes => Ok(()),
            Some(b) => Err(format!(
                "{what} needs about {} of memory, more than the cap of {} ({})",
                gib(b),
                gib(self.bytes),
                self.source
            )),
            None => Err(format!(
                "{what} needs more than 2^64 bytes of memory, more than any machine has"
            )),
        }
    }
}

/// `bytes` in GiB with one decimal (`0.1 GiB` at least, for readability).
pub fn gib(bytes: u64) -> String {
    let g = bytes as f64 / (1u64 << 30) as f64;
    if g >= 1000.0 {
        format!("{g:.0} GiB")
    } else {
        format!("{:.1} GiB", g.max(0.1))
    }
}

/// How the image is cut into units of work (see the module doc).
struct Layout {
    width: u32,
    height: u32,
    tile: u32,
    tiles_x: u32,
    tiles: usize,
    spp: u32,
    units: usize,
}

impl Layout {
    fn new(width: u32, height: u32, tile_size: u32, spp: u32) -> Self {
        let tile = tile_size.max(1);
        let tiles_x = width.div_ceil(tile);
        let tiles = tiles_x as usize * height.div_ceil(tile) as usize;
        let passes = spp.div_ceil(SAMPLES_PER_PASS) as usize;
        Layout {
            width,
            height,
            tile,
            tiles_x,
            tiles,
            spp,
            units: tiles * passes,
        }
    }

    /// Unit `u`: the tile's origin and size, and the range of sample indices.
    fn unit(&self, u: usize) -> (UVec2, UVec2, Range<u32>) {
        let (pass, tile) = ((u / self.tiles) as u32, (u % self.tiles) as u32);
        let origin = UVec2::new(tile % self.tiles_x, tile / self.tiles_x) * self.tile;
        let size = UVec2::splat(self.tile).min(UVec2::new(self.width, self.height) - origin);
        let first = pass * SAMPLES_PER_PASS;
        (
            origin,
            size,
            first..(first + SAMPLES_PER_PASS).min(self.spp),
        )
    }
}

/// Merges finished tiles into the film in unit order.
struct Merger<'w> {
    film: Film,
    /// The next unit to merge.
    next: usize,
    /// Finished units `next, next+1, …` (`None`: not finished yet).
    pending: VecDeque<Option<FilmTile>>,
    /// Merged tiles, kept for reuse.
    spare: Vec<FilmTile>,
    /// Shown the film after every merge.
    watch: &'w mut (dyn FnMut(&Progress) + Send),
    start: Instant,
}

impl Merger<'_> {
    /// Takes finished unit `u`, merges every unit that is now next in line,
    /// showing the watcher the film after each, and hands back an empty tile for the
    /// worker's next unit.
    fn submit(&mut self, u: usize, tile: FilmTile, layout: &Layout) -> FilmTile {
        let slot = u - self.next;
        if self.pending.len() <= slot {
            self.pending.resize_with(slot + 1, || None);
        }
        self.pending[slot] = Some(tile);
        while let Some(Some(_)) = self.pending.front() {
            let tile = self.pending.pop_front().flatten().expect("checked above");
            self.film.merge_tile(&tile);
            self.spare.push(tile);
            self.next += 1;
            self.show(layout);
        }
        self.spare.pop().unwrap_or_else(|| self.new_tile())
    }

    /// Calls the watcher. A pass counts as complete only if every pixel has
    /// its samples (a unit cut short by a stop request is merged too).
    fn show(&mut self, layout: &Layout) {
        let passes = (self.next / layout.tiles.max(1)) as u32;
        let complete_spp = passes.saturating_mul(SAMPLES_PER_PASS).min(layout.spp);
        let pixels = layout.width as u64 * layout.height as u64;
        let pass_complete = self.next % layout.tiles.max(1) == 0
            && self.film.total_samples() == pixels * complete_spp as u64;
        (self.watch)(&Progress {
            film: &self.film,
            complete_spp,
            pass_complete,
            elapsed: self.start.elapsed(),
        });
    }

    fn new_tile(&self) -> FilmTile {
        let size = UVec2::new(self.film.width(), self.film.height());
        FilmTile::new(size, UVec2::ZERO, UVec2::ZERO)
    }
}

/// Everything the workers share.
struct Job<'a, F> {
    layout: Layout,
    seed: u64,
    sample: &'a F,
    stop: &'a AtomicBool,
    next_unit: AtomicUsize,
    merger: Mutex<Merger<'a>>,
    bar: &'a ProgressBar,
}

impl<F> Job<'_, F>
where
    F: Fn(&Unit, &mut FilmTile, &AtomicBool) -> u64 + Sync,
{
    /// One worker: takes units in increasing order until none is left or a
    /// stop is requested. Units are handed out in order, so the reorder buffer
    /// stays about as small as the number of workers.
    fn work(&self) {
        let lock = || self.merger.lock().expect("a render worker panicked");
        let mut tile = {
            let mut m = lock();
            m.spare.pop().unwrap_or_else(|| m.new_tile())
        };
        // Long samples see the stop flag too (see `integrator::stop`).
        stop::watch(self.stop, || {
            while !self.stop.load(Ordering::Relaxed) {
                let u = self.next_unit.fetch_add(1, Ordering::Relaxed);
                if u >= self.layout.units {
                    break;
                }
                // Once taken, a unit is always submitted (maybe partly done), so
                // the units merged are exactly 0..(last taken).
                let done = self.render_unit(u, &mut tile);
                self.bar.inc(done);
                tile = lock().submit(u, tile, &self.layout);
            }
        });
    }

    /// Computes unit `u` into `tile`; returns the number of samples taken.
    fn render_unit(&self, u: usize, tile: &mut FilmTile) -> u64 {
        let (origin, size, samples) = self.layout.unit(u);
        tile.reset(origin, size);
        let unit = Unit {
            origin,
            size,
            samples,
            seed: self.seed,
            width: self.layout.width,
        };
        (self.sample)(&unit, tile, self.stop)
    }
}

/// The per-sample loop over one unit: one call of `sample` per pixel sample.
fn render_unit_by_samples<F>(unit: &Unit, tile: &mut FilmTile, stop: &AtomicBool, sample: &F) -> u64
where
    F: Fn(UVec2, &mut Sampler, &mut Vec<Splat>) -> Color + Sync,
{
    let (origin, size) = (unit.origin, unit.size);
    let mut done = 0;
    for y in origin.y..origin.y + size.y {
        for x in origin.x..origin.x + size.x {
            let pixel = UVec2::new(x, y);
            for k in unit.samples.clone() {
                if stop.load(Ordering::Relaxed) {
                    return done;
                }
                let mut sampler = unit.sampler(pixel, k);
                // A sample cut short by a stop request is dropped whole.
                let kept = tile.record_unless_abandoned(pixel, |splats| {
                    let value = sample(pixel, &mut sampler, splats);
                    (!stop::take_abandoned()).then_some(value)
                });
                if !kept {
                    return done;
                }
                done += 1;
            }
        }
    }
    done
}

/// The progress bar's line for work counted in `unit`s.
pub fn progress_template(unit: &str) -> String {
    format!(
        "{{prefix}} {{wide_bar}} {{percent:>3}}% {{human_pos}}/{{human_len}} {unit}, {{per_sec:0}}, ETA {{eta}}"
    )
}

/// A progress bar counting samples (or another `unit` of work), with rate
/// and ETA; hidden unless requested and stderr is a terminal.
pub fn progress_bar(options: &RenderOptions, samples: u64, unit: &str) -> ProgressBar {
    if !options.progress || !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let style = ProgressStyle::with_template(&progress_template(unit))
        .unwrap_or_else(|_| ProgressStyle::default_bar());
    ProgressBar::with_draw_target(Some(samples), ProgressDrawTarget::stderr())
        .with_style(style)
        .with_prefix(options.label.clone())
}

/// One line: what was rendered, how fast, and anything unusual.
pub fn summary(options: &RenderOptions, w: u32, h: u32, threads: usize, s: &RenderStats) -> String {
    let words = words();
    let mut line = format!(
        "{}: {w}×{h}, {} spp, {} {samples} {took} {:.2} s ({} {samples}/s, {threads} {threads_word})",
        options.label,
        options.spp,
        human(s.samples as f64),
        s.elapsed.as_secs_f64(),
        human(s.samples_per_second()),
        samples = words.samples,
        took = words.took,
        threads_word = words.threads,
    );
    if s.interrupted {
        line += &format!(", {}", words.interrupted);
    }
    if s.nonfinite > 0 {
        line += &format!(", {} {}", s.nonfinite, words.dropped);
    }
    line
}

/// `1234567` → `"1.23M"`.
pub fn human(x: f64) -> String {
    match x {
        x if x >= 1e9 => format!("{:.2}G", x / 1e9),
        x if x >= 1e6 => format!("{:.2}M", x / 1e6),
        x if x >= 1e3 => format!("{:.1}k", x / 1e3),
        x => format!("{x:.0}"),
    }
}
