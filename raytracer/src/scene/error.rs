//! Scene errors that say where the mistake is: file, line, column and the
//! field, e.g. `cornell.toml:12:10: shapes[3].radius: must be positive, got -1`.
//!
//! Lecture topic: none (tooling). Students edit scene files; an error that
//! names the exact field lets them fix it without reading the loader.
//!
//! Every error the loader finds carries the byte range of the offending text
//! (the toml crate's `Error::span()` for syntax and type errors, a
//! `toml::Spanned` value for the checks made after parsing). The range is
//! turned into a 1-based line and column, and the field path is found by
//! walking the parsed document for the deepest key whose text contains it.

use std::fmt;
use std::ops::Range;

use toml::Spanned;
use toml::de::{DeTable, DeValue};

/// A scene that cannot be loaded, and why.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SceneError {
    /// The file as the user named it, or `builtin:NAME` for a built-in scene.
    pub file: String,
    /// 1-based line of the offending text, if the error has a place in the file.
    pub line: Option<usize>,
    /// 1-based column (in characters) of the offending text.
    pub column: Option<usize>,
    /// The field, e.g. `shapes[3].radius` (empty if the error is about the
    /// whole file).
    pub path: String,
    /// What is wrong and what was expected.
    pub message: String,
}

impl SceneError {
    /// An error that concerns the file as a whole (not found, unreadable, …).
    pub fn whole_file(file: impl Into<String>, message: impl Into<String>) -> Self {
        SceneError {
            file: file.into(),
            line: None,
            column: None,
            path: String::new(),
            message: message.into(),
        }
    }

    /// An error at the byte range `span` of the scene text `text`: the line,
    /// column and field path are computed from the range.
    pub fn at(file: &str, text: &str, span: Option<Range<usize>>, message: String) -> Self {
        let mut error = SceneError::whole_file(file, message);
        if let Some(span) = span {
            let (line, column) = line_column(text, span.start);
            error.line = Some(line);
            error.column = Some(column);
            error.path = field_path(text, &span);
        }
        error
    }

    /// The error of the toml crate (syntax, unknown field, wrong type) in the
    /// scene's words.
    pub fn from_toml(file: &str, text: &str, error: &toml::de::Error) -> Self {
        let span = error.span();
        let message = error.message().trim();
        let spanned = span
            .as_ref()
            .and_then(|s| text.get(s.clone()))
            .map(str::trim);
        // The line of the error, to tell a `[table]` header from a `key = …`.
        let line = span.as_ref().and_then(|s| {
            let start = text.get(..s.start)?.rfind('\n').map_or(0, |i| i + 1);
            let end = text[start..].find('\n').map_or(text.len(), |i| start + i);
            Some(text[start..end].trim())
        });
        let message = match (message, spanned, line) {
            // The toml crate does not say which key; its span does.
            ("duplicate key", Some(_), Some(header)) if header.starts_with('[') => {
                // `[a.b]` or `[[a]]`, without a trailing comment.
                let close = if header.starts_with("[[") { "]]" } else { "]" };
                let header = header
                    .find(close)
                    .map_or(header, |i| &header[..i + close.len()]);
                format!("duplicate table `{header}`: each table may be defined only once")
            }
            ("duplicate key", Some(key), _) if !key.is_empty() => {
                format!("duplicate key `{key}`: each key may appear only once in a table")
            }
            (m, _, _) if m.contains("recursion") => {
                "arrays or tables nested too deeply: a scene file needs only a few levels".into()
            }
            (m, _, _) => m.to_string(),
        };
        SceneError::at(file, text, span, message)
    }
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.file)?;
        if let (Some(line), Some(column)) = (self.line, self.column) {
            write!(f, ":{line}:{column}")?;
        }
        if !self.path.is_empty() {
            write!(f, ": {}", self.path)?;
        }
        write!(f, ": {}", self.message)
    }
}

impl std::error::Error for SceneError {}

/// 1-based line and column (in characters) of the byte offset `offset`.
pub fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let mut offset = offset.min(text.len());
    while !text.is_char_boundary(offset) {
        offset -= 1;
    }
    let before = &text[..offset];
    let line = before.matches('\n').count() + 1;
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    let column = before[line_start..].chars().count() + 1;
    (line, column)
}

/// The path of the deepest field whose key or value contains `span`, such as
/// `shapes[3].radius` or `materials.white.albedo` (empty if none does, or if
/// the text is not valid TOML).
pub fn field_path(text: &str, span: &Range<usize>) -> String {
    let Ok(root) = DeTable::parse(text) else {
        return String::new();
    };
    let mut path = String::new();
    walk_table(root.get_ref(), span, &mut path);
    path
}

fn contains(outer: &Range<usize>, inner: &Range<usize>) -> bool {
    outer.start <= inner.start && inner.end <= outer.end
}

/// Appends to `path` the key (and deeper keys) of `table` that contain `span`.
/// Returns whether one did. Tables of `[[array]]` headers do not always span
/// their body, so every child is searched, not only those whose span
/// contains the target.
fn walk_table(table: &DeTable<'_>, span: &Range<usize>, path: &mut String) -> bool {
    for (key, value) in table.iter() {
        let len = path.len();
        if !path.is_empty() {
            path.push('.');
        }
        path.push_str(key.get_ref());
        if contains(&key.span(), span) {
            return true;
        }
        if walk_value(value, span, path) {
            return true;
        }
        path.truncate(len);
    }
    false
}

fn walk_value(value: &Spanned<DeValue<'_>>, span: &Range<usize>, path: &mut String) -> bool {
    let deeper = match value.get_ref() {
        DeValue::Table(table) => walk_table(table, span, path),
        DeValue::Array(array) => array.iter().enumerate().any(|(i, item)| {
            let len = path.len();
            path.push_str(&format!("[{i}]"));
            let found = walk_value(item, span, path);
            if !found {
                path.truncate(len);
            }
            found
        }),
        _ => false,
    };
    deeper || contains(&value.span(), span)
}
