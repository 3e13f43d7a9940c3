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

/// Grades every exercise, in order, on up to `threads` threads.
pub fn grade_all(threads: usize) -> Vec<(exercises::Exercise, Outcome)> {
    let reg = exercises::registry();
    let next = std::sync::atomic::AtomicUsize::new(0);
    let results = std::sync::Mutex::new(vec![None; reg.len()]);
    std::thread::scope(|s| {
        for _ in 0..threads.max(1) {
            s.spawn(|| {
                loop {
                    let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                    let Some(e) = reg.get(i) else { break };
                    let o = grade_exercise(&e.name).unwrap_or_else(|| {
                        Outcome::Failed(format!("the grader has no check for {}", e.name))
                    });
                    results.lock().expect("no panics while holding the lock")[i] = Some(o);
                }
            });
        }
    });
    let results = results.into_inner().expect("no poisoned lock");
    reg.into_iter()
        .zip(results)
        .map(|(e, o)| (e, o.expect("every exercise graded")))
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
