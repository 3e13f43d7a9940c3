//! `lesson11`: Lecture 11 of the ray-tracing course as a program.
//!
//! Without arguments it walks the lecture in order and writes every picture
//! into `out/lesson11/` with an `index.html` that shows them. Each chapter is
//! also a subcommand with its own options; `--help` at every level says which
//! part of the lecture it shows.

mod bench;
mod bench_rays;
mod brdf_plots;
mod chapters;
mod exercises_cmd;
mod integrators;
mod options;
mod page;
mod plots;
mod references_cmd;
mod render_cmd;
mod render_files;
mod scenes_cmd;
mod slides_cmd;
mod stereo_cmd;
mod tour;

use std::process::ExitCode;

use clap::{Parser, Subcommand};

/// Lecture 11: stereoscopy, BRDFs, the rendering equation, path tracing,
/// light tracing and bidirectional path tracing — rendered.
///
/// Run without a command to walk the whole lecture with quick settings and
/// write its pictures to out/lesson11/ (open out/lesson11/index.html).
#[derive(Parser)]
#[command(name = "lesson11", version)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand)]
enum Command {
    /// Walk the lecture in order and write every picture (the default).
    Tour(tour::TourArgs),
    /// 1 · Stereoscopy: two eyes, anaglyphs, side-by-side, crosstalk and a light field.
    Stereo(stereo_cmd::StereoArgs),
    /// 2 · Global illumination effects: direct light, ambient occlusion and full GI side by side.
    GiEffects(tour::TourArgs),
    /// 3 · BRDFs: lobes, directional albedo of normalized and unnormalized Phong, reciprocity, a gallery.
    Brdf(tour::TourArgs),
    /// 4 · The rendering equation: naive recursive Monte Carlo and its N^D rays per pixel.
    RenderingEquation(tour::TourArgs),
    /// 5 · Path tracing: a samples-per-pixel ladder; BRDF sampling, light sampling and MIS.
    Path(tour::TourArgs),
    /// 6 · Light tracing, and the caustic that only light paths find.
    Light(tour::TourArgs),
    /// 7 · Bidirectional path tracing and its (s, t) strategies.
    Bdpt(tour::TourArgs),
    /// 8 · Every algorithm at equal time: RMSE against a reference, convergence plots.
    Compare(tour::TourArgs),
    /// Render one scene with one integrator to PNG (to look at) and EXR (to measure).
    Render(render_cmd::RenderArgs),
    /// List the built-in scenes, or write one out as a file to edit.
    Scenes(scenes_cmd::ScenesArgs),
    /// Measure the renderer: rays per second on big meshes, samples per second on the Cornell box.
    Bench(bench::BenchArgs),
    /// The exercises: which pass, fail or are not started, and the next one.
    Exercises(exercises_cmd::ExercisesArgs),
    /// The next hint of exercise N.
    Hint(exercises_cmd::HintArgs),
    /// The reference solution of exercise N, once yours passes.
    Solution(exercises_cmd::SolutionArgs),
    /// For instructors: regenerate the grader's reference images (mean and variance EXR).
    References(references_cmd::ReferencesArgs),
    /// Build the lecture's slides (Bulgarian and English) as HTML with the rendered pictures.
    Slides(slides_cmd::SlidesArgs),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    raytracer::render::install_interrupt_handler();
    let result = match cli
        .command
        .unwrap_or(Command::Tour(tour::TourArgs::default()))
    {
        Command::Tour(args) => tour::run(&args),
        Command::GiEffects(args) => tour::run_chapters(&args, Some("gi-effects")),
        Command::Brdf(args) => tour::run_chapters(&args, Some("brdf")),
        Command::RenderingEquation(args) => tour::run_chapters(&args, Some("rendering-equation")),
        Command::Path(args) => tour::run_chapters(&args, Some("path")),
        Command::Light(args) => tour::run_chapters(&args, Some("light")),
        Command::Bdpt(args) => tour::run_chapters(&args, Some("bdpt")),
        Command::Compare(args) => tour::run_chapters(&args, Some("compare")),
        Command::Render(args) => render_cmd::run(&args),
        Command::Scenes(args) => scenes_cmd::run(&args),
        Command::Bench(args) => bench::run(&args),
        Command::Stereo(args) => stereo_cmd::run(&args),
        Command::Exercises(args) => exercises_cmd::run_exercises(&args),
        Command::Hint(args) => exercises_cmd::run_hint(&args),
        Command::Solution(args) => exercises_cmd::run_solution(&args),
        Command::References(args) => references_cmd::run(&args),
        Command::Slides(args) => slides_cmd::run(&args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::FAILURE
        }
    }
}
