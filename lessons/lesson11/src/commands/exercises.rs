//! `lesson11 exercises`, `lesson11 hint N` and `lesson11 solution N`: the
//! student's loop, rustlings-like (`lesson11 render --student` renders with
//! their code).
//!
//! Progress comes from the same grader as `cargo test` (the `grading`
//! crate); hints are shown one at a time by the `hint` crate (how many were
//! shown is kept in `target/lesson11-hints.txt`), which `cargo run -p hint -- N`
//! runs without building this program; a reference solution is shown only
//! once the exercise passes.

use anyhow::{Context, Result, anyhow, bail};
use clap::Args;
use exercises::Exercise;
use grading::Outcome;

/// Show which exercises pass, fail or are not started, and the next one.
#[derive(Args, Debug, Default)]
pub struct ExercisesArgs {
    /// Keep watching exercises/src/: grade an exercise again each time its
    /// file is saved, with its verdict and the next hint command.
    #[arg(long)]
    pub watch: bool,
}

/// Show the next hint of exercise N (one more each time; --all for all of them).
#[derive(Args, Debug)]
pub struct HintArgs {
    /// The exercise number (1, 2, …) as listed by `lesson11 exercises`.
    pub number: usize,
    /// Show every hint at once.
    #[arg(long)]
    pub all: bool,
    /// Forget how many hints were shown (for every exercise).
    #[arg(long)]
    pub reset: bool,
}

/// Show the reference solution of exercise N — only once your solution passes.
#[derive(Args, Debug)]
pub struct SolutionArgs {
    pub number: usize,
}

fn exercise(number: usize) -> Result<Exercise> {
    hint::exercise(number).map_err(|e| anyhow!(e))
}

pub fn run_exercises(args: &ExercisesArgs) -> Result<()> {
    if args.watch {
        // Ctrl-C is how a watch ends: no render, nothing to keep.
        raytracer::render::on_interrupt_say(lang::pick(
            "stopped watching exercises/src/",
            "спрях да следя exercises/src/",
        ));
        return grading::watch::run(&raytracer::render::interrupted)
            .context("watching exercises/src/");
    }
    let threads = std::thread::available_parallelism().map_or(2, |n| n.get());
    let results = grading::grade_all(threads, grading::TIMEOUT);
    crate::console::say!(
        "{}",
        lang::pick(
            "Grade: `cargo test -p grading --test exercises` · on every save: `lesson11 exercises --watch` · hints: `cargo run -q -p hint -- N` · a solution once it passes: `lesson11 solution N`",
            "Проверка: `cargo test -p grading --test exercises` · при всяко записване: `lesson11 exercises --watch` · подсказки: `cargo run -q -p hint -- N` · решението, щом вашето минава: `lesson11 solution N`",
        )
    );
    crate::console::say_inline!("{}", grading::progress_report(&results));
    Ok(())
}

/// The same as `cargo run -p hint -- N` (the `hint` crate), which answers
/// without building this program.
pub fn run_hint(args: &HintArgs) -> Result<()> {
    if args.reset {
        hint::reset();
        crate::console::say!(
            "{}",
            lang::pick(
                "Hint counters reset.",
                "Броячите на подсказките са нулирани."
            )
        );
        return Ok(());
    }
    let text = hint::next_hints(args.number, args.all).map_err(|e| anyhow!(e))?;
    crate::console::say_inline!("{text}");
    Ok(())
}

pub fn run_solution(args: &SolutionArgs) -> Result<()> {
    let e = exercise(args.number)?;
    match grading::grade_exercise(&e.name).unwrap_or(Outcome::Failed("no grader".into())) {
        Outcome::Passed => {
            let path = exercises::crate_dir().join(e.solution_file());
            let text = std::fs::read_to_string(&path)
                .with_context(|| format!("cannot read {}", path.display()))?;
            let (number, path) = (args.number, path.display());
            crate::console::say!(
                "{}",
                lang::pick(
                    format!("Your exercise {number} passes. The reference solution ({path}):\n"),
                    format!("Задача {number} при вас минава. Еталонното решение ({path}):\n"),
                )
            );
            crate::console::say_inline!("{text}");
            Ok(())
        }
        other => {
            let (number, status) = (args.number, other.status());
            bail!(
                "{}",
                lang::pick(
                    format!(
                        "exercise {number} is {status}: the solution is shown once it passes (`cargo test`, hints: `cargo run -q -p hint -- {number}`)"
                    ),
                    format!(
                        "задача {number}: {status}; решението се показва, щом тя минава (`cargo test`, подсказки: `cargo run -q -p hint -- {number}`)"
                    ),
                )
            )
        }
    }
}
