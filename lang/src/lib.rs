//! The toolkit's one language setting, Bulgarian or English, and the fill-in
//! of message templates. Used by `hint`, `grading` and `lesson11` alike; it
//! has no dependencies, so the `hint` crate stays small.
//!
//! Where the language comes from, first found wins:
//! 1. [`with`]: a scope on one thread (the grader's self-test grades the same
//!    wrong solution in both languages at once);
//! 2. [`set`]: the program's choice (`lesson11 --lang bg|en`, which also
//!    passes it to the programs it starts through [`ENV`]);
//! 3. the variable `LESSON11_LANG` (`bg` or `en`; for the grader and `hint`);
//! 4. the system locale: the first non-empty of `LC_ALL`, `LC_MESSAGES`,
//!    `LANG` (POSIX order); one that starts with `bg` is Bulgarian;
//! 5. English.
//!
//! Which words the Bulgarian texts use for the lecture's terms is fixed by
//! the glossary, `lang/glossary.toml` ([`GLOSSARY`]).

use std::cell::Cell;
use std::fmt::{self, Display, Write as _};
use std::sync::atomic::{AtomicU8, Ordering};

/// The variable that chooses the language for the grader and `hint`.
pub const ENV: &str = "LESSON11_LANG";

/// The glossary: the lecture's terms in English and in Bulgarian, as both
/// decks and the program use them, and the words the Bulgarian texts avoid.
pub const GLOSSARY: &str = include_str!("../glossary.toml");

/// A language of the toolkit.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Lang {
    En,
    Bg,
}

impl Lang {
    /// Both languages, English first.
    pub const ALL: [Lang; 2] = [Lang::En, Lang::Bg];

    /// `bg`, `bg_BG.UTF-8`, `BG` → Bulgarian; `en`, `en_US.UTF-8` → English;
    /// anything else (`C`, `POSIX`, `de_DE`) → `None`.
    pub fn parse(s: &str) -> Option<Lang> {
        let s = s.trim().to_ascii_lowercase();
        let tag = s.split(['_', '-', '.', '@']).next().unwrap_or_default();
        match tag {
            "bg" => Some(Lang::Bg),
            "en" => Some(Lang::En),
            _ => None,
        }
    }

    /// The language of a locale string: Bulgarian if it starts with `bg`,
    /// else English (`C`, `POSIX`, `de_DE.UTF-8`, …).
    pub fn of_locale(locale: &str) -> Lang {
        if Lang::parse(locale) == Some(Lang::Bg) {
            Lang::Bg
        } else {
            Lang::En
        }
    }

    /// `en` or `bg`.
    pub fn code(self) -> &'static str {
        match self {
            Lang::En => "en",
            Lang::Bg => "bg",
        }
    }

    /// `en` or `bg` from this language's pair.
    pub fn pick<T>(self, en: T, bg: T) -> T {
        match self {
            Lang::En => en,
            Lang::Bg => bg,
        }
    }
}

impl Display for Lang {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.code())
    }
}

/// The language the environment asks for, `get` reading a variable:
/// `LESSON11_LANG` if it names one, else the locale (see the crate doc).
pub fn from_vars(get: impl Fn(&str) -> Option<String>) -> Lang {
    if let Some(l) = get(ENV).as_deref().and_then(Lang::parse) {
        return l;
    }
    ["LC_ALL", "LC_MESSAGES", "LANG"]
        .iter()
        .filter_map(|v| get(v))
        .find(|v| !v.trim().is_empty())
        .map_or(Lang::En, |v| Lang::of_locale(&v))
}

/// 0: not set; 1 + the language's index otherwise.
static CHOSEN: AtomicU8 = AtomicU8::new(0);

thread_local! {
    static SCOPED: Cell<Option<Lang>> = const { Cell::new(None) };
}

/// The program's choice (`lesson11 --lang`), above the environment.
pub fn set(lang: Lang) {
    CHOSEN.store(1 + lang as u8, Ordering::Relaxed);
}

