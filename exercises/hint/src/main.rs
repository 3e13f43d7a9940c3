//! `cargo run -p hint -- N`: the next hint of exercise N (see the crate doc).

use std::io::Write;
use std::process::ExitCode;

const USAGE: &str = "\
Show the next hint of exercise N, one more each time you ask.
Hints go from the idea to the formula; the formula is always the last one,
so reading ahead spoils the exercise.

Usage: cargo run -q -p hint -- N [--all]
       cargo run -q -p hint -- --reset

  N        the exercise number (1, 2, …), as the grader lists them
  --all    show every hint of exercise N at once
  --reset  forget how many hints were shown (for every exercise)";

fn main() -> ExitCode {
    let (mut number, mut all, mut reset) = (None, false, false);
    for a in std::env::args().skip(1) {
        match a.as_str() {
            "-h" | "--help" => {
                say(&format!("{USAGE}\n"));
                return ExitCode::SUCCESS;
            }
            "--all" => all = true,
            "--reset" => reset = true,
            n => match n.parse::<usize>() {
                Ok(n) if number.is_none() => number = Some(n),
                _ => {
                    eprintln!("hint: `{n}` is not an exercise number (try --help)");
                    return ExitCode::from(2);
                }
            },
        }
    }
    if reset {
        hint::reset();
        say("Hint counters reset.\n");
        return ExitCode::SUCCESS;
    }
    let Some(number) = number else {
        eprintln!("hint: which exercise? `cargo run -q -p hint -- N` (try --help)");
        return ExitCode::from(2);
    };
    match hint::next_hints(number, all) {
        Ok(text) => {
            say(&text);
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("hint: {e}");
            ExitCode::from(2)
        }
    }
}

/// Standard output that cannot panic: a closed pipe (`… | head -1`) or a
/// full device ends the program quietly instead of with a panic.
fn say(text: &str) {
    let _ = std::io::stdout().write_all(text.as_bytes());
}
