//! What every chapter of the tour is and gets: its entry in the chapter list
//! ([`Chapter`]: subcommand, help line, how it renders) and the context it
//! renders in ([`Tour`]: where to write, how hard to work, the scenes at the
//! tour's quality, pictures added to its section of the page).
//!
//! `lesson11` without a command walks the chapters in order: each renders its
//! pictures into `out/lesson11/NN-chapter/`, prints one line per picture, and
//! adds a section to `out/lesson11/index.html`. The chapters themselves live
//! in `chapters/`, above this file: it imports none of them.

use std::path::PathBuf;

use anyhow::{Context, Result};
use clap::{ArgMatches, Args, ValueEnum};
use raytracer::integrator::record::PathRecord;
use raytracer::integrator::{Integrator, PathTracer};
use raytracer::render::{RenderOptions, memory_needed};
use raytracer::scene::Scene;

use crate::engine::Engine;
use crate::options::{SceneArgs, check_memory, check_threads, create_dir, load_scene};
use crate::page::{Figure, Picture, Section};
use crate::plots::{Labels, path_figure_svg};
use crate::render_files::{render_to_files, render_with_to_files, warn_if_unlit};

/// How long the tour may take.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum, Default)]
pub enum Quality {
    /// Tiny images, a few samples: checks that every chapter runs (seconds).
    Tiny,
    /// The default: every picture readable, the whole tour in about a minute.
    #[default]
    Quick,
    /// Eight times the samples of `quick`, for slides and handouts.
    Full,
}

/// Walk the lecture in order and write its pictures and out/lesson11/index.html.
/// `--scene` replaces the chapters' Cornell box; `--width`, `--height`,
/// `--spp` and `--seed` apply to every picture.
#[derive(Args, Debug, Clone)]
pub struct TourArgs {
    #[command(flatten)]
    pub common: SceneArgs,
    /// How much time to spend: tiny, quick (the default) or full.
    #[arg(long, value_enum, default_value = "quick")]
    pub quality: Quality,
    /// Short for --quality quick.
    #[arg(long, conflicts_with_all = ["quality", "full"])]
    pub quick: bool,
    /// Short for --quality full.
    #[arg(long, conflicts_with = "quality")]
    pub full: bool,
}

impl Default for TourArgs {
    fn default() -> Self {
        TourArgs {
            common: SceneArgs {
                out: PathBuf::from("out/lesson11"),
                ..SceneArgs::default()
            },
            quality: Quality::Quick,
            quick: false,
            full: false,
        }
    }
}

/// One chapter of the lecture: its entry in the tour's list and its subcommand.
pub struct Chapter {
    /// Its subcommand (`lesson11 path`), also the page it writes when run
    /// alone with the tour's options (`path.html`).
    pub name: &'static str,
    /// Its line in `lesson11 --help`: number, topic, what it shows.
    pub about: &'static str,
    /// Renders its pictures, tables and plots and returns its section of the page.
    pub render: fn(&Tour) -> Result<Section>,
    /// Options of its own, where the tour's (`TourArgs`) are not enough.
    pub options: Option<ChapterOptions>,
}

/// A chapter subcommand with options of its own (the stereo rig's).
pub struct ChapterOptions {
    /// Adds the options to the subcommand: their struct's `Args::augment_args`.
    pub augment: fn(clap::Command) -> clap::Command,
    /// Runs the chapter alone with the options parsed from the command line.
    pub run: fn(&ArgMatches) -> Result<()>,
}

impl Chapter {
    /// A chapter that takes the tour's options (`--quality`, `--scene`, `--spp`, …).
    pub const fn new(
        name: &'static str,
        about: &'static str,
        render: fn(&Tour) -> Result<Section>,
    ) -> Self {
        Chapter {
            name,
            about,
            render,
            options: None,
        }
    }

    /// The chapter's subcommand: its options, and its help line as clap's
    /// derive writes a documented variant (`about`, no long text).
    pub fn subcommand(&self) -> clap::Command {
        let command = clap::Command::new(self.name);
        let command = match &self.options {
            Some(options) => (options.augment)(command),
            None => TourArgs::augment_args(command),
        };
        command.about(self.about).long_about(None)
    }
}

/// What every chapter needs: where to write, how hard to work.
pub struct Tour {
    pub out: PathBuf,
    pub quality: Quality,
    pub threads: Option<usize>,
    /// The command line's overrides of scene, size, samples and seed.
    pub overrides: SceneArgs,
}

impl Tour {
    /// The tour the command line asks for; creates its output folder.
    pub fn new(args: &TourArgs) -> Result<Tour> {
        let out = &args.common.out;
        check_threads(args.common.threads)?;
        create_dir(out)?;
        let quality = if args.quick {
            Quality::Quick
        } else if args.full {
            Quality::Full
        } else {
            args.quality
        };
        Ok(Tour {
            out: out.clone(),
            quality,
            threads: args.common.threads,
            overrides: args.common.clone(),
        })
    }

