//! The grader of the exercises in `exercises/`.
//!
//! Layered as the course's design describes:
//! 0. deterministic answers (stereo eyes, anaglyph, BRDF values, reflection,
//!    change of measure, geometry term, splat values): exact comparisons
//!    against the grader's own formulas, with a diagnosis of the usual
//!    mistakes;
//! 1. sampling routines: chi-square against the grader's own pdf
//!    (exercise 6);
//! 2. estimators: furnace-like integrals with known answers, z-tests that use
//!    the student's own variance (exercises 7, 8, 9, 11, 12, 13);
//! 3. whole integrators: the Cornell box tile by tile against the renderer
//!    ([`compare`]; exercises 9, 10).
//!
//! Every grading function takes the student's functions as parameters
//! (`exNN::check(f) -> Result<(), String>`), so the grader's self-test can
//! feed it the reference solutions, correct variants and typical wrong
//! solutions. [`GRADERS`] grades the `exercises` crate itself;
//! [`outcome::grade`] turns a `todo!()` into "not started".
//! Fixed seeds everywhere: a given solution passes or fails deterministically;
//! each tolerance states the probability that a correct solution fails it.

pub mod compare;
pub mod cone;
pub mod ex01_stereo_eyes;
pub mod ex02_anaglyph;
pub mod ex03_lambert;
pub mod ex04_phong;
pub mod ex05_mirror;
pub mod ex06_cosine_sampling;
pub mod ex07_albedo;
pub mod ex08_naive_recursive;
pub mod ex09_path_tracing;
pub mod ex10_nee;
pub mod ex11_mis;
pub mod ex12_light_tracing;
pub mod ex13_bdpt_connection;
pub mod outcome;
pub mod stats;

pub use exercises;
pub use outcome::{Outcome, grade};

use exercises as ex;

/// The grader of each exercise of the `exercises` crate, in lecture order
/// (names as in `exercises/info.toml`).
/// The checks of one exercise against the student's crate.
pub type Check = fn() -> Result<(), String>;

pub const GRADERS: &[(&str, Check)] = &[
    ("ex01_stereo_eyes", || {
        ex01_stereo_eyes::check(ex::ex01_stereo_eyes::stereo_eyes)
    }),
    ("ex02_anaglyph", || {
        ex02_anaglyph::check(ex::ex02_anaglyph::anaglyph)
    }),
    ("ex03_lambert", || {
        ex03_lambert::check(ex::ex03_lambert::lambert_eval)
    }),
    ("ex04_phong", || {
        ex04_phong::check(
            ex::ex04_phong::phong_normalization,
            ex::ex04_phong::phong_eval,
        )
    }),
    ("ex05_mirror", || {
        ex05_mirror::check(ex::ex05_mirror::reflect, ex::ex05_mirror::mirror_sample)
    }),
    ("ex06_cosine_sampling", || {
        ex06_cosine_sampling::check(
            ex::ex06_cosine_sampling::sample_cosine_hemisphere,
            ex::ex06_cosine_sampling::cosine_hemisphere_pdf,
        )
    }),
    ("ex07_albedo", || {
        ex07_albedo::check(ex::ex07_albedo::estimate_albedo)
    }),
    ("ex08_naive_recursive", || {
        ex08_naive_recursive::check(ex::ex08_naive_recursive::naive_radiance)
    }),
    ("ex09_path_tracing", || {
        ex09_path_tracing::check(ex::ex09_path_tracing::path_radiance)
    }),
    ("ex10_nee", || {
        ex10_nee::check(
            ex::ex10_nee::area_pdf_to_solid_angle,
            ex::ex10_nee::estimate_direct,
        )
    }),
    ("ex11_mis", || ex11_mis::check(ex::ex11_mis::mis_weight)),
    ("ex12_light_tracing", || {
        ex12_light_tracing::check(ex::ex12_light_tracing::splat_light_vertex)
    }),
    ("ex13_bdpt_connection", || {
        ex13_bdpt_connection::check(
            ex::ex13_bdpt_connection::geometry_term,
            ex::ex13_bdpt_connection::bdpt_mis_weight,
        )
    }),
];

/// Grades the student's exercise `name` (`None` if there is no such exercise).
pub fn grade_exercise(name: &str) -> Option<Outcome> {
    GRADERS
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, check)| grade(check))
}

