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
  --reset  forget how many hints were shown (for every exercise)

The language is Bulgarian or English: LESSON11_LANG=bg|en, else the system
locale (LC_ALL, LC_MESSAGES, LANG starting with `bg`: Bulgarian).";

const USAGE_BG: &str = "\
Показва следващата подсказка за задача N, по една при всяко питане.
Подсказките вървят от идеята към формулата; формулата винаги е последна,
така че четенето напред разваля задачата.

Употреба: cargo run -q -p hint -- N [--all]
          cargo run -q -p hint -- --reset

  N        номерът на задачата (1, 2, …), както ги изброява проверката
  --all    показва наведнъж всички подсказки за задача N
  --reset  забравя колко подсказки са показани (за всички задачи)

Езикът е български или английски: LESSON11_LANG=bg|en, иначе езикът на
системата (LC_ALL, LC_MESSAGES, LANG, започващ с `bg`: български).";

fn main() -> ExitCode {
    let (mut number, mut all, mut reset) = (None, false, false);
    for a in std::env::args().skip(1) {
        match a.as_str() {
            "-h" | "--help" => {
                say(&format!("{}\n", hint::lang::pick(USAGE, USAGE_BG)));
                return ExitCode::SUCCESS;
            }
            "--all" => all = true,
            "--reset" => reset = true,
            n => match n.parse::<usize>() {
                Ok(n) if number.is_none() => number = Some(n),
                _ => {
                    eprintln!(
                        "{}",
                        hint::lang::pick(
                            format!("hint: `{n}` is not an exercise number (try --help)"),
                            format!("hint: `{n}` не е номер на задача (вижте --help)"),
                        )
                    );
                    return ExitCode::from(2);
                }
            },
        }
    }
    if reset {
        hint::reset();
        say(hint::lang::pick(
            "Hint counters reset.\n",
            "Броячите на подсказките са нулирани.\n",
        ));
        return ExitCode::SUCCESS;
    }
    let Some(number) = number else {
        eprintln!(
            "{}",
            hint::lang::pick(
                "hint: which exercise? `cargo run -q -p hint -- N` (try --help)",
                "hint: коя задача? `cargo run -q -p hint -- N` (вижте --help)",
            )
        );
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
