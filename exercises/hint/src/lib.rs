//! The exercises' registry (`exercises/info.toml`: title, slides and hints of
//! each exercise, in lecture order) and the hint counter, in a crate of their
//! own so that `cargo run -p hint -- N` answers in seconds on a fresh clone:
//! it builds two small dependencies, not the renderer.
//!
//! `lesson11 hint N` and the grader's messages use the same code; how many
//! hints of each exercise were shown is kept in `target/lesson11-hints.txt`.

pub mod registry;

pub use registry::{Exercise, INFO_TOML, parse, registry};

use std::fmt::Write as _;
use std::path::PathBuf;

/// The file that remembers how many hints of each exercise were shown.
pub fn hints_file() -> PathBuf {
    let target = std::env::var_os("CARGO_TARGET_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../../target")));
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

/// The exercise with this number, or an error that lists the numbers there are.
pub fn exercise(number: usize) -> Result<Exercise, String> {
    let reg = registry();
    let numbers: Vec<String> = reg
        .iter()
        .filter_map(|e| e.number())
        .map(|n| n.to_string())
        .collect();
    reg.into_iter()
        .find(|e| e.number() == Some(number))
        .ok_or_else(|| {
            format!(
                "there is no exercise {number}: the exercises are {}",
                numbers.join(", ")
            )
        })
}

/// Forgets how many hints were shown, for every exercise.
pub fn reset() {
    let _ = std::fs::remove_file(hints_file());
}

/// The text that shows the next hint of exercise `number` (all of them with
/// `all`), and remembers that it was shown. Hints come one at a time, the
/// formula last: reading ahead spoils the exercise.
pub fn next_hints(number: usize, all: bool) -> Result<String, String> {
    let e = exercise(number)?;
    let mut shown = read_shown();
    let before = shown
        .iter()
        .find(|(n, _)| *n == e.name)
        .map_or(0, |(_, c)| *c);
    let now = if all {
        e.hints.len()
    } else {
        (before + 1).min(e.hints.len())
    };
    let mut out = String::new();
    let _ = writeln!(out, "Exercise {number}: {} (slide: {})", e.title, e.slide);
    let _ = writeln!(out, "File: exercises/{}", e.file);
    for (i, h) in e.hints.iter().take(now).enumerate() {
        let _ = writeln!(out, "  hint {}/{}: {h}", i + 1, e.hints.len());
    }
    if now == e.hints.len() {
        let _ = writeln!(
            out,
            "That was the last hint; the solution is shown once your exercise passes (`cargo run -p lesson11 -- solution {number}`)."
        );
    } else {
        let _ = writeln!(out, "Run `{}` again for the next hint.", e.hint_command());
    }
    shown.retain(|(n, _)| *n != e.name);
    shown.push((e.name.clone(), now));
    let text: String = shown.iter().map(|(n, c)| format!("{n} {c}\n")).collect();
    let path = hints_file();
    if let Some(dir) = path.parent() {
        let _ = std::fs::create_dir_all(dir);
    }
    // Losing the counter only means the next hint is shown again. Written to
    // a temporary file and renamed, so it is never left half written.
    let tmp = path.with_extension("txt.tmp");
    if let Err(err) = std::fs::write(&tmp, text).and_then(|()| std::fs::rename(&tmp, &path)) {
        let _ = std::fs::remove_file(&tmp);
        let _ = writeln!(
            out,
            "note: cannot remember the hints shown ({}: {err})",
            path.display()
        );
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    #[test]
    fn an_unknown_number_lists_the_exercises() {
        let e = super::exercise(0).unwrap_err();
        assert!(e.contains("no exercise 0") && e.contains("1, 2, 3"), "{e}");
        assert!(super::exercise(1).is_ok());
    }
}
