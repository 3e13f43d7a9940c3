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
    text_in(lang::current(), key, args)
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
