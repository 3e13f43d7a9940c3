//! `lesson11`: Lecture 11 of the ray-tracing course as a program.
//!
//! Without arguments it walks the lecture in order and writes every picture
//! into `out/lesson11/` with an `index.html` that shows them. Each chapter is
//! also a subcommand with its own options; `--help` at every level says which
//! part of the lecture it shows.
//!
//! # Layout
//!
//! Arrows point down. A file imports only files on lower lines of this list
//! and its own submodules; files on one line import each other only inside a
//! folder named on it, and never in a circle. `tests/layers.rs` reads this
//! list and fails otherwise, and a new file must find its line here.
//!
//! ```text
//! main.rs lib.rs  the program, and the command line: the tour, one subcommand per listed chapter, then the rest
//! commands/        the subcommands that are not chapters: render, scenes, bench, exercises, slides, …
//! chapters/mod.rs  the chapter list in lecture order, and the tour that walks it
//! chapters/c*.rs   one chapter each: its pictures, tables and plots, and its section of the page
//! tour.rs          what every chapter is (its entry in the list) and gets (the Tour context)
//! equal_time.rs algorithms.rs integrators.rs integrators/ bias.rs     shared by chapters and commands
//! metropolis.rs    --integrator mlt: its options and its render to files
//! render_files.rs  rendering to files: PNG, EXR and the variance, replaced together
//! reference.rs     the independent references renders are measured against
//! engine.rs        which engine runs the path tracer: the lecture's, or the wavefront one
//! options.rs       scene, size, samples, seed, threads and output folder of a command line
//! page/ plots/     the HTML page and its SVG plots
//! language.rs cli_errors.rs  --lang bg|en, and the command line's help and clap's errors in Bulgarian
//! console.rs       standard output that a closed pipe or a full disk cannot crash
//! ```
//!
//! Below them all are the crates `raytracer` (the renderer), `exercises` (the
//! student's code) and `grading` (the grader).
//!
//! Adding a chapter is adding its file, `chapters/cNN_topic.rs` with a
//! `pub const CHAPTER: Chapter`, and its name to the list in
//! `chapters/mod.rs`: its subcommand and its place in the tour follow.

pub mod algorithms;
pub mod bias;
pub mod chapters;
pub mod cli_errors;
pub mod commands;
pub mod console;
pub mod engine;
pub mod equal_time;
pub mod integrators;
pub mod language;
pub mod metropolis;
pub mod options;
pub mod page;
pub mod plots;
pub mod reference;
pub mod render_files;
pub mod tour;

use std::process::ExitCode;

use clap::{ArgMatches, Args, CommandFactory, FromArgMatches, Parser, Subcommand};

use crate::tour::{Chapter, TourArgs};

/// Lecture 11: stereoscopy, BRDFs, the rendering equation, path tracing,
/// light tracing and bidirectional path tracing, and the biased algorithms — rendered.
///
/// Run without a command to walk the whole lecture with quick settings and
/// write its pictures to out/lesson11/ (open out/lesson11/index.html).
#[derive(Parser)]
#[command(name = "lesson11", version)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
    /// The language: bg (Bulgarian) or en (English); default: LESSON11_LANG,
    /// else the system locale (LANG starting with bg: Bulgarian).
    #[arg(long, global = true, value_parser = ["bg", "en"])]
    lang: Option<String>,
}

impl Cli {
    /// Parses the command line in the language it asks for (see
    /// [`language`]), `--help` included.
    fn parse_localized() -> Cli {
        let args: Vec<String> = std::env::args().collect();
        let language = language::choose(&args);
        let matches = language::localize(Cli::command(), language)
            .try_get_matches_from(args)
            .unwrap_or_else(|e| cli_errors::exit(e));
        Cli::from_arg_matches(&matches).unwrap_or_else(|e| cli_errors::exit(e))
    }
}

/// The subcommands, in the order `--help` lists them: the tour, one per
/// chapter of [`chapters::CHAPTERS`] in lecture order, then the others.
pub enum Command {
    Tour(TourArgs),
    /// A chapter alone, with the options its subcommand parsed.
    Chapter(&'static Chapter, ArgMatches),
    Other(commands::Command),
}

/// What `lesson11 --help` says of `lesson11 tour`.
const TOUR_ABOUT: &str = "Walk the lecture in order and write every picture (the default)";

impl Subcommand for Command {
    fn augment_subcommands(cli: clap::Command) -> clap::Command {
        let tour = TourArgs::augment_args(clap::Command::new("tour"))
            .about(TOUR_ABOUT)
            .long_about(None);
        let cli = chapters::CHAPTERS
            .iter()
            .fold(cli.subcommand(tour), |cli, chapter| {
                cli.subcommand(chapter.subcommand())
            });
        commands::Command::augment_subcommands(cli)
    }

    fn augment_subcommands_for_update(cli: clap::Command) -> clap::Command {
        Self::augment_subcommands(cli)
    }

    fn has_subcommand(name: &str) -> bool {
        name == "tour" || chapters::find(name).is_some() || commands::Command::has_subcommand(name)
    }
}

impl FromArgMatches for Command {
    fn from_arg_matches(matches: &ArgMatches) -> Result<Self, clap::Error> {
        match matches.subcommand() {
            Some(("tour", tour)) => Ok(Command::Tour(TourArgs::from_arg_matches(tour)?)),
            Some((name, sub)) => match chapters::find(name) {
                Some(chapter) => Ok(Command::Chapter(chapter, sub.clone())),
                None => Ok(Command::Other(commands::Command::from_arg_matches(
                    matches,
                )?)),
            },
            None => Err(clap::Error::new(clap::error::ErrorKind::MissingSubcommand)),
        }
    }

    fn update_from_arg_matches(&mut self, matches: &ArgMatches) -> Result<(), clap::Error> {
        *self = Self::from_arg_matches(matches)?;
        Ok(())
    }
}

/// The renderer's summary line and progress bar in Bulgarian (see
/// `raytracer::render::Words`: the renderer knows no language, so the words
/// are handed down to it).
const BULGARIAN_RENDER_WORDS: raytracer::render::Words = raytracer::render::Words {
    samples: "проби",
    took: "за",
    threads: "нишки",
    interrupted: "ПРЕКЪСНАТО",
    dropped: "стойности NaN/inf/отрицателни, изхвърлени",
    interrupted_twice: "прекъснато два пъти: излизам, без да записвам",
};

/// The program: parses the command line (in the language it asks for) and runs
/// the tour, a chapter or a command; an error is one line on standard error.
pub fn main() -> ExitCode {
    let cli = Cli::parse_localized();
    raytracer::render::install_interrupt_handler();
    if lang::current() == lang::Lang::Bg {
        raytracer::render::say_in(BULGARIAN_RENDER_WORDS);
        raytracer::render::on_interrupt_say(
            "прекъснато: спирам и пазя изчислените дотук проби (прекъснете пак, за да излезете)",
        );
    }
    let result = match cli.command.unwrap_or(Command::Tour(TourArgs::default())) {
        Command::Tour(args) => chapters::run(&args),
        Command::Chapter(chapter, matches) => chapters::run_alone(chapter, &matches),
        Command::Other(command) => command.run(),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("{} {e:#}", lang::pick("error:", "грешка:"));
            ExitCode::FAILURE
        }
    }
}