/// The language to speak now (see the crate doc for the order).
pub fn current() -> Lang {
    if let Some(l) = SCOPED.with(Cell::get) {
        return l;
    }
    match CHOSEN.load(Ordering::Relaxed) {
        1 => Lang::En,
        2 => Lang::Bg,
        _ => from_vars(|v| std::env::var(v).ok()),
    }
}

/// Runs `f` with `lang` as this thread's language (nested scopes restore
/// the outer one, also when `f` panics).
pub fn with<R>(lang: Lang, f: impl FnOnce() -> R) -> R {
    struct Restore(Option<Lang>);
    impl Drop for Restore {
        fn drop(&mut self) {
            SCOPED.with(|s| s.set(self.0));
        }
    }
    let _restore = Restore(SCOPED.with(|s| s.replace(Some(lang))));
    f()
}

/// Picks `en` or `bg` by the [`current`] language.
pub fn pick<T>(en: T, bg: T) -> T {
    current().pick(en, bg)
}

/// The names of a template's placeholders (`{name}`, `{name:.3}`), in order,
/// each once; `{{` and `}}` are literal braces.
pub fn placeholders(template: &str) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    for piece in pieces(template) {
        if let Piece::Hole { name, .. } = piece
            && !out.iter().any(|n| n == name)
        {
            out.push(name.to_string());
        }
    }
    out
}

enum Piece<'a> {
    Text(&'a str),
    Hole {
        name: &'a str,
        spec: Spec,
        whole: &'a str,
    },
}

/// The formats a template may ask for: `[<|>][+][width][.precision]`.
#[derive(Clone, Copy, Default)]
struct Spec {
    right: bool,
    plus: bool,
    width: usize,
    precision: Option<usize>,
}

impl Spec {
    fn parse(spec: &str) -> Option<Spec> {
        let mut s = Spec::default();
        let mut rest = spec;
        if let Some(r) = rest.strip_prefix('>') {
            (s.right, rest) = (true, r);
        } else if let Some(r) = rest.strip_prefix('<') {
            rest = r;
        }
        if let Some(r) = rest.strip_prefix('+') {
            (s.plus, rest) = (true, r);
        }
        let (width, precision) = rest.split_once('.').unwrap_or((rest, ""));
        if !width.is_empty() {
            s.width = width.parse().ok()?;
        }
        if rest.contains('.') {
            s.precision = Some(precision.parse().ok()?);
        }
        Some(s)
    }
}

fn pieces(template: &str) -> Vec<Piece<'_>> {
    let mut out = Vec::new();
    let mut rest = template;
    while let Some(i) = rest.find(['{', '}']) {
        out.push(Piece::Text(&rest[..i]));
        let brace = &rest[i..i + 1];
        if rest[i + 1..].starts_with(brace) {
            out.push(Piece::Text(brace));
            rest = &rest[i + 2..];
            continue;
        }
        let close = if brace == "{" {
            rest[i..].find('}').map(|j| i + j)
        } else {
            None
        };
        let Some(close) = close else {
            out.push(Piece::Text(brace));
            rest = &rest[i + 1..];
            continue;
        };
        let inner = &rest[i + 1..close];
        let (name, spec) = inner.split_once(':').unwrap_or((inner, ""));
        let spec = Spec::parse(spec);
        let valid = !name.is_empty() && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
        if let (true, Some(spec)) = (valid, spec) {
            out.push(Piece::Hole {
                name,
                spec,
                whole: &rest[i..=close],
            });
        } else {
            out.push(Piece::Text(&rest[i..=close]));
        }
        rest = &rest[close + 1..];
    }
    out.push(Piece::Text(rest));
    out
}

