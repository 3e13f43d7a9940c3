//! The grader of the exercises in `exercises/`.
//!
//! Layered as the course's design describes:
//! 0. deterministic answers (stereo eyes, anaglyph, BRDF values and their
//!    normalizations, reflection, the density of a warp, change of measure,
//!    MIS weights, geometry term, splat values, the total brightness of a
//!    Metropolis chain): exact comparisons against the grader's own formulas; a wrong answer is compared with the answers
//!    of the usual mistakes in every case at once, and the one that matches
//!    is named ([`stats::recognise`]);
//! 1. sampling routines: chi-square against the grader's own pdf
//!    (exercise 7), with histograms of the student's samples on failure;
//! 2. estimators: integrals with known answers (furnaces, the albedo of a
//!    lobe by quadrature, the irradiance of a polygon light by Lambert's
//!    formula, the density of photons spread uniformly), z-tests that use the
//!    student's own variance (exercises 9–16);
//! 3. whole integrators: the Cornell box tile by tile against the renderer
//!    ([`compare`]; exercises 11, 12, 15, 18: the renderer's path tracer,
//!    bidirectional path tracer or instant radiosity renders the reference),
//!    and the `caustic` scene against its light tracer (exercise 14).
//!
//! Every grading function takes the student's functions as parameters
//! (`exNN::check(f) -> Result<(), String>`), so the grader's self-test can
//! feed it the reference solutions, correct variants and typical wrong
//! solutions. [`GRADERS`] grades the `exercises` crate itself;
//! [`outcome::grade`] turns a `todo!()` into "not started".
//! Fixed seeds everywhere: a given solution passes or fails deterministically;
//! each tolerance states the probability that a correct solution fails it.

pub mod bdpt_paths;
pub mod compare;
pub mod cone;
pub mod ex01_stereo_eyes;
pub mod ex02_anaglyph;
pub mod ex03_lambert;
pub mod ex04_phong;
pub mod ex05_cone_lobe;
pub mod ex06_mirror;
pub mod ex07_cosine_sampling;
pub mod ex08_phong_lobe_pdf;
pub mod ex09_albedo;
pub mod ex10_naive_recursive;
pub mod ex11_path_tracing;
pub mod ex12_nee;
pub mod ex13_mis;
pub mod ex14_light_tracing;
pub mod ex15_bdpt;
pub mod ex16_metropolis;
pub mod ex17_photon_mapping;
pub mod ex18_instant_radiosity;
pub mod messages;
pub mod outcome;
pub mod pictures;
pub mod polygon;
pub mod shortcuts;
pub mod stats;
pub mod texts;
pub mod watch;

pub use exercises;
pub use outcome::{Outcome, grade};

use std::time::Duration;

use exercises as ex;
use exercises::Exercise;

/// The checks of one exercise against the student's crate.
pub type Check = fn() -> Result<(), String>;