    /// A built-in scene at the tour's quality, with `spp` samples at `quick`.
    /// The Cornell box may be replaced by `--scene`, and the size, samples and
    /// seed of every picture by `--width`, `--height`, `--spp` and `--seed`.
    pub fn scene(&self, name: &str, spp: u32) -> Result<(Scene, RenderOptions)> {
        let o = &self.overrides;
        let name = match &o.scene {
            Some(other) if name == "cornell" => other.as_str(),
            _ => name,
        };
        let mut scene = load_scene(name)?;
        let mut spp = match self.quality {
            Quality::Tiny => {
                let (w, h) = (scene.settings.width as u64, scene.settings.height as u64);
                // In 64 bits: a scene file may give sizes up to 2³² − 1.
                scene.set_resolution(32, (32 * h / w).clamp(1, u32::MAX as u64) as u32);
                2.min(spp)
            }
            Quality::Quick => spp,
            Quality::Full => spp * 8,
        };
        if o.width.is_some() || o.height.is_some() {
            let (w, h) = (
                o.width.unwrap_or(scene.settings.width),
                o.height.unwrap_or(scene.settings.height),
            );
            if w == 0 || h == 0 {
                anyhow::bail!(
                    "{} {w}×{h}",
                    lang::pick(
                        "the image size must be positive, got",
                        "размерът на картината трябва да е положителен, а е"
                    )
                );
            }
            scene.set_resolution(w, h);
        }
        let (w, h) = (scene.settings.width, scene.settings.height);
        check_memory(
            &lang::pick(format!("a {w}×{h} render"), format!("рендериране {w}×{h}")),
            memory_needed(w, h),
            lang::pick("--width and --height", "--width и --height"),
            o.force,
        )?;
        if let Some(s) = o.spp {
            if s == 0 {
                anyhow::bail!(lang::pick(
                    "--spp must be at least 1",
                    "--spp трябва да е поне 1"
                ));
            }
            spp = s;
        }
        let options = RenderOptions {
            spp,
            seed: o.seed.unwrap_or(scene.settings.seed),
            threads: self.threads,
            label: name.to_string(),
            ..RenderOptions::default()
        };
        Ok((scene, options))
    }

    /// Starts a chapter whose files go into `out/<folder>`.
    pub fn chapter(&self, folder: &str, title: &str, text: &str) -> Result<ChapterOutput> {
        let dir = self.out.join(folder);
        create_dir(&dir)?;
        Ok(ChapterOutput {
            dir,
            section: Section::new(title, text),
        })
    }

    /// Renders the picture (PNG at exposure 0), adds it to the chapter with
    /// its caption, and returns what it wrote.
    pub fn picture(
        &self,
        chapter: &mut ChapterOutput,
        scene: &Scene,
        integrator: &dyn Integrator,
        options: &RenderOptions,
        stem: &str,
        caption: &str,
    ) -> Result<Picture> {
        let p = render_to_files(scene, integrator, options, &chapter.dir, stem, 0.0)?;
        chapter
            .section
            .figures
            .push(Figure::new(&self.out, &p, caption));
        Ok(p)
    }

    /// [`Tour::picture`] for the path tracer `pt` on [`Engine::FASTEST`], for
    /// chapters that show what path tracing renders rather than its code (the
    /// same image bit for bit on either engine).
    pub fn path_picture(
        &self,
        chapter: &mut ChapterOutput,
        scene: &Scene,
        pt: &PathTracer,
        options: &RenderOptions,
        stem: &str,
        caption: &str,
    ) -> Result<Picture> {
        let engine = Engine::FASTEST;
        engine.check(pt)?;
        warn_if_unlit(scene, pt);
        let p = render_with_to_files(scene, options, &chapter.dir, stem, 0.0, || {
            engine.render(scene, pt, options).expect("checked above")
        })?;
        chapter
            .section
            .figures
            .push(Figure::new(&self.out, &p, caption));
        Ok(p)
    }

    /// Draws the recorded sample `record` (projected by `scene`'s camera)
    /// over `picture`, a render of the same scene and size, into
    /// `<stem>.svg`, and adds it to the chapter with its caption.
    pub fn path_figure(
        &self,
        chapter: &mut ChapterOutput,
        record: &PathRecord,
        (scene, picture): (&Scene, &Picture),
        labels: Labels,
        stem: &str,
        caption: &str,
    ) -> Result<()> {
        let png = std::fs::read(&picture.png)
            .with_context(|| format!("cannot read {}", picture.png.display()))?;
        let size = (scene.camera.width, scene.camera.height);
        let path = chapter.dir.join(format!("{stem}.svg"));
        raytracer::film::output::write_file(&path, path_figure_svg(record, &png, size, labels))?;
        let (pixel, sample) = (record.pixel, record.sample);
        crate::console::say!(
            "{}",
            lang::pick(
                format!("  {stem}: pixel {pixel:?}, sample {sample} recorded"),
                format!("  {stem}: записах проба {sample} на пиксел {pixel:?}"),
            )
        );
        chapter
            .section
            .figures
            .push(Figure::plot(&self.out, &path, caption));
        Ok(())
    }
}

/// A chapter being written: its folder and its section of the page.
pub struct ChapterOutput {
    pub dir: PathBuf,
    pub section: Section,
}
