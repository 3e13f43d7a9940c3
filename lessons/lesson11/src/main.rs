//! `lesson11`: Lecture 11 of the ray-tracing course as a program.
//!
//! Without arguments it walks the lecture in order and writes every picture
//! into `out/lesson11/` with an `index.html` that shows them. Each chapter is
//! also a subcommand with its own options; `--help` at every level says which
//! part of the lecture it shows.

mod brdf_plots;
mod chapters;
mod commands;
mod equal_time;
mod integrators;
mod options;
mod page;
mod plots;
mod render_files;
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
    #[command(flatten)]
    Other(commands::Command),
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
        Command::Stereo(args) => stereo_cmd::run(&args),
        Command::Other(command) => command.run(),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::FAILURE
        }
    }
}
