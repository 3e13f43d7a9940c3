//! A table of numbers: shown on the page and written beside it as CSV.
//!
//! The page shows a table in the run's language; its CSV keeps English
//! column names and words whatever the language (a table made with
//! [`Table::in_both`], or with [`Table::new`] and headings that
//! [`HEADINGS`] translates), so that scripts, the tests and the slides'
//! checks read the same columns from every run.

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
    /// The CSV's headings in English, where they differ from the page's;
    /// `None`: the page's.
    csv_header: Option<Vec<String>>,
    /// The CSV's rows in English, for a table made with [`Table::in_both`];
    /// `None`: the page's rows.
    csv_rows: Option<Vec<Vec<String>>>,
}

/// The Bulgarian of the column headings that tables made with
/// [`Table::new`] use (chapters 8 and 9), in the lecture's words: the page
/// shows these, the CSV the English. A heading not listed (a symbol, `RMSE`,
/// `spp`) is the same in both languages.
pub const HEADINGS: [(&str, &str); 10] = [
    ("scene", "сцена"),
    ("algorithm", "алгоритъм"),
    ("max depth D", "максимална дълбочина D"),
    ("seconds", "секунди"),
    ("reference", "еталон"),
    ("reference noise floor", "дъно на шума на еталона"),
    ("unbiased", "неотместен"),
    ("bias² ± SE", "отместване² ± SE"),
    ("variance", "дисперсия"),
    ("first time RMSE ≤ target", "първо време с RMSE ≤ целта"),
];

impl Table {
    /// A table whose CSV has the headings `header` and the page's rows; the
    /// page shows the headings in the run's language ([`HEADINGS`]).
    pub fn new(caption: &str, header: &[&str]) -> Self {
        let shown = |h: &str| {
            match lang::current() {
                Lang::Bg => HEADINGS
                    .iter()
                    .find(|(en, _)| *en == h)
                    .map_or(h, |(_, bg)| *bg),
                _ => h,
            }
            .to_string()
        };
        let header: Vec<String> = header.iter().map(|h| h.to_string()).collect();
        let page: Vec<String> = header.iter().map(|h| shown(h)).collect();
        Table {
            caption: caption.into(),
            csv_header: (page != header).then_some(header),
            header: page,
            rows: Vec::new(),
            csv_rows: None,
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
        table.csv_header = Some(header.iter().map(|(en, _)| en.to_string()).collect());
        table.csv_rows = Some(Vec::new());
        table
    }

    /// Adds a row made by `row` in the page's language and, for the CSV of
    /// a table in both languages, in English.
    pub fn push(&mut self, row: impl Fn(Lang) -> Vec<String>) {
        self.rows.push(row(lang::current()));
        if let Some(rows) = &mut self.csv_rows {
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
        let header = self.csv_header.as_ref().unwrap_or(&self.header);
        let rows = self.csv_rows.as_ref().unwrap_or(&self.rows);
        let mut text = String::new();
        for row in std::iter::once(header).chain(rows) {
            text.push_str(&row.iter().map(|f| field(f)).collect::<Vec<_>>().join(","));
            text.push('\n');
        }
        raytracer::film::output::write_file(path, text)
            .with_context(|| format!("cannot write {}", path.display()))
    }
}
