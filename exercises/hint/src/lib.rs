//! The exercises' registry (`exercises/info.toml`: title, slides and hints of
//! each exercise, in lecture order) and the hint counter, in a crate of their
//! own so that `cargo run -p hint -- N` answers in seconds on a fresh clone:
//! it builds two small dependencies, not the renderer.
//!
//! `lesson11 hint N` and the grader's messages use the same code; how many
//! hints of each exercise were shown is kept in `target/lesson11-hints.txt`.
//! It speaks the toolkit's language ([`lang::current`]: `LESSON11_LANG=bg|en`,
//! else the system locale); both languages' texts sit side by side, here and
//! in `info.toml`.

pub mod registry;

pub use lang;
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
            let numbers = numbers.join(", ");
            lang::pick(
                format!("there is no exercise {number}: the exercises are {numbers}"),
                format!("няма задача {number}: задачите са {numbers}"),
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
    // hints_bg has one hint for each English one (the registry checks it).
    let l = lang::current();
    let hints = e.hints_in(l);
    let mut out = String::new();
    let (title, slide, file) = (e.title_in(l), e.slide_in(l), &e.file);
    let _ = match l {
        lang::Lang::En => writeln!(
            out,
            "Exercise {number}: {title} (slide: {slide})\nFile: exercises/{file}"
        ),
        lang::Lang::Bg => writeln!(
            out,
            "Задача {number}: {title} (слайд: {slide})\nФайл: exercises/{file}"
        ),
    };
    let word = l.pick("hint", "подсказка");
    for (i, h) in hints.iter().take(now).enumerate() {
        let _ = writeln!(out, "  {word} {}/{}: {h}", i + 1, hints.len());
    }
    let cmd = e.hint_command();
    let _ = if now == hints.len() {
        match l {
            lang::Lang::En => writeln!(
                out,
                "That was the last hint; the solution is shown once your exercise passes (`cargo run -p lesson11 -- solution {number}`)."
            ),
            lang::Lang::Bg => writeln!(
                out,
                "Това беше последната подсказка; решението се показва, щом задачата ви минава (`cargo run -p lesson11 -- solution {number}`)."
            ),
        }
    } else {
        match l {
            lang::Lang::En => writeln!(out, "Run `{cmd}` again for the next hint."),
            lang::Lang::Bg => writeln!(out, "Изпълнете `{cmd}` отново за следващата подсказка."),
        }
    };
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
        let path = path.display();
        let _ = writeln!(
            out,
            "{}",
            lang::pick(
                format!("note: cannot remember the hints shown ({path}: {err})"),
                format!("бележка: не мога да запомня показаните подсказки ({path}: {err})"),
            )
        );
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use lang::Lang;

    #[test]
    fn an_unknown_number_lists_the_exercises() {
        let e = lang::with(Lang::En, || super::exercise(0).unwrap_err());
        assert!(e.contains("no exercise 0") && e.contains("1, 2, 3"), "{e}");
        let e = lang::with(Lang::Bg, || super::exercise(0).unwrap_err());
        assert!(e.contains("няма задача 0") && e.contains("1, 2, 3"), "{e}");
        assert!(super::exercise(1).is_ok());
    }

    #[test]
    fn every_exercise_has_its_title_and_hints_in_both_languages() {
        for e in super::registry() {
            for l in Lang::ALL {
                assert!(
                    !e.title_in(l).trim().is_empty(),
                    "{}: no title in {l}",
                    e.name
                );
                let hints = e.hints_in(l);
                assert_eq!(hints.len(), e.hints.len(), "{}: hints in {l}", e.name);
                for (i, h) in hints.iter().enumerate() {
                    assert!(
                        !h.trim().is_empty(),
                        "{}: hint {} in {l} is empty",
                        e.name,
                        i + 1
                    );
                }
            }
            // The Bulgarian texts are Bulgarian (Cyrillic), not a copy.
            assert_ne!(
                e.title, e.title_bg,
                "{}: title_bg is the English title",
                e.name
            );
            for (i, (en, bg)) in e.hints.iter().zip(&e.hints_bg).enumerate() {
                assert!(
                    en != bg && bg.chars().any(|c| ('а'..='я').contains(&c)),
                    "{}: hint {} in Bulgarian is not translated",
                    e.name,
                    i + 1
                );
            }
        }
    }
}
