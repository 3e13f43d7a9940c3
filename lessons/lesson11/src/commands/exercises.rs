//! `lesson11 exercises`, `lesson11 hint N` and `lesson11 solution N`: the
//! student's loop, rustlings-like (`lesson11 render --student` renders with
//! their code).
//!
//! Progress comes from the same grader as `cargo test` (the `grading`
//! crate); hints are shown one at a time (how many were shown is kept in
//! `target/lesson11-hints.txt`); a reference solution is shown only once the
//! exercise passes.

use std::path::PathBuf;

use anyhow::{Context, Result, bail};
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
    let reg = exercises::registry();
    // Listed, not given as a range: a number may be skipped (18 before 16).
    let numbers: Vec<String> = reg
        .iter()
        .filter_map(|e| e.number())
        .map(|n| n.to_string())
        .collect();
    reg.into_iter()
        .find(|e| e.number() == Some(number))
        .with_context(|| {
            format!(
                "there is no exercise {number}: the exercises are {}",
                numbers.join(", ")
            )
        })
}

pub fn run_exercises(args: &ExercisesArgs) -> Result<()> {
    if args.watch {
        return grading::watch::run().context("watching exercises/src/");
    }
    let threads = std::thread::available_parallelism().map_or(2, |n| n.get());
    let results = grading::grade_all(threads, grading::TIMEOUT);
    println!(
        "Grade: `cargo test -p grading --test exercises` · on every save: `lesson11 exercises --watch` · hints: `lesson11 hint N` · a solution once it passes: `lesson11 solution N`"
    );
    print!("{}", grading::progress_report(&results));
    Ok(())
}

fn hints_file() -> PathBuf {
    let target = std::env::var_os("CARGO_TARGET_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| exercises::crate_dir().join("../target"));
    target.join("lesson11-hints.txt")
}

/// `name count` lines: how many hints of each exercise were shown.
fn read_shown() -> Vec<(String, usize)> {
    std::fs::read_to_string(hints_file())
        .unwrap_or_default()
        .lines()
        .filter_map(|l| {
            let (name, n) = l.split_once(' ')?;
            Some((name.to_string(), n.trim().parse().ok()?))
        })
        .collect()
}

pub fn run_hint(args: &HintArgs) -> Result<()> {
    let path = hints_file();
    if args.reset {
        let _ = std::fs::remove_file(&path);
        println!("Hint counters reset.");
        return Ok(());
    }
    let e = exercise(args.number)?;
    let mut shown = read_shown();
    let before = shown
        .iter()
        .find(|(n, _)| *n == e.name)
        .map_or(0, |(_, c)| *c);
    let now = if args.all {
        e.hints.len()
    } else {
        (before + 1).min(e.hints.len())
    };
    println!("Exercise {}: {} (slide: {})", args.number, e.title, e.slide);
    println!("File: exercises/{}", e.file);
    for (i, h) in e.hints.iter().take(now).enumerate() {
        println!("  hint {}/{}: {h}", i + 1, e.hints.len());
    }
    if now == e.hints.len() {
        println!(
            "That was the last hint; the solution is shown once your exercise passes (`lesson11 solution {}`).",
            args.number
        );
    } else {
        println!(
            "Run `lesson11 hint {}` again for the next hint.",
            args.number
        );
    }
    shown.retain(|(n, _)| *n != e.name);
    shown.push((e.name.clone(), now));
    let text: String = shown.iter().map(|(n, c)| format!("{n} {c}\n")).collect();
    if let Some(dir) = path.parent() {
        let _ = std::fs::create_dir_all(dir);
    }
    // Losing the counter only means the next hint is shown again.
    if let Err(err) = raytracer::film::output::write_file(&path, text) {
        eprintln!(
            "note: cannot remember the hints shown ({}: {err})",
            path.display()
        );
    }
    Ok(())
}

pub fn run_solution(args: &SolutionArgs) -> Result<()> {
    let e = exercise(args.number)?;
    match grading::grade_exercise(&e.name).unwrap_or(Outcome::Failed("no grader".into())) {
        Outcome::Passed => {
            let path = exercises::crate_dir().join(e.solution_file());
            let text = std::fs::read_to_string(&path)
                .with_context(|| format!("cannot read {}", path.display()))?;
            println!(
                "Your exercise {} passes. The reference solution ({}):\n",
                args.number,
                path.display()
            );
            print!("{text}");
            Ok(())
        }
        other => bail!(
            "exercise {} is {}: the solution is shown once it passes (`cargo test`, hints: `lesson11 hint {}`)",
            args.number,
            other.status(),
            args.number
        ),
    }
}
