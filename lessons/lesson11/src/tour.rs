//! The tour: every chapter of the lecture in order.
//!
//! `lesson11` without a command runs it: each chapter renders its pictures
//! into `out/lesson11/NN-chapter/`, prints one line per picture, and adds a
//! section to `out/lesson11/index.html`.

use std::path::PathBuf;
use std::time::Instant;

use anyhow::Result;
use clap::{Args, ValueEnum};
use raytracer::integrator::{
    AmbientOcclusion, Direct, DirectStrategy, Integrator, NaiveRecursive, PathTracer,
};
use raytracer::render::{RenderOptions, render};
use raytracer::scene::Scene;

use crate::options::{SceneArgs, create_dir, load_scene};
use crate::page::{Figure, Page, Section, Table};
use crate::render_files::render_to_files;

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

/// What every chapter needs: where to write, how hard to work.
pub struct Tour {
    pub out: PathBuf,
    pub quality: Quality,
    pub threads: Option<usize>,
    /// The command line's overrides of scene, size, samples and seed.
    pub overrides: SceneArgs,
}

impl Tour {
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
                let (w, h) = (scene.settings.width, scene.settings.height);
                scene.set_resolution(32, (32 * h / w).max(1));
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
                anyhow::bail!("the image size must be positive, got {w}×{h}");
            }
            scene.set_resolution(w, h);
        }
        if let Some(s) = o.spp {
            if s == 0 {
                anyhow::bail!("--spp must be at least 1");
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
    pub fn chapter(&self, folder: &str, title: &str, text: &str) -> Result<Chapter> {
        let dir = self.out.join(folder);
        create_dir(&dir)?;
        Ok(Chapter {
            dir,
            section: Section::new(title, text),
        })
    }

    /// Renders and adds the picture to the chapter.
    pub fn picture(
        &self,
        chapter: &mut Chapter,
        scene: &Scene,
        integrator: &dyn Integrator,
        options: &RenderOptions,
        stem: &str,
        caption: &str,
    ) -> Result<()> {
        let p = render_to_files(scene, integrator, options, &chapter.dir, stem, 0.0)?;
        chapter
            .section
            .figures
            .push(Figure::new(&self.out, &p, caption));
        Ok(())
    }
}

/// A chapter being written: its folder and its section of the page.
pub struct Chapter {
    pub dir: PathBuf,
    pub section: Section,
}

/// A chapter: renders its pictures and returns its section of the page.
pub type ChapterFn = fn(&Tour) -> Result<Section>;

/// The chapters in lecture order, by subcommand name.
pub const CHAPTERS: [(&str, ChapterFn); 8] = [
    ("stereo", stereo),
    ("gi-effects", gi_effects),
    ("brdf", brdf),
    ("rendering-equation", rendering_equation),
    ("path", path),
    ("light", crate::chapters::light),
    ("bdpt", crate::chapters::bdpt),
    ("compare", crate::chapters::compare),
];

/// The whole tour: every chapter, and `index.html` with all of them.
pub fn run(args: &TourArgs) -> Result<()> {
    run_chapters(args, None)
}

/// Runs every chapter (`only = None`) or one, and writes the page: the
/// tour's `index.html`, or `<chapter>.html` beside it for a single chapter.
pub fn run_chapters(args: &TourArgs, only: Option<&str>) -> Result<()> {
    let out = &args.common.out;
    create_dir(out)?;
    if args.common.threads == Some(0) {
        anyhow::bail!("--threads must be at least 1 (or left out to use every core)");
    }
    let quality = if args.quick {
        Quality::Quick
    } else if args.full {
        Quality::Full
    } else {
        args.quality
    };
    let tour = Tour {
        out: out.clone(),
        quality,
        threads: args.common.threads,
        overrides: args.common.clone(),
    };
    let start = Instant::now();
    let mut page = Page::new("Lecture 11: stereoscopy and global illumination, rendered");
    for (name, chapter) in CHAPTERS {
        if only.is_some_and(|o| o != name) {
            continue;
        }
        println!("\n== {name}");
        let t = Instant::now();
        page.sections.push(chapter(&tour)?);
        println!("== {name}: {:.1} s", t.elapsed().as_secs_f64());
    }
    let file = only.map_or_else(|| "index.html".to_string(), |name| format!("{name}.html"));
    let index = page.write(out, &file)?;
    println!(
        "\nThat took {:.1} s. Open {} to see the pictures.",
        start.elapsed().as_secs_f64(),
        index.display()
    );
    Ok(())
}

/// Chapter 1: stereoscopy (see `lesson11 stereo --help` for every option).
fn stereo(tour: &Tour) -> Result<Section> {
    let mut args = crate::stereo_cmd::StereoArgs::default();
    args.scene.out = tour.out.clone();
    args.scene.threads = tour.threads;
    match tour.quality {
        Quality::Tiny => {
            args.scene.width = Some(32);
            args.scene.height = Some(24);
            args.scene.spp = Some(2);
            args.lf_views = 2;
            args.lf_spp = Some(1);
        }
        Quality::Quick => args.scene.spp = Some(32),
        Quality::Full => args.scene.spp = Some(256),
    }
    let o = &tour.overrides;
    args.scene.width = o.width.or(args.scene.width);
    args.scene.height = o.height.or(args.scene.height);
    args.scene.spp = o.spp.or(args.scene.spp);
    args.scene.seed = o.seed;
    crate::stereo_cmd::render_section(&args, &tour.out)
}

/// Chapter 2: what direct light alone misses.
fn gi_effects(tour: &Tour) -> Result<Section> {
    let mut s = tour.chapter(
        "02-gi-effects",
        "2 · Global illumination effects",
        "The same Cornell box three ways. Direct light alone (one bounce) leaves the ceiling black and \
         the shadows hard-edged and empty. Ambient occlusion darkens corners and contact regions but knows \
         nothing of the light. Full global illumination (path tracing, unlimited depth) brings the indirect \
         light: a lit ceiling, soft shadows, and colour bleeding — red and green tints on the white boxes.",
    )?;
    let (scene, options) = tour.scene("cornell", 64)?;
    tour.picture(
        &mut s,
        &scene,
        &Direct,
        &options,
        "cornell-direct",
        "Direct light only (max depth 2).",
    )?;
    let ao = AmbientOcclusion { distance: 0.5 };
    tour.picture(
        &mut s,
        &scene,
        &ao,
        &options,
        "cornell-ao",
        "Ambient occlusion (rays of 0.5 m).",
    )?;
    let pt = PathTracer {
        max_depth: None,
        rr_depth: 5,
        strategy: DirectStrategy::Mis,
    };
    tour.picture(
        &mut s,
        &scene,
        &pt,
        &options,
        "cornell-path",
        "Global illumination: path tracing, unlimited depth.",
    )?;
    Ok(s.section)
}

/// Chapter 3: BRDFs.
fn brdf(tour: &Tour) -> Result<Section> {
    let mut s = tour.chapter(
        "03-brdf",
        "3 · BRDFs",
        "A BRDF f_r(ω_i → ω_o) says how much of the light arriving from ω_i leaves towards ω_o. The plots \
         show lobes in the plane of incidence, the directional albedo ∫ f_r cos θ dω (energy conservation \
         demands ≤ 1) of normalized and unnormalized Phong, and reciprocity. The render shows Lambert, \
         normalized Phong with n = 1, 10, 100 and 1000, a perfect mirror and glass, path traced: as n \
         grows the highlight narrows and brightens, and the normalization (n+2)/2π keeps the reflected \
         energy the same.",
    )?;
    crate::brdf_plots::write_all(&mut s, tour)?;
    let (scene, options) = tour.scene("brdf-gallery", 32)?;
    let pt = PathTracer::default();
    tour.picture(
        &mut s,
        &scene,
        &pt,
        &options,
        "brdf-gallery",
        "The BRDF gallery, path traced.",
    )?;
    Ok(s.section)
}

/// Chapter 4: the rendering equation solved by naive recursion, and its cost.
fn rendering_equation(tour: &Tour) -> Result<Section> {
    let mut s = tour.chapter(
        "04-rendering-equation",
        "4 · The rendering equation and its recursion",
        "Naive recursive Monte Carlo shoots N rays at every hit and recurses: a pixel sample costs \
         1 + N + N² + … rays, so the cost explodes with depth (the table counts the rays actually traced). \
         Path tracing follows one ray per bounce and spends the same budget on more samples per pixel.",
    )?;
    let (mut scene, mut options) = tour.scene("cornell", 1)?;
    if tour.quality != Quality::Tiny {
        scene.set_resolution(96, 96);
    }
    options.progress = false;
    let mut table = Table::new(
        "Naive recursion on the Cornell box, 1 sample per pixel",
        &[
            "N (branching)",
            "max depth D",
            "rays per pixel (measured)",
            "rays per pixel bound Σ N^d",
            "seconds",
        ],
    );
    let pixels = (scene.camera.width * scene.camera.height) as f64;
    for n in [2u32, 4, 8] {
        for d in [2u32, 3, 4] {
            let naive = NaiveRecursive::new(vec![n], Some(d));
            let result = render(&scene, &naive, &options);
            table.rows.push(vec![
                n.to_string(),
                d.to_string(),
                format!("{:.1}", naive.rays_traced() as f64 / pixels),
                naive.rays_per_sample_bound().unwrap_or(0).to_string(),
                format!("{:.3}", result.stats.elapsed.as_secs_f64()),
            ]);
        }
    }
    for row in &table.rows {
        println!(
            "  naive N={} D={}: {} rays per pixel, {} s",
            row[0], row[1], row[2], row[4]
        );
    }
    table.write_csv(&s.dir.join("naive-rays.csv"))?;
    s.section.tables.push(table);
    let naive = NaiveRecursive::new(vec![8], Some(4));
    tour.picture(
        &mut s,
        &scene,
        &naive,
        &options,
        "naive-n8-d4",
        "Naive recursion, N = 8, D = 4, 1 spp.",
    )?;
    let pt = PathTracer {
        max_depth: Some(4),
        rr_depth: 5,
        strategy: DirectStrategy::BrdfOnly,
    };
    let mut equal = options.clone();
    equal.spp = if tour.quality == Quality::Tiny { 2 } else { 64 };
    tour.picture(
        &mut s,
        &scene,
        &pt,
        &equal,
        "path-d4",
        "Path tracing (BRDF sampling only, as naive recursion), D = 4.",
    )?;
    Ok(s.section)
}

/// Chapter 5: path tracing, samples per pixel, and light sampling with MIS.
fn path(tour: &Tour) -> Result<Section> {
    let mut s = tour.chapter(
        "05-path",
        "5 · Path tracing",
        "One continuation per bounce and many samples per pixel: the noise falls as 1/√spp (each row of \
         pictures quadruples the samples and halves the noise). Below, the three ways of finding light at \
         equal samples: BRDF sampling only (lights are found by chance), light sampling only, and both \
         combined by multiple importance sampling.",
    )?;
    let pt = PathTracer::default();
    for spp in [1u32, 4, 16, 64] {
        let (scene, mut options) = tour.scene("cornell", spp)?;
        options.spp = options.spp.min(spp.max(1) * 8);
        let stem = format!("cornell-path-{spp:03}spp");
        tour.picture(
            &mut s,
            &scene,
            &pt,
            &options,
            &stem,
            &format!("Path tracing, {spp} spp."),
        )?;
    }
    let (scene, options) = tour.scene("cornell", 16)?;
    for (strategy, stem, caption) in [
        (
            DirectStrategy::BrdfOnly,
            "cornell-brdf-only",
            "BRDF sampling only.",
        ),
        (
            DirectStrategy::LightOnly,
            "cornell-light-only",
            "Light sampling only (no MIS).",
        ),
        (
            DirectStrategy::Mis,
            "cornell-mis",
            "Light and BRDF sampling under MIS (power heuristic).",
        ),
    ] {
        let pt = PathTracer {
            strategy,
            ..PathTracer::default()
        };
        tour.picture(&mut s, &scene, &pt, &options, stem, caption)?;
    }
    Ok(s.section)
}
