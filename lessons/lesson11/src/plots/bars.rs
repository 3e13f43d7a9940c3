//! Stacked bar charts: one bar per label, its parts stacked in the palette's
//! order (bias² under variance, so that the bar's height is the MSE).

use std::fmt::Write as _;
use std::path::Path;

use anyhow::{Context, Result};

use super::chart::{FONT, TITLE_FONT, legend_layout};
use super::palette::OTHERS as COLORS;
use super::series::escape;

/// A stacked bar chart with a linear y axis from 0.
pub struct Bars {
    pub title: String,
    pub y_label: String,
    /// The names of the parts of every bar, bottom first.
    pub parts: Vec<String>,
    /// One bar per entry: its label and its parts' values (≥ 0), bottom first.
    pub bars: Vec<(String, Vec<f64>)>,
}

const W: f64 = 560.0;
const H: f64 = 380.0;
const LEFT: f64 = 84.0;
const RIGHT: f64 = 20.0;
const TOP: f64 = 40.0;
const BOTTOM: f64 = 110.0;

/// A round step for about five ticks up to `hi`.
pub fn step(hi: f64) -> f64 {
    let raw = hi.max(1e-30) / 5.0;
    let mag = 10f64.powf(raw.log10().floor());
    [1.0, 2.0, 5.0, 10.0]
        .iter()
        .map(|m| m * mag)
        .find(|s| hi / s <= 6.0)
        .unwrap_or(10.0 * mag)
}

impl Bars {
    /// The chart as an SVG document.
    pub fn to_svg(&self) -> String {
        let top = self
            .bars
            .iter()
            .map(|(_, v)| v.iter().map(|x| x.max(0.0)).sum::<f64>())
            .fold(0.0f64, f64::max);
        let top = if top > 0.0 { top * 1.05 } else { 1.0 };
        let py = |v: f64| H - BOTTOM - v / top * (H - TOP - BOTTOM);
        let slot = (W - LEFT - RIGHT) / self.bars.len().max(1) as f64;
        // The bars' labels slant down to the right: the last one may need
        // the chart to be wider (a character taken as 0.6 of the font size).
        let last = self.bars.last().map_or(0, |(l, _)| l.chars().count());
        let reach = LEFT + slot * (self.bars.len() as f64 - 0.5) + 0.6 * FONT * last as f64 * 0.87;
        let width = W.max(reach + 6.0);
        let parts: Vec<&str> = self.parts.iter().map(String::as_str).collect();
        let (columns, column, rows) = legend_layout(&parts, width);
        let height = H + 22.0 * rows as f64 + 8.0;
        let mut s = String::new();
        let _ = writeln!(
            s,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{width:.0}\" height=\"{height}\" viewBox=\"0 0 {width:.0} {height}\" \
             font-family=\"sans-serif\" font-size=\"{FONT}\"><rect width=\"100%\" height=\"100%\" fill=\"white\"/>"
        );
        let _ = writeln!(
            s,
            "<text x=\"{}\" y=\"24\" text-anchor=\"middle\" font-size=\"{TITLE_FONT}\">{}</text>",
            W / 2.0,
            escape(&self.title)
        );
        let st = step(top);
        let mut t = 0.0;
        while t <= top * (1.0 + 1e-9) {
            let y = py(t);
            let _ = writeln!(
                s,
                "<line x1=\"{LEFT}\" y1=\"{y:.1}\" x2=\"{}\" y2=\"{y:.1}\" stroke=\"#ddd\"/><text x=\"{}\" y=\"{:.1}\" text-anchor=\"end\">{}</text>",
                W - RIGHT,
                LEFT - 6.0,
                y + 4.0,
                format_tick(t)
            );
            t += st;
        }
        for (i, (label, values)) in self.bars.iter().enumerate() {
            let x = LEFT + slot * (i as f64 + 0.2);
            let mut base = 0.0;
            for (k, v) in values.iter().enumerate() {
                let v = v.max(0.0);
                let (y0, y1) = (py(base), py(base + v));
                let _ = writeln!(
                    s,
                    "<rect x=\"{x:.1}\" y=\"{y1:.1}\" width=\"{:.1}\" height=\"{:.1}\" fill=\"{}\"/>",
                    slot * 0.6,
                    (y0 - y1).max(0.0),
                    COLORS[k % COLORS.len()]
                );
                base += v;
            }
            let cx = x + slot * 0.3;
            // Slanted 30° so that long names do not run into each other.
            let _ = writeln!(
                s,
                "<text transform=\"translate({cx:.1} {}) rotate(30)\" text-anchor=\"start\">{}</text>",
                H - BOTTOM + 14.0,
                escape(label)
            );
        }
        let _ = writeln!(
            s,
            "<rect x=\"{LEFT}\" y=\"{TOP}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"black\"/>",
            W - LEFT - RIGHT,
            H - TOP - BOTTOM
        );
        let _ = writeln!(
            s,
            "<text transform=\"translate(16 {}) rotate(-90)\" text-anchor=\"middle\">{}</text>",
            (TOP + H - BOTTOM) / 2.0,
            escape(&self.y_label)
        );
        // The legend, under the bars' labels.
        for (k, part) in self.parts.iter().enumerate() {
            let lx = 10.0 + column * (k % columns) as f64;
            let ly = H + 14.0 + 22.0 * (k / columns) as f64;
            let _ = writeln!(
                s,
                "<rect x=\"{lx}\" y=\"{}\" width=\"16\" height=\"12\" fill=\"{}\"/><text class=\"legend\" x=\"{}\" y=\"{}\">{}</text>",
                ly - 6.0,
                COLORS[k % COLORS.len()],
                lx + 22.0,
                ly + 5.0,
                escape(part)
            );
        }
        s.push_str("</svg>\n");
        s
    }

    pub fn write(&self, path: &Path) -> Result<()> {
        raytracer::film::output::write_file(path, self.to_svg())
            .with_context(|| format!("cannot write {}", path.display()))
    }
}

/// A tick value: plain where short, else in scientific notation.
pub fn format_tick(t: f64) -> String {
    if t == 0.0 {
        "0".into()
    } else if (1e-2..1e4).contains(&t) {
        format!("{}", (t * 1e4).round() / 1e4)
    } else {
        format!("{t:.0e}")
    }
}
