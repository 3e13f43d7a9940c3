//! `lesson11`: Lecture 11 of the ray-tracing course as a program.
//!
//! Without arguments it walks the lecture in order and writes every picture
//! into `out/lesson11/` with an `index.html` that shows them. Each chapter is
//! also a subcommand with its own options; `--help` at every level says which
//! part of the lecture it shows.

mod chapters;
mod commands;
mod equal_time;
mod integrators;
mod options;
mod page;
mod plots;
mod render_files;
mod tour;

use std::process::ExitCode;

use clap::{ArgMatches, Args, FromArgMatches, Parser, Subcommand};

use crate::tour::{Chapter, TourArgs};

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

/// The subcommands, in the order `--help` lists them: the tour, one per
/// chapter of [`chapters::CHAPTERS`] in lecture order, then the others.
enum Command {
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

fn main() -> ExitCode {
    let cli = Cli::parse();
    raytracer::render::install_interrupt_handler();
    let result = match cli.command.unwrap_or(Command::Tour(TourArgs::default())) {
        Command::Tour(args) => chapters::run(&args),
        Command::Chapter(chapter, matches) => chapters::run_alone(chapter, &matches),
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