/// The template with its placeholders filled: `{name}` by the argument's
/// `Display`, `{name:.3}` with three decimals, `{name:+.1}` with a sign too
/// (for numbers), `{name:>2}`, `{name:<22}` padded to a width (other formats
/// are formatted by the caller). A placeholder without an argument stays as
/// written, so a test can find it.
pub fn fill(template: &str, args: &[(&str, &dyn Display)]) -> String {
    let mut out = String::with_capacity(template.len() + 16);
    for piece in pieces(template) {
        match piece {
            Piece::Text(t) => out.push_str(t),
            Piece::Hole { name, spec, whole } => match args.iter().find(|(n, _)| *n == name) {
                None => out.push_str(whole),
                Some((_, v)) => {
                    let mut s = String::new();
                    let _ = match (spec.plus, spec.precision) {
                        (false, None) => write!(s, "{v}"),
                        (true, None) => write!(s, "{v:+}"),
                        (false, Some(p)) => write!(s, "{v:.p$}"),
                        (true, Some(p)) => write!(s, "{v:+.p$}"),
                    };
                    let pad = spec.width.saturating_sub(s.chars().count());
                    if spec.right {
                        out.extend(std::iter::repeat_n(' ', pad));
                        out.push_str(&s);
                    } else {
                        out.push_str(&s);
                        out.extend(std::iter::repeat_n(' ', pad));
                    }
                }
            },
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn vars<'a>(pairs: &'a [(&'a str, &'a str)]) -> impl Fn(&str) -> Option<String> + 'a {
        move |v| {
            pairs
                .iter()
                .find(|(k, _)| *k == v)
                .map(|(_, x)| x.to_string())
        }
    }

    #[test]
    fn the_locale_chooses_unless_lesson11_lang_does() {
        assert_eq!(from_vars(vars(&[])), Lang::En);
        assert_eq!(from_vars(vars(&[("LANG", "bg_BG.UTF-8")])), Lang::Bg);
        assert_eq!(from_vars(vars(&[("LANG", "C")])), Lang::En);
        assert_eq!(from_vars(vars(&[("LANG", "de_DE.UTF-8")])), Lang::En);
        // LC_ALL above LC_MESSAGES above LANG; an empty one is skipped.
        let l = [("LC_ALL", "C"), ("LANG", "bg_BG.UTF-8")];
        assert_eq!(from_vars(vars(&l)), Lang::En);
        let l = [("LC_ALL", ""), ("LC_MESSAGES", "bg_BG"), ("LANG", "C")];
        assert_eq!(from_vars(vars(&l)), Lang::Bg);
        // LESSON11_LANG above the locale, if it names a language.
        let l = [("LESSON11_LANG", "en"), ("LANG", "bg_BG.UTF-8")];
        assert_eq!(from_vars(vars(&l)), Lang::En);
        let l = [("LESSON11_LANG", "bg"), ("LC_ALL", "C")];
        assert_eq!(from_vars(vars(&l)), Lang::Bg);
        let l = [("LESSON11_LANG", "xx"), ("LANG", "bg_BG.UTF-8")];
        assert_eq!(from_vars(vars(&l)), Lang::Bg);
    }

    #[test]
    fn a_scope_sets_the_language_of_its_thread_only() {
        let outer = current();
        with(Lang::Bg, || {
            assert_eq!(current(), Lang::Bg);
            with(Lang::En, || assert_eq!(current(), Lang::En));
            assert_eq!(current(), Lang::Bg);
            let other = std::thread::spawn(current).join().unwrap();
            assert_eq!(other, outer);
        });
        assert_eq!(current(), outer);
    }

    #[test]
    fn templates_are_filled_by_name_with_precision_and_sign() {
        let x = 0.123_456f32;
        let why = "причина";
        let args: [(&str, &dyn Display); 3] = [("x", &x), ("why", &why), ("n", &3)];
        assert_eq!(
            fill("x = {x:.3} ({x:+.1}), {n} — {why}", &args),
            "x = 0.123 (+0.1), 3 — причина"
        );
        assert_eq!(fill("{{x}} {missing} {x", &args), "{x} {missing} {x");
        assert_eq!(
            fill("[{n:>3}|{why:<8}|{x:>7.2}]", &args),
            "[  3|причина |   0.12]"
        );
        assert_eq!(fill("{x:?} {n:x}", &args), "{x:?} {n:x}");
        assert_eq!(placeholders("{a} {b:.2} {a} {{c}}"), ["a", "b"]);
    }
}
