//! A table of numbers: shown on the page and written beside it as CSV.

use std::path::Path;

use anyhow::{Context, Result};

/// A table of numbers, shown on the page and written as CSV.
pub struct Table {
    pub caption: String,
    pub header: Vec<String>,
    pub rows: Vec<Vec<String>>,
}

impl Table {
    pub fn new(caption: &str, header: &[&str]) -> Self {
        Table {
            caption: caption.into(),
            header: header.iter().map(|h| h.to_string()).collect(),
            rows: Vec::new(),
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
        let mut text = String::new();
        for row in std::iter::once(&self.header).chain(&self.rows) {
            text.push_str(&row.iter().map(|f| field(f)).collect::<Vec<_>>().join(","));
            text.push('\n');
        }
        raytracer::film::output::write_file(path, text)
            .with_context(|| format!("cannot write {}", path.display()))
    }
}
