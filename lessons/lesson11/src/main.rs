//! `lesson11`: Lecture 11 of the ray-tracing course as a program.
//!
//! Without arguments it walks the lecture in order and writes every picture
//! into `out/lesson11/` with an `index.html` that shows them. Each chapter is
//! also a subcommand with its own options; `--help` at every level says which
//! part of the lecture it shows.

mod bench;
mod bench_rays;
mod chapters;
mod options;
mod page;
mod render_cmd;
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
    /// Render one scene with one integrator to PNG (to look at) and EXR (to measure).
    Render(render_cmd::RenderArgs),
    /// List the built-in scenes, or write one out as a file to edit.
    Scenes(scenes_cmd::ScenesArgs),
    /// Stereoscopy: two eyes, anaglyphs, side-by-side, crosstalk and a light field.
    Stereo(stereo_cmd::StereoArgs),
    /// Measure the renderer: rays per second on big meshes, samples per second on the Cornell box.
    Bench(bench::BenchArgs),
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
        Command::Render(args) => render_cmd::run(&args),
        Command::Scenes(args) => scenes_cmd::run(&args),
        Command::Bench(args) => bench::run(&args),
        Command::Stereo(args) => stereo_cmd::run(&args),
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
