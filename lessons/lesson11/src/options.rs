//! Options shared by every chapter: which scene, how big, how many samples.
//!
//! Two steps, as in ripgrep: clap keeps what the user typed ([`SceneArgs`]),
//! and [`SceneArgs::load`] turns it once into a checked scene and render
//! options, with errors that say what to do.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};

use anyhow::{Context, Result, bail};
use clap::Args;
use lang::Lang;
use raytracer::film::output::StagedFile;
use raytracer::render::{MemoryCap, RenderOptions, gib, memory_needed, thread_limit};
use raytracer::scene::{Scene, builtin};

/// Scene and sampling options common to the chapters.
#[derive(Args, Clone, Debug, Default)]
pub struct SceneArgs {
    /// A built-in scene name (see `lesson11 scenes`) or a path to a scene file (.toml).
    /// A built-in name wins over a file of that name in the current folder (pass ./NAME for the file).
    #[arg(long, short)]
    pub scene: Option<String>,
    /// Image width in pixels (default: the scene's).
    #[arg(long)]
    pub width: Option<u32>,
    /// Image height in pixels (default: the scene's).
    #[arg(long)]
    pub height: Option<u32>,
    /// Samples per pixel (default: the scene's).
    #[arg(long)]
    pub spp: Option<u32>,
    /// Seed of the random numbers: the same seed gives the same image, bit for bit.
    #[arg(long)]
    pub seed: Option<u64>,
    /// Worker threads (default: all cores; at most 4 per core, and at least 64 are allowed).
    /// The image does not depend on it.
    #[arg(long)]
    pub threads: Option<usize>,
    /// Output folder.
    #[arg(long, default_value = "out/lesson11")]
    pub out: PathBuf,
    /// Go ahead although the render needs more memory than the cap (half of the physical
    /// memory) or more work than the budget (1e10 rays, light paths or mutations at worst).
    #[arg(long)]
    pub force: bool,
}

impl SceneArgs {
    /// Loads the scene (`default` if none was named), applies the overrides
    /// and checks, before anything is rendered, that the threads and the
    /// memory are within bounds.
    pub fn load(&self, default: &str) -> Result<(Scene, RenderOptions)> {
        check_threads(self.threads)?;
        let name = self.scene.as_deref().unwrap_or(default);
        let mut scene = load_scene(name)?;
        let width = self.width.unwrap_or(scene.settings.width);
        let height = self.height.unwrap_or(scene.settings.height);
        if width == 0 || height == 0 {
            bail!(
                "{} {width}×{height}: {}",
                lang::pick(
                    "the image size must be positive, got",
                    "размерът на картината трябва да е положителен, а е"
                ),
                lang::pick(
                    "pass e.g. --width 256 --height 256",
                    "дайте например --width 256 --height 256"
                )
            );
        }
        check_memory(
            &lang::pick(
                format!("a {width}×{height} render"),
                format!("рендериране {width}×{height}"),
            ),
            memory_needed(width, height),
            lang::pick("--width and --height", "--width и --height"),
            self.force,
        )?;
        if width != scene.settings.width || height != scene.settings.height {
            scene.set_resolution(width, height);
        }
        if let Some(seed) = self.seed {
            scene.settings.seed = seed;
        }
        let spp = self.spp.unwrap_or(scene.settings.spp);
        if spp == 0 {
            bail!(lang::pick(
                "--spp must be at least 1",
                "--spp трябва да е поне 1"
            ));
        }
        scene.settings.spp = spp;
        let options = RenderOptions {
            spp,
            seed: scene.settings.seed,
            threads: self.threads,
            label: scene.name.clone(),
            ..RenderOptions::default()
        };
        Ok((scene, options))
    }
}

/// `--exposure`: stops in [−64, 64] (NaN would make the PNG black, and
/// beyond ±128 the factor 2^stops is 0 or infinite in `f32`).
pub fn check_exposure(stops: f32) -> Result<()> {
    if !(-64.0..=64.0).contains(&stops) {
        bail!(
            "{} {stops}",
            lang::pick(
                "--exposure must be a number of stops in [-64, 64] (+1 doubles the brightness), got",
                "--exposure трябва да е брой стъпки в [-64, 64] (+1 удвоява яркостта), а е"
            )
        );
    }
    Ok(())
}

/// `--threads`: at least 1 and at most [`thread_limit`].
pub fn check_threads(threads: Option<usize>) -> Result<()> {
    match threads {
        Some(0) => bail!(lang::pick(
            "--threads must be at least 1 (or left out to use every core)",
            "--threads трябва да е поне 1 (или да се пропусне, за да се ползват всички ядра)"
        )),
        Some(n) if n > thread_limit() => bail!(
            "{}",
            lang::fill(
                lang::pick(
                    "--threads {n} is more than the {limit} threads a render may use here \
                     (4 per core, at least 64)",
                    "--threads {n} е повече от {limit}-те нишки, които едно рендериране може да \
                     ползва тук (4 на ядро, поне 64)",
                ),
                &[("n", &n), ("limit", &thread_limit())]
            )
        ),
        _ => Ok(()),
    }
}

/// The most work a command line may ask for without `--force`: 10¹⁰ rays
/// (or light paths, or Metropolis mutations) in the worst case, some
/// minutes on two cores. One rule for every option that multiplies work
/// ([`check_work`]): naive recursion's branching, photon mapping's photons
/// and final gather, SPPM's photons per pass, the VPLs' shadow rays, the
/// irradiance cache's rays, Metropolis's mutations and bootstrap.
pub const WORK_BUDGET: f64 = 1e10;

