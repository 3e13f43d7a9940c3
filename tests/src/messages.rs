//! The grader's messages in English and Bulgarian: `tests/messages/en.toml`
//! and `tests/messages/bg.toml`, one table per exercise (`[ex03]`) and one
//! for the report (`[report]`), the same keys in both. [`tr!`](crate::tr)
//! fills a message's template in the current language ([`lang::current`]:
//! `LESSON11_LANG`, else the locale).
//!
//! A message names the mistake and its symptom, never the fix: the fixed
//! formula is only in the last hint, in both languages. A key missing in
//! Bulgarian falls back to English (the test `messages_exist_in_both_languages`
//! of `tests/tests/check_texts.rs` names it).

use std::cell::RefCell;
use std::collections::BTreeMap;
use std::fmt::Display;
use std::sync::OnceLock;

pub use lang::{self, Lang};

/// The English messages, as written.
pub const EN_TOML: &str = include_str!("../messages/en.toml");
/// The Bulgarian messages, as written.
pub const BG_TOML: &str = include_str!("../messages/bg.toml");

/// `section.key` → template, from the text of a messages file.
pub fn parse(text: &str) -> Result<BTreeMap<String, String>, String> {
    let table: BTreeMap<String, BTreeMap<String, String>> =
        toml::from_str(text).map_err(|e| e.to_string())?;
    Ok(table
        .into_iter()
        .flat_map(|(section, keys)| {
            keys.into_iter()
                .map(move |(k, v)| (format!("{section}.{k}"), v))
        })
        .collect())
}

/// The messages of `lang` (`section.key` → template).
///
/// # Panics
/// If a compiled-in messages file is malformed (a test proves it is not).
pub fn catalog(lang: Lang) -> &'static BTreeMap<String, String> {
    static EN: OnceLock<BTreeMap<String, String>> = OnceLock::new();
    static BG: OnceLock<BTreeMap<String, String>> = OnceLock::new();
    let (cell, text, file) = match lang {
        Lang::En => (&EN, EN_TOML, "en"),
        Lang::Bg => (&BG, BG_TOML, "bg"),
    };
    cell.get_or_init(|| parse(text).unwrap_or_else(|e| panic!("tests/messages/{file}.toml: {e}")))
}

/// The message `key` in `lang` with its placeholders filled; English if
/// `lang` lacks it, the key itself if English does too.
pub fn text_in(lang: Lang, key: &str, args: &[(&str, &dyn Display)]) -> String {
    let template = catalog(lang)
        .get(key)
        .or_else(|| catalog(Lang::En).get(key))
        .map_or(key, String::as_str);
    lang::fill(template, args)
}

/// The message `key` in the current language (see [`text_in`]).
pub fn text(key: &str, args: &[(&str, &dyn Display)]) -> String {
    LOG.with(|log| {
        if let Some(keys) = log.borrow_mut().as_mut() {
            keys.push(key.to_string());
        }
    });
    text_in(lang::current(), key, args)
}

thread_local! {
    static LOG: RefCell<Option<Vec<String>>> = const { RefCell::new(None) };
}

/// Runs `f` and returns, beside its result, the keys of the messages it
/// made on this thread, in order (the self-test compares a failure's keys
/// in both languages: the same keys name the same mistake).
pub fn keys_used<R>(f: impl FnOnce() -> R) -> (R, Vec<String>) {
    let outer = LOG.with(|log| log.borrow_mut().replace(Vec::new()));
    let r = f();
    let keys = LOG.with(|log| std::mem::replace(&mut *log.borrow_mut(), outer));
    (r, keys.unwrap_or_default())
}

/// A message of the grader in the current language:
/// `tr!("ex03.albedo", albedo, why = reason)` fills the template
/// `[ex03] albedo` of `tests/messages/{en,bg}.toml` (`{albedo:.3}`,
/// `{why}`); an argument is any `Display` value.
#[macro_export]
macro_rules! tr {
    ($key:literal $(, $name:ident $(= $value:expr)?)* $(,)?) => {
        $crate::messages::text(
            $key,
            &[$((stringify!($name), &$crate::tr!(@value $name $($value)?) as &dyn ::std::fmt::Display)),*],
        )
    };
    (@value $name:ident) => { $name };
    (@value $name:ident $value:expr) => { $value };
}

/// What is wrong between two catalogs, one line each (empty: nothing): a
/// key that one language lacks, or whose placeholders differ.
pub fn mismatches(en: &BTreeMap<String, String>, bg: &BTreeMap<String, String>) -> Vec<String> {
    let mut out = Vec::new();
    for (key, template) in en {
        match bg.get(key) {
            None => out.push(format!("{key}: missing in tests/messages/bg.toml")),
            Some(t) => {
                let (mut a, mut b) = (lang::placeholders(template), lang::placeholders(t));
                a.sort();
                b.sort();
                if a != b {
                    out.push(format!(
                        "{key}: placeholders {a:?} in English, {b:?} in Bulgarian"
                    ));
                }
            }
        }
    }
    for key in bg.keys().filter(|k| !en.contains_key(*k)) {
        out.push(format!("{key}: missing in tests/messages/en.toml"));
    }
    out
}

/// The keys of the `tr!("…")` calls in a Rust source.
pub fn keys_in_source(source: &str) -> Vec<String> {
    let pieces: Vec<&str> = source.split("tr!(").collect();
    pieces
        .windows(2)
        .filter(|w| !w[0].ends_with(|c: char| c.is_alphanumeric() || c == '_'))
        .filter_map(|w| {
            let rest = w[1].trim_start().strip_prefix('"')?;
            let key = &rest[..rest.find('"')?];
            let (section, name) = key.split_once('.')?;
            let word =
                |s: &str| !s.is_empty() && s.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
            (word(section) && word(name)).then(|| key.to_string())
        })
        .collect()
}
