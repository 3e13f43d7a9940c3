//! A table of numbers: shown on the page and written beside it as CSV.
//!
//! The page shows a table in the run's language; its CSV keeps English
//! column names and words whatever the language (a table made with
//! [`Table::in_both`]), so that scripts, the tests and the slides' checks
//! read the same columns from every run.

use std::path::Path;

use anyhow::{Context, Result};
use lang::Lang;

/// A table of numbers, shown on the page and written as CSV.
pub struct Table {
    pub caption: String,
    /// The column headings as the page shows them.
    pub header: Vec<String>,
    /// The rows as the page shows them.
    pub rows: Vec<Vec<String>>,
    /// The CSV's headings and rows in English, where they may differ from
    /// the page's (a table made with [`Table::in_both`]); `None`: the CSV is
    /// the page's table.
    csv: Option<(Vec<String>, Vec<Vec<String>>)>,
}

impl Table {
    /// A table whose page and CSV say the same.
    pub fn new(caption: &str, header: &[&str]) -> Self {
        Table {
            caption: caption.into(),
            header: header.iter().map(|h| h.to_string()).collect(),
            rows: Vec::new(),
            csv: None,
        }
    }

    /// A table with its headings in both languages, `(English, Bulgarian)`:
    /// the page shows the run's language, the CSV English. Add its rows
    /// with [`Table::push`].
    pub fn in_both(caption: &str, header: &[(&str, &str)]) -> Self {
        let mut table = Table::new(caption, &[]);
        table.header = header
            .iter()
            .map(|(en, bg)| lang::pick(*en, *bg).into())
            .collect();
        table.csv = Some((
            header.iter().map(|(en, _)| en.to_string()).collect(),
            Vec::new(),
        ));
        table
    }

    /// Adds a row made by `row` in the page's language and, for the CSV of
    /// a table in both languages, in English.
    pub fn push(&mut self, row: impl Fn(Lang) -> Vec<String>) {
        self.rows.push(row(lang::current()));
        if let Some((_, rows)) = &mut self.csv {
            rows.push(row(Lang::En));
        }
    }

    /// Writes the table as CSV (fields with commas or quotes are quoted).
    pub fn write_csv(&self, path: &Path) -> Result<()> {
        let field = |f: &str| {
            if f.contains([',', '"', '\n']) {
                format!("\"{}\"", f.replace('"', "\"\""))
            } else {
                f.to_string()
            }
        };
        let (header, rows) = match &self.csv {
            Some((header, rows)) => (header, rows),
            None => (&self.header, &self.rows),
        };
        let mut text = String::new();
        for row in std::iter::once(header).chain(rows) {
            text.push_str(&row.iter().map(|f| field(f)).collect::<Vec<_>>().join(","));
            text.push('\n');
        }
        raytracer::film::output::write_file(path, text)
            .with_context(|| format!("cannot write {}", path.display()))
    }
}