/// The grader of each exercise of the `exercises` crate, in lecture order
/// (names as in `exercises/info.toml`).
pub const GRADERS: &[(&str, Check)] = &[
    ("ex01_stereo_eyes", || {
        ex01_stereo_eyes::check(ex::ex01_stereo_eyes::stereo_eyes)
    }),
    ("ex02_anaglyph", || {
        ex02_anaglyph::check(ex::ex02_anaglyph::desaturate, ex::ex02_anaglyph::anaglyph)
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
    ("ex05_cone_lobe", || {
        ex05_cone_lobe::check(ex::ex05_cone_lobe::cone_lobe_normalization)
    }),
    ("ex06_mirror", || {
        ex06_mirror::check(ex::ex06_mirror::reflect, ex::ex06_mirror::mirror_sample)
    }),
    ("ex07_cosine_sampling", || {
        ex07_cosine_sampling::check(
            ex::ex07_cosine_sampling::sample_cosine_hemisphere,
            ex::ex07_cosine_sampling::cosine_hemisphere_pdf,
        )
    }),
    ("ex08_phong_lobe_pdf", || {
        ex08_phong_lobe_pdf::check(ex::ex08_phong_lobe_pdf::phong_lobe_pdf)
    }),
    ("ex09_albedo", || {
        ex09_albedo::check(ex::ex09_albedo::estimate_albedo)
    }),
    ("ex10_naive_recursive", || {
        ex10_naive_recursive::check(ex::ex10_naive_recursive::naive_radiance)
    }),
    ("ex11_path_tracing", || {
        ex11_path_tracing::check(ex::ex11_path_tracing::path_radiance)
    }),
    ("ex12_nee", || {
        ex12_nee::check(
            ex::ex12_nee::area_pdf_to_solid_angle,
            ex::ex12_nee::estimate_direct,
            ex::ex12_nee::path_radiance_nee,
        )
    }),
    ("ex13_mis", || {
        ex13_mis::check(ex::ex13_mis::path_radiance_mis)
    }),
    ("ex14_light_tracing", || {
        ex14_light_tracing::check(ex::ex14_light_tracing::trace_light_path)
    }),
    ("ex15_bdpt", || {
        ex15_bdpt::check(
            ex::ex15_bdpt::geometry_term,
            ex::ex15_bdpt::connect,
            ex::ex15_bdpt::mis_weight,
        )
    }),
    ("ex16_metropolis", || {
        ex16_metropolis::check(ex::ex16_metropolis::metropolis_chain)
    }),
    ("ex17_photon_mapping", || {
        ex17_photon_mapping::check(
            ex::ex17_photon_mapping::trace_photon_path,
            ex::ex17_photon_mapping::photon_radiance,
        )
    }),
    ("ex18_instant_radiosity", || {
        ex18_instant_radiosity::check(
            ex::ex18_instant_radiosity::generate_vpls,
            ex::ex18_instant_radiosity::gather,
        )
    }),
];

/// Grades the student's exercise `name` (`None` if there is no such exercise).
pub fn grade_exercise(name: &str) -> Option<Outcome> {
    let check = GRADERS.iter().find(|(n, _)| *n == name)?.1;
    let cut = exercises::registry()
        .iter()
        .find(|e| e.name == name)
        .and_then(shortcuts::shortcut);
    Some(cut.map_or_else(|| grade(check), Outcome::Failed))
}

/// How long one exercise may take to grade. A correct solution takes well
/// under a second on two cores (the table prints each exercise's time); an
/// exercise still running after this is reported as "an endless loop, or far
/// too slow", and the others are graded meanwhile.
pub const TIMEOUT: Duration = Duration::from_secs(20);

/// The result of grading one exercise.
#[derive(Clone, Debug)]
pub struct Graded {
    pub exercise: Exercise,
    pub outcome: Outcome,
    /// Wall-clock time of its grading (the budget if it timed out).
    pub seconds: f64,
}

/// Grades the exercises of the registry that `keep` selects, in order, on up
/// to `threads` threads, each within `timeout` (see [`grade_checks`]).
pub fn grade_selected(
    keep: impl Fn(&Exercise) -> bool,
    threads: usize,
    timeout: Duration,
) -> Vec<Graded> {
    let reg: Vec<Exercise> = exercises::registry().into_iter().filter(keep).collect();
    // A solution that calls the renderer's own answer fails before it runs.
    let shortcuts: Vec<Option<String>> = reg.iter().map(shortcuts::shortcut).collect();
    let checks = reg
        .iter()
        .zip(&shortcuts)
        .map(|(e, cut)| {
            if cut.is_some() {
                return None;
            }
            GRADERS.iter().find(|(n, _)| *n == e.name).map(|(_, c)| *c)
        })
        .collect();
    let results = grade_checks(checks, threads, timeout);
    reg.into_iter()
        .zip(results)
        .zip(shortcuts)
        .map(|((exercise, (outcome, seconds)), cut)| Graded {
            exercise,
            outcome: cut.map_or(outcome, Outcome::Failed),
            seconds,
        })
        .collect()
}

/// Grades every exercise (see [`grade_selected`]).
pub fn grade_all(threads: usize, timeout: Duration) -> Vec<Graded> {
    grade_selected(|_| true, threads, timeout)
}

/// Runs `checks` (`None`: no grader) on up to `threads` threads at once,
/// each with its own `timeout` counted from its start; outcomes and seconds
/// in the same order. A check still running at its deadline is reported as
/// failed and its thread is left behind (a thread cannot be stopped): its
/// slot goes to the next check, so one endless exercise delays the others by
/// at most `timeout`. The caller should exit the process when done.
pub fn grade_checks(
    checks: Vec<Option<Check>>,
    threads: usize,
    timeout: Duration,
) -> Vec<(Outcome, f64)> {
    use std::sync::mpsc;
    use std::time::Instant;
    let n = checks.len();
    let (tx, rx) = mpsc::channel::<(usize, Outcome, f64)>();
    let mut results: Vec<Option<(Outcome, f64)>> = vec![None; n];
    let mut running: Vec<(usize, Instant)> = Vec::new();
    let mut next = 0;
    while results.iter().any(Option::is_none) {
        while running.len() < threads.max(1) && next < n {
            let (i, check, tx) = (next, checks[next], tx.clone());
            let start = Instant::now();
            // The caller's language, also when it is a scope of its thread.
            let language = lang::current();
            std::thread::spawn(move || {
                let o = lang::with(language, || match check {
                    Some(c) => grade(c),
                    None => Outcome::Failed(tr!("report.no_grader")),
                });
                let _ = tx.send((i, o, start.elapsed().as_secs_f64()));
            });
            running.push((i, start));
            next += 1;
        }
        let deadline = running
            .iter()
            .map(|(_, s)| *s + timeout)
            .min()
            .expect("something is running");
        match rx.recv_timeout(deadline.saturating_duration_since(Instant::now())) {
            Ok((i, o, s)) => {
                if results[i].is_none() {
                    results[i] = Some((o, s));
                }
                running.retain(|(j, _)| *j != i);
            }
            Err(_) => {
                let now = Instant::now();
                for (i, start) in running.iter().filter(|(_, s)| now >= *s + timeout) {
                    results[*i] = Some((
                        Outcome::Failed(tr!("report.timeout", seconds = timeout.as_secs_f32())),
                        start.elapsed().as_secs_f64(),
                    ));
                }
                running.retain(|(_, s)| now < *s + timeout);
            }
        }
    }
    results.into_iter().map(|r| r.expect("graded")).collect()
}

/// The progress table of graded exercises, with the summary and the next
/// step as its last lines (`cargo test` prints it last), in the current
/// language.
pub fn progress_report(results: &[Graded]) -> String {
    let mut out = tr!("report.title") + "\n";
    for g in results {
        out.push_str(&tr!(
            "report.row",
            number = g.exercise.number().unwrap_or(0),
            name = g.exercise.name,
            outcome = g.outcome,
            seconds = g.seconds
        ));
        out.push('\n');
    }
    out.push_str(&summary(results));
    out
}

/// The last lines of [`progress_report`]: how many passed, failed or are not
/// started, and what to do next.
pub fn summary(results: &[Graded]) -> String {
    let done = results.iter().filter(|g| g.outcome.is_passed()).count();
    let failing = results.iter().filter(|g| g.outcome.is_failed()).count();
    let todo = results.len() - done - failing;
    let total = results.len();
    let mut out = tr!("report.progress", done, total, failing, todo) + "\n";
    let language = lang::current();
    let line = match results.iter().find(|g| !g.outcome.is_passed()) {
        Some(g) => tr!(
            "report.next",
            number = g.exercise.number().unwrap_or(0),
            title = g.exercise.title_in(language),
            slides = g.exercise.slide_in(language),
            file = g.exercise.file,
            hint = g.exercise.hint_command()
        ),
        None if results.len() == exercises::MODULES.len() => tr!("report.all_pass"),
        None => tr!("report.all_here_pass"),
    };
    out.push_str(&line);
    out.push('\n');
    out
}

/// The verdict of the exercises graded alone (`cargo test -p grading --test
/// exercises -- NAME`, and each save in `lesson11 exercises --watch`): each
/// one's outcome, then its hint command, or the next exercise once it passes.
pub fn exercise_report(results: &[Graded]) -> String {
    let registry = exercises::registry();
    let language = lang::current();
    let mut out = String::new();
    let mut line = |s: String| {
        out.push_str(&s);
        out.push('\n');
    };
    for g in results {
        let e = &g.exercise;
        line(tr!(
            "report.exercise",
            number = e.number().unwrap_or(0),
            title = e.title_in(language),
            file = e.file
        ));
        line(tr!(
            "report.exercise_outcome",
            outcome = g.outcome,
            seconds = g.seconds
        ));
        if g.outcome.is_passed() {
            // The next in the registry's order (numbers may skip).
            let next = registry.iter().skip_while(|n| n.name != e.name).nth(1);
            match next {
                Some(n) => line(tr!(
                    "report.next_alone",
                    number = n.number().unwrap_or(0),
                    title = n.title_in(language),
                    file = n.file
                )),
                None => line(tr!("report.last")),
            }
        } else {
            line(tr!("report.hint", hint = e.hint_command()));
        }
    }
    if results.is_empty() {
        line(tr!("report.no_match"));
    }
    out
}
