//! `cargo test` for the student: grades every exercise and prints the
//! progress table (passed / failed with the reason / not started) and the
//! next exercise. Fails only if an exercise fails: stubs that still say
//! `todo!()` are "not started", so the pristine course is green.
//!
//! Arguments that are not options filter the exercises by name
//! (`cargo test -p grading --test exercises -- ex03`); libtest's options are
//! accepted and ignored, `--list` lists the exercises.

use std::process::ExitCode;

/// libtest options that take a value (skipped with it).
const WITH_VALUE: &[&str] = &[
    "--test-threads",
    "--skip",
    "--color",
    "--format",
    "--logfile",
    "-Z",
];

fn main() -> ExitCode {
    let mut filters = Vec::new();
    let mut args = std::env::args().skip(1);
    let mut list = false;
    while let Some(a) = args.next() {
        if WITH_VALUE.contains(&a.as_str()) {
            args.next();
        } else if a == "--list" {
            list = true;
        } else if !a.starts_with('-') {
            filters.push(a);
        }
    }
    let keep = |name: &str| filters.is_empty() || filters.iter().any(|f| name.contains(f.as_str()));
    if list {
        for e in exercises::registry().iter().filter(|e| keep(&e.name)) {
            println!("{}: test", e.name);
        }
        return ExitCode::SUCCESS;
    }
    let threads = std::thread::available_parallelism().map_or(2, |n| n.get());
    let mut results = grading::grade_all(threads, grading::TIMEOUT);
    results.retain(|(e, _)| keep(&e.name));
    if exercises::SOLUTIONS {
        println!("(graded: the reference solutions, feature `solutions`)");
    }
    print!("{}", grading::progress_report(&results));
    if results.iter().any(|(_, o)| o.is_failed()) {
        ExitCode::FAILURE
    } else {
        ExitCode::SUCCESS
    }
}
