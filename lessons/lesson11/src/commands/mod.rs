//! The subcommands that are not chapters of the lecture: rendering one scene,
//! the lab in the browser, the scenes, the benchmark, the student's
//! exercises, the instructor's references and slides. One file each; a new command is one more file and
//! one more variant below.

pub mod bench;
pub mod exercises;
pub mod lab;
pub mod references;
pub mod render;
pub mod scenes;
pub mod slides;

use anyhow::Result;
use clap::Subcommand;

// No doc comment on this enum: clap would print it as the whole program's
// description. Each variant's doc is its line in `lesson11 --help`.
#[derive(Subcommand)]
pub enum Command {
    /// Render one scene with one integrator to PNG (to look at) and EXR (to measure).
    Render(Box<render::RenderArgs>),
    /// The lecture live in the browser: a progressive render with its knobs, a live stereo pair, BRDF lobes and albedo, and a path inspector.
    Lab(lab::LabArgs),
    /// List the built-in scenes, or write one out as a file to edit.
    Scenes(scenes::ScenesArgs),
    /// Measure the renderer: rays per second on big meshes, samples per second on the Cornell box.
    Bench(bench::BenchArgs),
    /// The exercises: which pass, fail or are not started, and the next one.
    Exercises(self::exercises::ExercisesArgs),
    /// The next hint of exercise N.
    Hint(self::exercises::HintArgs),
    /// The reference solution of exercise N, once yours passes.
    Solution(self::exercises::SolutionArgs),
    /// For instructors: regenerate the grader's reference images (mean and variance EXR).
    References(references::ReferencesArgs),
    /// Build the lecture's slides (Bulgarian and English) as HTML with the rendered pictures.
    Slides(slides::SlidesArgs),
}

impl Command {
    pub fn run(self) -> Result<()> {
        match self {
            Command::Render(args) => render::run(&args),
            Command::Lab(args) => lab::run(&args),
            Command::Scenes(args) => scenes::run(&args),
            Command::Bench(args) => bench::run(&args),
            Command::Exercises(args) => self::exercises::run_exercises(&args),
            Command::Hint(args) => self::exercises::run_hint(&args),
            Command::Solution(args) => self::exercises::run_solution(&args),
            Command::References(args) => references::run(&args),
            Command::Slides(args) => slides::run(&args),
        }
    }
}