/// How long [`grade_all`] waits for the whole suite (it takes seconds).
pub const TIMEOUT: std::time::Duration = std::time::Duration::from_secs(120);

/// Grades every exercise, in order, on up to `threads` threads. An exercise
/// still running after `timeout` (an endless loop in the student's code) is
/// reported as failed; its thread is left behind, so the caller should exit
/// the process when done.
pub fn grade_all(
    threads: usize,
    timeout: std::time::Duration,
) -> Vec<(exercises::Exercise, Outcome)> {
    let reg = exercises::registry();
    let checks = reg
        .iter()
        .map(|e| GRADERS.iter().find(|(n, _)| *n == e.name).map(|(_, c)| *c))
        .collect();
    let outcomes = grade_checks(checks, threads, timeout);
    reg.into_iter().zip(outcomes).collect()
}

/// Runs `checks` (`None`: no grader) on `threads` threads with an overall
/// `timeout`, outcomes in the same order.
pub fn grade_checks(
    checks: Vec<Option<Check>>,
    threads: usize,
    timeout: std::time::Duration,
) -> Vec<Outcome> {
    use std::sync::atomic::{AtomicUsize, Ordering};
    use std::sync::{Arc, mpsc};
    let n = checks.len();
    let names = Arc::new(checks);
    let next = Arc::new(AtomicUsize::new(0));
    let (tx, rx) = mpsc::channel();
    for _ in 0..threads.max(1) {
        let (names, next, tx) = (Arc::clone(&names), Arc::clone(&next), tx.clone());
        std::thread::spawn(move || {
            loop {
                let i = next.fetch_add(1, Ordering::Relaxed);
                let Some(check) = names.get(i) else { break };
                let o = match check {
                    Some(c) => grade(c),
                    None => Outcome::Failed("the grader has no check for this exercise".into()),
                };
                if tx.send((i, o)).is_err() {
                    break;
                }
            }
        });
    }
    drop(tx);
    let deadline = std::time::Instant::now() + timeout;
    let mut results: Vec<Option<Outcome>> = vec![None; n];
    while results.iter().any(Option::is_none) {
        let left = deadline.saturating_duration_since(std::time::Instant::now());
        match rx.recv_timeout(left) {
            Ok((i, o)) => results[i] = Some(o),
            Err(_) => break,
        }
    }
    results
        .into_iter()
        .map(|o| {
            o.unwrap_or_else(|| {
                Outcome::Failed(format!(
                    "did not finish within {} s — an endless loop? (every path must end: max_depth, roulette, or a ray that escapes)",
                    timeout.as_secs_f32()
                ))
            })
        })
        .collect()
}

/// The progress table of [`grade_all`]'s results and the next exercise.
pub fn progress_report(results: &[(exercises::Exercise, Outcome)]) -> String {
    let mut out = String::from("Exercises of Lecture 11\n");
    for (e, o) in results {
        out.push_str(&format!("  {} {:<24} {}\n", o.mark(), e.name, o));
    }
    let done = results.iter().filter(|(_, o)| o.is_passed()).count();
    let failing = results.iter().filter(|(_, o)| o.is_failed()).count();
    let todo = results.len() - done - failing;
    out.push_str(&format!(
        "Progress: {done}/{} done, {failing} failing, {todo} not started.\n",
        results.len()
    ));
    match results.iter().find(|(_, o)| !o.is_passed()) {
        Some((e, _)) => out.push_str(&format!(
            "Next: {} — {} (slide: {}); edit exercises/{}, hints: `cargo run -p lesson11 -- hint {}`.\n",
            e.name,
            e.title,
            e.slide,
            e.file,
            e.number().unwrap_or(0)
        )),
        None => out.push_str("All exercises pass. Well done!\n"),
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_endless_exercise_times_out_and_the_others_are_graded() {
        let endless: Check = || loop {
            std::thread::sleep(std::time::Duration::from_millis(50));
        };
        let fine: Check = || Ok(());
        let todo: Check = || todo!();
        let o = grade_checks(
            vec![Some(fine), Some(endless), Some(todo), None],
            2,
            std::time::Duration::from_millis(300),
        );
        assert_eq!(o[0], Outcome::Passed);
        assert!(
            matches!(&o[1], Outcome::Failed(r) if r.contains("endless loop")),
            "{:?}",
            o[1]
        );
        assert!(o[2].is_not_started());
        assert!(o[3].is_failed());
    }
}
