//! Unit tests of `lib.rs`.

use grading::*;
use outcome::Outcome;
use std::time::Duration;

#[test]
fn an_endless_exercise_times_out_and_the_others_are_graded() {
    let endless: Check = || loop {
        std::thread::sleep(Duration::from_millis(50));
    };
    let fine: Check = || Ok(());
    let todo: Check = || todo!();
    // Two endless exercises on two threads: the rest still get graded,
    // each endless one within its own budget.
    let o = lang::with(lang::Lang::En, || {
        grade_checks(
            vec![Some(endless), Some(endless), Some(fine), Some(todo), None],
            2,
            Duration::from_millis(300),
        )
    });
    for (k, (r, s)) in o.iter().take(2).enumerate() {
        assert!(
            matches!(r, Outcome::Failed(m) if m.contains("an endless loop, or far too slow")),
            "{k}: {r:?}"
        );
        assert!((0.3..2.0).contains(s), "{k}: waited {s} s");
    }
    assert_eq!(o[2].0, Outcome::Passed);
    assert!(o[3].0.is_not_started());
    assert!(o[4].0.is_failed());
}

/// The gate of `cargo test --workspace` (and `cargo test -p grading`):
/// red while an exercise the student started fails. With the feature
/// `solutions` the self-test's `reference_solutions_pass` does this work. The student's own
/// harness (`--test exercises`) exits with success so that its summary
/// stays the last line printed; this test is what fails instead.
#[test]
fn every_exercise_you_started_passes() {
    if exercises::SOLUTIONS {
        // The reference solutions: check_grader's `reference_solutions_pass`
        // grades them, and demands more (every one passed).
        return;
    }
    let threads = std::thread::available_parallelism().map_or(2, |n| n.get());
    let failing: Vec<String> = grade_all(threads, TIMEOUT)
        .into_iter()
        .filter(|g| g.outcome.is_failed())
        .map(|g| {
            format!(
                "exercise {} ({}): {}",
                g.exercise.number().unwrap_or(0),
                g.exercise.name,
                g.outcome
            )
        })
        .collect();
    assert!(
        failing.is_empty(),
        "{} exercise(s) fail:\n{}\nThe progress table and the next step: `cargo test -p grading --test exercises`",
        failing.len(),
        failing.join("\n")
    );
}

#[test]
fn the_summary_is_last_and_names_the_next_step() {
    let reg = exercises::registry();
    let graded: Vec<Graded> = reg
        .iter()
        .enumerate()
        .map(|(i, e)| Graded {
            exercise: e.clone(),
            outcome: if i < 2 {
                Outcome::Passed
            } else {
                Outcome::NotStarted(None)
            },
            seconds: 0.1,
        })
        .collect();
    let report = lang::with(lang::Lang::En, || progress_report(&graded));
    let last: Vec<&str> = report.lines().rev().take(2).collect();
    assert!(last[1].starts_with("Progress: 2/"), "{report}");
    assert!(
        last[0].starts_with("Next: exercise 3") && last[0].contains("-p hint -- 3"),
        "{report}"
    );
    // The same in Bulgarian, with the exercise's Bulgarian title.
    let report = lang::with(lang::Lang::Bg, || progress_report(&graded));
    let last: Vec<&str> = report.lines().rev().take(2).collect();
    assert!(last[1].starts_with("Напредък: 2/"), "{report}");
    assert!(
        last[0].starts_with("Следва: задача 3 — Ламбертова BRDF")
            && last[0].contains("-p hint -- 3"),
        "{report}"
    );
    assert!(report.contains("· не е започната"), "{report}");
    let all: Vec<Graded> = graded
        .into_iter()
        .map(|g| Graded {
            outcome: Outcome::Passed,
            ..g
        })
        .collect();
    assert!(
        lang::with(lang::Lang::En, || progress_report(&all))
            .trim_end()
            .ends_with("All exercises pass. Well done!")
    );
}
