//! clap's own error lines in Bulgarian: "error: unexpected argument …",
//! "Usage: …" and "For more information, try '--help'" are clap's English
//! texts, so under Bulgarian the program writes its own line for each kind
//! of clap error, naming the same argument and value from the error's
//! context, and exits with clap's code (2). `--help` and `--version` go
//! through clap unchanged (they are not errors), and so does everything in
//! English.

use clap::error::{ContextKind, ContextValue, ErrorKind};
use lang::Lang;

/// Exits on `e` as clap would, in the program's language.
pub fn exit(e: clap::Error) -> ! {
    let help = e.kind() == ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand;
    if lang::current() == Lang::En || !e.use_stderr() || help {
        e.exit();
    }
    eprint!("{}", bulgarian(&e));
    std::process::exit(e.exit_code());
}

/// The reasons Rust's number parsers give (clap passes them on), in
/// Bulgarian; any other reason as it is.
pub fn why_bg(why: &str) -> &str {
    match why {
        "invalid digit found in string" => "не е цяло неотрицателно число",
        "cannot parse integer from empty string" | "cannot parse float from empty string" => {
            "празно поле"
        }
        "number too large to fit in target type" => "твърде голямо число",
        "number too small to fit in target type" => "твърде малко число",
        "invalid float literal" => "не е число",
        other => other,
    }
}

/// A context value as text: one string, or a list joined by ", ".
fn text(e: &clap::Error, kind: ContextKind) -> Option<String> {
    match e.get(kind)? {
        ContextValue::String(s) => Some(s.clone()),
        ContextValue::Strings(v) => Some(v.join(", ")),
        ContextValue::StyledStr(s) => Some(s.to_string()),
        ContextValue::StyledStrs(v) => Some(
            v.iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
                .join(", "),
        ),
        ContextValue::Number(n) => Some(n.to_string()),
        _ => None,
    }
}

/// The whole message in Bulgarian: the error's line, a suggestion if clap
/// has one, the usage line, and where to read more.
pub fn bulgarian(e: &clap::Error) -> String {
    let arg = text(e, ContextKind::InvalidArg).unwrap_or_default();
    let value = text(e, ContextKind::InvalidValue).unwrap_or_default();
    let line = match e.kind() {
        ErrorKind::UnknownArgument => format!("непознат аргумент „{arg}“"),
        ErrorKind::InvalidSubcommand => format!(
            "непозната команда „{}“",
            text(e, ContextKind::InvalidSubcommand).unwrap_or_default()
        ),
        ErrorKind::InvalidValue if value.is_empty() => {
            format!("{arg} иска стойност, а не е дадена")
        }
        ErrorKind::InvalidValue => {
            let valid = text(e, ContextKind::ValidValue)
                .map(|v| format!(" (възможни стойности: {v})"))
                .unwrap_or_default();
            format!("„{value}“ не е допустима стойност за {arg}{valid}")
        }
        ErrorKind::ValueValidation => {
            // The reason is the last part of clap's own line.
            let rendered = e.render().to_string();
            let first = rendered.lines().next().unwrap_or_default();
            let why = first.rsplit_once("': ").map_or("", |(_, why)| why.trim());
            let why = why_bg(why);
            if why.is_empty() {
                format!("„{value}“ не е допустима стойност за {arg}")
            } else {
                format!("„{value}“ не е допустима стойност за {arg}: {why}")
            }
        }
        ErrorKind::NoEquals => format!("{arg} иска стойността си след „=“"),
        ErrorKind::TooManyValues => format!("твърде много стойности за {arg}: „{value}“"),
        ErrorKind::TooFewValues | ErrorKind::WrongNumberOfValues => {
            format!("{arg} иска друг брой стойности")
        }
        ErrorKind::ArgumentConflict => match text(e, ContextKind::PriorArg) {
            Some(prior) if prior != arg => format!("{arg} не може да се дава заедно с {prior}"),
            _ => format!("{arg} може да се даде само веднъж"),
        },
        ErrorKind::MissingRequiredArgument => format!("липсва задължителният аргумент {arg}"),
        ErrorKind::MissingSubcommand => "липсва команда".to_string(),
        _ => "грешен команден ред".to_string(),
    };
    let mut out = format!("грешка: {line}\n");
    let suggested = text(e, ContextKind::SuggestedArg)
        .or_else(|| text(e, ContextKind::SuggestedSubcommand))
        .or_else(|| text(e, ContextKind::SuggestedValue));
    if let Some(s) = suggested {
        out.push_str(&format!("\n  подсказка: може би „{s}“?\n"));
    }
    if let Some(usage) = text(e, ContextKind::Usage) {
        let usage = usage.trim().trim_start_matches("Usage:").trim();
        out.push_str(&format!("\nУпотреба: {usage}\n"));
    }
    out.push_str("\nЗа повече информация: „--help“.\n");
    out
}
