//! Rendering to files: PNG to look at, EXR to measure, and the variance of
//! each pixel's mean, written where a chapter or a command asks.
//!
//! The files of one picture are replaced together: all are written to
//! temporary files first and only then renamed over the old ones (see
//! `raytracer::film::output`), so a full disk, a kill or an error leaves the
//! previous picture whole.
//!
//! A picture an interrupted render wrote has a note beside it,
//! `stem.png.partial` ([`partial_note`]), saying how much of the render it
//! holds ("0.56 of 64 spp on average"); the next complete render of the
//! picture removes it, and `lesson11 slides` renders such pictures again
//! rather than show them as finished.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};

use anyhow::Result;
use raytracer::film::output::{StagedFile, commit_all};
use raytracer::film::{Film, Image};
use raytracer::integrator::Integrator;
use raytracer::render::{RenderOptions, RenderResult, RenderStats, render};
use raytracer::scene::Scene;

use crate::options::create_dir;
use crate::page::{Picture, seconds_text};

/// Renders and writes `dir/stem.png`, `dir/stem.exr` and `dir/stem-variance.exr`,
/// then prints one summary line. An interrupted render (Ctrl-C, SIGTERM,
/// SIGHUP) still writes what it computed, says how much that is, and
/// returns an error.
pub fn render_to_files(
    scene: &Scene,
    integrator: &dyn Integrator,
    options: &RenderOptions,
    dir: &Path,
    stem: &str,
    exposure: f32,
) -> Result<Picture> {
    warn_if_unlit(scene, integrator);
    render_with_to_files(scene, options, dir, stem, exposure, || {
        render(scene, integrator, options)
    })
}

/// [`render_to_files`] for a render made by `render` (another engine).
pub fn render_with_to_files(
    scene: &Scene,
    options: &RenderOptions,
    dir: &Path,
    stem: &str,
    exposure: f32,
    render: impl FnOnce() -> RenderResult,
) -> Result<Picture> {
    let files = OutputFiles::new(dir, stem)?;
    let result = render();
    files.write(&result.film, &result.stats, options.spp, exposure, || {
        interrupted_summary(
            &result.stats,
            options,
            result.film.unsampled_pixels(),
            scene,
        )
    })
}

/// The three files of one picture: `stem.png`, `stem.exr` and
/// `stem-variance.exr` in a folder.
pub struct OutputFiles {
    png: PathBuf,
    exr: PathBuf,
    variance: PathBuf,
}

impl OutputFiles {
    /// Creates `dir` and checks, before anything is rendered, that no
    /// folder stands where a file must go (a folder cannot be replaced by a
    /// file).
    pub fn new(dir: &Path, stem: &str) -> Result<OutputFiles> {
        create_dir(dir)?;
        let files = OutputFiles {
            png: dir.join(format!("{stem}.png")),
            exr: dir.join(format!("{stem}.exr")),
            variance: dir.join(format!("{stem}-variance.exr")),
        };
        if let Some(folder) = [&files.png, &files.exr, &files.variance]
            .into_iter()
            .find(|p| p.is_dir())
        {
            anyhow::bail!(
                "cannot write {}: a folder has that name; move it or choose another --out",
                folder.display()
            );
        }
        Ok(files)
    }

    /// Writes a rendered film (its image, its variance image, the PNG) and
    /// prints one line; `interrupted` says how much an interrupted render
    /// computed. Nothing is written if nothing was computed.
    pub fn write(
        &self,
        film: &Film,
        stats: &RenderStats,
        spp: u32,
        exposure: f32,
        interrupted: impl FnOnce() -> String,
    ) -> Result<Picture> {
        let (png, exr) = (&self.png, &self.exr);
        if film.total_samples() == 0 && stats.interrupted {
            // A black picture would only replace a better one.
            crate::console::say!(
                "  {}: {}",
                png.display(),
                lang::pick(
                    "interrupted before any sample was computed; nothing written",
                    "прекъснато преди да е изчислена и една проба; нищо не е записано",
                )
            );
            anyhow::bail!(lang::pick(
                "interrupted before any sample was computed",
                "прекъснато преди да е изчислена и една проба"
            ));
        }
        let image = film.image();
        let note = partial_note(png);
        // An interrupted render's note goes in place first: a kill between
        // the renames leaves a finished picture marked partial, never the
        // other way round.
        let partial = stats.interrupted.then(|| {
            let pixels = film.width() as f64 * film.height() as f64;
            let mean = film.total_samples() as f64 / pixels.max(1.0);
            StagedFile::write(&note, "note", |w| {
                use std::io::Write;
                writeln!(w, "{mean:.2} of {spp} spp on average (interrupted)")
            })
        });
        let staged = [
            image.stage_exr(exr),
            film.variance_image().stage_exr(&self.variance),
            image.stage_png(png, exposure),
        ];
        // All written before any is renamed: an error leaves the old three.
        let staged = partial
            .into_iter()
            .chain(staged)
            .collect::<std::io::Result<Vec<_>>>()?;
        commit_all(staged)?;
        if !stats.interrupted {
            match std::fs::remove_file(&note) {
                Err(e) if e.kind() != std::io::ErrorKind::NotFound => {
                    anyhow::bail!(
                        "{} {}: {e}",
                        lang::pick("cannot remove", "не мога да изтрия"),
                        note.display()
                    )
                }
                _ => {}
            }
        }
        let seconds = stats.elapsed.as_secs_f64();
        if stats.nonfinite > 0 {
            crate::console::say!(
                "  {}",
                lang::fill(
                    lang::pick(
                        "note: {n} samples were NaN, infinite or negative and counted as zero",
                        "бележка: {n} проби бяха NaN, безкрайни или отрицателни и са броени за нула",
                    ),
                    &[("n", &stats.nonfinite)]
                )
            );
        }
        if stats.interrupted {
            crate::console::say!(
                "  {} {} {}: {}",
                lang::pick("wrote", "записах"),
                png.display(),
                lang::pick("and .exr", "и .exr"),
                interrupted()
            );
            anyhow::bail!(
                "{} {}",
                lang::pick(
                    "interrupted; what was rendered so far is in",
                    "прекъснато; рендерираното дотук е в"
                ),
                exr.display()
            );
        }
        crate::console::say!(
            "  {} {} {} ({spp} spp, {})",
            lang::pick("wrote", "записах"),
            png.display(),
            lang::pick("and .exr", "и .exr"),
            seconds_text(seconds)
        );
        Ok(Picture {
            png: png.clone(),
            exr: exr.clone(),
            spp,
            exposure,
            seconds: Some(seconds),
        })
    }
}

