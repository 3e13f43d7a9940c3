//! `lesson11 exercises`, `lesson11 hint N`, `lesson11 solution N` and
//! `lesson11 render --student`: the student's loop, rustlings-like.
//!
//! Progress comes from the same grader as `cargo test` (the `grading`
//! crate); hints are shown one at a time (how many were shown is kept in
//! `target/lesson11-hints.txt`); a reference solution is shown only once the
//! exercise passes.

use std::path::PathBuf;

use anyhow::{Context, Result, bail};
use clap::Args;
use exercises::Exercise;
use exercises::plug::StudentRender;
use grading::Outcome;
use raytracer::metrics::{z_test, z_threshold};
use raytracer::render::render;

use crate::render_cmd::{IntegratorKind, RenderArgs, render_to_files};

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
    let count = reg.len();
    reg.into_iter()
        .find(|e| e.number() == Some(number))
        .with_context(|| format!("there is no exercise {number}: they are numbered 1 to {count}"))
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
    if let Err(err) = std::fs::write(&path, text) {
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

/// `lesson11 render --student`: the student's integrator (exercise 10, 11 or
/// 12, by `--integrator`) beside the renderer's integrator with the same
/// estimator, and their tile z-test.
pub fn render_student(args: &RenderArgs) -> Result<()> {
    let (scene, options) = args.scene.load("cornell")?;
    let ia = &args.integrator_args;
    let max_depth = match ia.max_depth {
        Some(d) if d < 0 => None,
        Some(d) => Some(d as u32),
        None => scene.settings.max_depth,
    };
    let rr_depth = ia.rr_depth.unwrap_or(scene.settings.rr_depth);
    let which = match args.integrator {
        IntegratorKind::Path | IntegratorKind::PathBrdf => StudentRender::Path {
            max_depth,
            rr_depth,
        },
        IntegratorKind::Naive => StudentRender::Naive {
            max_depth: max_depth.unwrap_or(4),
            branching: ia.branching.first().copied().unwrap_or(8),
        },
        IntegratorKind::Direct | IntegratorKind::PathNee => StudentRender::Direct,
        IntegratorKind::Ao | IntegratorKind::Light | IntegratorKind::Bdpt => bail!(
            "--student renders the exercises that are whole integrators: use --integrator path, naive or direct \
             (light tracing and bidirectional tracing are graded piece by piece: exercises 14 and 15)"
        ),
    };
    let exercise = which.exercise();
    let (student, reference) = (which.student(), which.reference());
    let outcome = grading::grade_exercise(exercise).unwrap_or(Outcome::NotStarted(None));
    if outcome.is_not_started() {
        bail!(
            "{exercise} is not started yet ({outcome}): fill in exercises/src/{exercise}.rs first"
        );
    }
    println!("{exercise}: {outcome}");
    println!("  beside it: {}", which.reference_note());
    let out = &args.scene.out;
    let stem = format!("{}-{}", scene.name, reference.name());
    render_to_files(
        &scene,
        student.as_ref(),
        &options,
        out,
        &format!("{stem}-student"),
        args.exposure,
    )?;
    render_to_files(
        &scene,
        reference.as_ref(),
        &options,
        out,
        &format!("{stem}-reference"),
        args.exposure,
    )?;
    // Compare them tile by tile (16-pixel tiles), as the grader does.
    // Different seeds: the two integrators may use the same random numbers in
    // the same order, and correlated pictures would hide a difference.
    let mut quiet = options.clone();
    quiet.progress = false;
    let a = render(&scene, student.as_ref(), &quiet);
    quiet.seed = quiet.seed.wrapping_add(1);
    let b = render(&scene, reference.as_ref(), &quiet);
    let z = z_test(
        &a.film.image(),
        &a.film.variance_image(),
        &b.film.image(),
        &b.film.variance_image(),
        16,
    );
    let threshold = z_threshold(z.z.len() * 3, 1e-4);
    println!(
        "  tile z-test: largest |z| = {:.1} in tile {} (threshold {threshold:.1}): {}",
        z.max_abs_z,
        z.worst_tile,
        if (z.max_abs_z as f64) <= threshold {
            "consistent with the reference"
        } else {
            "DIFFERS from the reference"
        }
    );
    Ok(())
}