/// Refuses, in one line naming the options to lower, `what` if it would
/// trace more than [`WORK_BUDGET`] `units` ("rays", "light paths") at
/// worst, unless `force`.
pub fn check_work(what: &str, count: f64, units: &str, options: &str, force: bool) -> Result<()> {
    if count > WORK_BUDGET && !force {
        bail!(
            "{}",
            lang::fill(
                lang::pick(
                    "{what} would trace up to {count} {units}, more than the budget of \
                     {budget}: lower {options}, or pass --force",
                    "{what} би проследил(а) до {count} {units}, повече от бюджета от \
                     {budget}: намалете {options} или дайте --force",
                ),
                &[
                    ("what", &what),
                    ("count", &format!("{count:.2e}")),
                    ("units", &units),
                    ("budget", &format!("{WORK_BUDGET:.0e}")),
                    ("options", &options),
                ]
            )
        );
    }
    Ok(())
}

/// Refuses, in one line naming the options to change, what needs more memory
/// than the cap ([`MemoryCap::of_this_machine`]). With `--force` the cap is
/// the whole physical memory instead of half of it.
pub fn check_memory(what: &str, bytes: Option<u64>, options: &str, force: bool) -> Result<()> {
    let usual = MemoryCap::of_this_machine();
    let forced = MemoryCap {
        bytes: usual.bytes.saturating_mul(2),
        source: "with --force, twice the usual cap".into(),
    };
    let cap = if force { &forced } else { &usual };
    cap.check(what, bytes).map_err(|e| {
        // Suggest --force only where it would help.
        let helps = !force && forced.check(what, bytes).is_ok();
        let advice = match (lang::current(), helps) {
            (Lang::En, true) => format!("choose smaller {options}, or pass --force"),
            (Lang::En, false) => format!("choose smaller {options}"),
            (Lang::Bg, true) => format!("изберете по-малки {options} или дайте --force"),
            (Lang::Bg, false) => format!("изберете по-малки {options}"),
        };
        let e = match lang::current() {
            Lang::En => e,
            Lang::Bg => memory_bg(what, bytes, cap, force),
        };
        anyhow::anyhow!("{e}: {advice}")
    })
}

/// [`MemoryCap::check`]'s refusal in Bulgarian.
fn memory_bg(what: &str, bytes: Option<u64>, cap: &MemoryCap, force: bool) -> String {
    let Some(bytes) = bytes else {
        return format!("{what} иска повече от 2^64 байта памет, повече от всяка машина");
    };
    let source = if force {
        "с --force: двойно обичайната граница"
    } else if cap.source.contains("/proc/meminfo") && !cap.source.starts_with("a fixed") {
        "половината от физическата памет, по /proc/meminfo"
    } else {
        "фиксирани 4 GiB (няма /proc/meminfo, от който да се прочете физическата памет)"
    };
    format!(
        "{what} иска около {} памет, повече от границата от {} ({source})",
        gib(bytes),
        gib(cap.bytes)
    )
}

/// A built-in scene by name, or a scene file by path. A built-in name wins
/// over a file of that name in the current folder (a note says so once):
/// `./cornell` names the file.
pub fn load_scene(name: &str) -> Result<Scene> {
    static NOTED: AtomicBool = AtomicBool::new(false);
    let path = Path::new(name);
    let looks_like_file = name.ends_with(".toml") || name.contains('/') || name.contains('\\');
    if looks_like_file {
        return Ok(Scene::load(path)?);
    }
    if builtin(name).is_some() {
        if path.exists() && !NOTED.swap(true, Ordering::Relaxed) {
            eprintln!(
                "{}",
                lang::fill(
                    lang::pick(
                        "note: `{name}` is the built-in scene; to load the file {name} of this \
                         folder, pass --scene ./{name}",
                        "бележка: `{name}` е вградената сцена; за файла {name} от тази папка \
                         дайте --scene ./{name}",
                    ),
                    &[("name", &name)]
                )
            );
        }
        return Ok(Scene::builtin(name)?);
    }
    if path.is_file() {
        return Ok(Scene::load(path)?);
    }
    Ok(Scene::builtin(name)?)
}

/// Creates the output folder `dir` (and its parents) and checks that files
/// can be written in it, before any work is done; errors name `dir` and the
/// option (`--out`, `--to`) that chose it.
pub fn create_dir(dir: &Path) -> Result<()> {
    create_dir_for(dir, "--out")
}

/// [`create_dir`] for a folder chosen by the option `flag`.
pub fn create_dir_for(dir: &Path, flag: &str) -> Result<()> {
    if dir.exists() && !dir.is_dir() {
        bail!(
            "{}",
            lang::fill(
                lang::pick(
                    "the output folder {dir} is a file, not a folder: choose another with {flag}",
                    "папката за резултатите {dir} е файл, а не папка: изберете друга с {flag}",
                ),
                &[("dir", &dir.display()), ("flag", &flag)]
            )
        );
    }
    std::fs::create_dir_all(dir).with_context(|| {
        lang::fill(
            lang::pick(
                "cannot create the output folder {dir}: choose another with {flag}",
                "не мога да създам папката за резултатите {dir}: изберете друга с {flag}",
            ),
            &[("dir", &dir.display()), ("flag", &flag)],
        )
    })?;
    // A staged file that is never committed: created, then removed.
    StagedFile::write(dir.join("write-test"), "a test file", |_| Ok(()))
        .map(drop)
        .with_context(|| {
            lang::fill(
                lang::pick(
                    "cannot write into the output folder {dir}: choose another with {flag}",
                    "не мога да пиша в папката за резултатите {dir}: изберете друга с {flag}",
                ),
                &[("dir", &dir.display()), ("flag", &flag)],
            )
        })
}