/// The note beside `png` that says it holds an interrupted render
/// (`png` with `.partial` appended; see the module doc).
pub fn partial_note(png: &Path) -> PathBuf {
    let mut name = png.as_os_str().to_owned();
    name.push(".partial");
    PathBuf::from(name)
}

/// What an interrupted render computed: its samples, their average per
/// pixel, and how many pixels have none (they are black in the files).
fn interrupted_summary(
    stats: &RenderStats,
    options: &RenderOptions,
    unsampled: u64,
    scene: &Scene,
) -> String {
    let pixels = scene.camera.width as u64 * scene.camera.height as u64;
    let expected = pixels * options.spp as u64;
    let mean = stats.samples as f64 / pixels.max(1) as f64;
    let percent = 100.0 * unsampled as f64 / pixels.max(1) as f64;
    lang::fill(
        lang::pick(
            "INTERRUPTED after {done} of {expected} samples ({mean:.2} of {spp} spp on average, \
             {seconds:.2} s); {unsampled} of {pixels} pixels ({percent:.0} %) have no sample and \
             are black",
            "ПРЕКЪСНАТО след {done} от {expected} проби (средно {mean:.2} от {spp} spp, \
             {seconds:.2} s); {unsampled} от {pixels} пиксела ({percent:.0} %) нямат проба и са \
             черни",
        ),
        &[
            ("done", &stats.samples),
            ("expected", &expected),
            ("mean", &mean),
            ("spp", &options.spp),
            ("seconds", &stats.elapsed.as_secs_f64()),
            ("unsampled", &unsampled),
            ("pixels", &pixels),
            ("percent", &percent),
        ],
    )
}

/// Warns, once per run, that a scene without lights renders black (ambient
/// occlusion needs none).
pub fn warn_if_unlit(scene: &Scene, integrator: &dyn Integrator) {
    // Light tracing starts its paths on the lights' surfaces and points: an
    // environment emits none, so what the sky lights is missing (the white
    // furnace came out 0 instead of 1 with no word).
    static SKYLESS: AtomicBool = AtomicBool::new(false);
    if integrator.name() == "light"
        && scene.lights.iter().any(|l| l.is_environment())
        && !SKYLESS.swap(true, Ordering::Relaxed)
    {
        eprintln!(
            "{}",
            lang::fill(
                lang::pick(
                    "warning: light tracing starts no path at the environment of `{scene}`: the \
                     sky's light is missing from this image (too dark, or black under a sky \
                     alone); path or bdpt render it",
                    "внимание: light tracing не започва път от околната среда на `{scene}`: \
                     светлината на небето липсва в тази картина (твърде тъмна или черна само под \
                     небе); path или bdpt я рендерират",
                ),
                &[("scene", &scene.name)]
            )
        );
    }
    static WARNED: AtomicBool = AtomicBool::new(false);
    if scene.lights.is_empty() && integrator.name() != "ao" && !WARNED.swap(true, Ordering::Relaxed)
    {
        eprintln!(
            "{}",
            lang::fill(
                lang::pick(
                    "warning: scene `{scene}` has no light, no emitting shape and no \
                     environment: its image is black (add an `emission`, a [[lights]] or an \
                     [environment])",
                    "внимание: сцената `{scene}` няма лампа, светеща форма или околна среда: \
                     картината ѝ е черна (добавете `emission`, [[lights]] или [environment])",
                ),
                &[("scene", &scene.name)]
            )
        );
    }
}

/// Writes `dir/stem.png` (scaled by `2^exposure`) and `dir/stem.exr`
/// together: both or neither replace the old ones.
pub fn write_png_and_exr(
    image: &Image,
    dir: &Path,
    stem: &str,
    exposure: f32,
) -> Result<(PathBuf, PathBuf)> {
    let png = dir.join(format!("{stem}.png"));
    let exr = dir.join(format!("{stem}.exr"));
    let staged = vec![image.stage_exr(&exr)?, image.stage_png(&png, exposure)?];
    commit_all(staged)?;
    Ok((png, exr))
}

/// Writes an image computed outside `render` as `dir/stem.png` (at
/// `exposure` stops) and `dir/stem.exr`, recorded as a picture of `spp`
/// samples per pixel that took `seconds` to render (`None` if it was not
/// one render of its own).
pub fn write_image(
    dir: &Path,
    stem: &str,
    image: &Image,
    spp: u32,
    exposure: f32,
    seconds: Option<f64>,
) -> Result<Picture> {
    let (png, exr) = write_png_and_exr(image, dir, stem, exposure)?;
    Ok(Picture {
        png,
        exr,
        spp,
        exposure,
        seconds,
    })
}
