//! The page that shows the lesson's pictures: one self-contained HTML file,
//! no scripts and no network, in the language of the run (`--lang`): the
//! chapters write their titles, texts and captions in it, and the page
//! declares it (`<html lang>`).

pub mod figure;
pub mod table;

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result};

pub use figure::{Figure, Picture, seconds_number, seconds_text};
pub use table::Table;

/// One chapter of the page.
pub struct Section {
    pub title: String,
    pub text: String,
    pub figures: Vec<Figure>,
    pub tables: Vec<Table>,
}

impl Section {
    pub fn new(title: &str, text: &str) -> Self {
        Section {
            title: title.into(),
            text: text.into(),
            figures: Vec::new(),
            tables: Vec::new(),
        }
    }
}

/// The whole page.
pub struct Page {
    pub title: String,
    /// A paragraph under the title (may be empty).
    pub intro: String,
    pub sections: Vec<Section>,
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

impl Page {
    pub fn new(title: &str) -> Self {
        Page {
            title: title.into(),
            intro: String::new(),
            sections: Vec::new(),
        }
    }

    pub fn to_html(&self) -> String {
        let mut h = String::new();
        let _ = write!(
            h,
            "<!doctype html>\n<html lang=\"{l}\"><head><meta charset=\"utf-8\"><title>{t}</title>\n<style>\
             body{{font-family:system-ui,sans-serif;max-width:72rem;margin:2rem auto;padding:0 1rem;background:#111;color:#eee}}\
             figure{{display:inline-block;margin:0.5rem;vertical-align:top;max-width:20rem}}\
             img{{width:100%;image-rendering:pixelated;border:1px solid #333}}\
             figcaption{{font-size:0.9rem;color:#bbb}} table{{border-collapse:collapse;margin:1rem 0}} td,th{{border:1px solid #444;padding:0.2rem 0.6rem;text-align:right}} caption{{text-align:left;color:#bbb}} a{{color:#8cf}}</style></head><body>\n<h1>{t}</h1>\n",
            t = escape(&self.title),
            l = lang::current().code()
        );
        if !self.intro.is_empty() {
            let _ = writeln!(h, "<p>{}</p>", escape(&self.intro));
        }
        for s in &self.sections {
            let _ = writeln!(
                h,
                "<section><h2>{}</h2><p>{}</p>",
                escape(&s.title),
                escape(&s.text)
            );
            for f in &s.figures {
                let exr = f.exr.as_ref().map_or(String::new(), |e| {
                    format!(" · <a href=\"{}\">EXR</a>", escape(e))
                });
                // What the caption states of a render, for tests and scripts to check it by.
                let mut data = String::new();
                if let Some(spp) = f.spp {
                    let _ = write!(data, " data-spp=\"{spp}\"");
                }
                if let Some(stops) = f.exposure {
                    let _ = write!(data, " data-exposure=\"{stops}\"");
                }
                // Never blown up above twice its size.
                let style = f.width.map_or(String::new(), |w| {
                    format!(" style=\"max-width:{}px\"", 2 * w)
                });
                let _ = writeln!(
                    h,
                    "<figure{data}><a href=\"{src}\"><img src=\"{src}\"{style} alt=\"{cap}\"></a><figcaption>{cap}{exr}</figcaption></figure>",
                    src = escape(&f.src),
                    cap = escape(&f.caption)
                );
            }
            for t in &s.tables {
                let _ = write!(h, "<table><caption>{}</caption><tr>", escape(&t.caption));
                for c in &t.header {
                    let _ = write!(h, "<th>{}</th>", escape(c));
                }
                h.push_str("</tr>\n");
                for row in &t.rows {
                    h.push_str("<tr>");
                    for c in row {
                        let _ = write!(h, "<td>{}</td>", escape(c));
                    }
                    h.push_str("</tr>\n");
                }
                h.push_str("</table>\n");
            }
            h.push_str("</section>\n");
        }
        h.push_str("</body></html>\n");
        h
    }

    /// Writes the page as `dir/file`.
    pub fn write(&self, dir: &Path, file: &str) -> Result<PathBuf> {
        let path = dir.join(file);
        raytracer::film::output::write_file(&path, self.to_html())
            .with_context(|| format!("cannot write {}", path.display()))?;
        Ok(path)
    }
}
