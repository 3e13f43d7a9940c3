//! Bar charts on a log axis: one group per label, its parts side by side in
//! the palette's order (bias² beside variance), so that a part a hundred
//! times smaller than its neighbour still shows. A part that is only an
//! upper bound (an estimate that does not stand out of its noise) is drawn
//! as an outline up to that bound.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::{Context, Result};

use super::chart::{
    FONT, Scale, TITLE_FONT, is_bulgarian, legend_layout, tick_class, tick_text, ticks,
};
use super::palette::{GUIDE, OTHERS as COLORS};
use super::series::label_text;

/// One part of a bar: its value (> 0), or an upper bound on it.
#[derive(Clone, Copy, Debug)]
pub struct Part {
    pub value: f64,
    /// Only "at most `value`": drawn as an outline.
    pub bound: bool,
}

/// A grouped bar chart with a log y axis.
pub struct Bars {
    pub title: String,
    pub y_label: String,
    /// The names of the parts of every group, left first.
    pub parts: Vec<String>,
    /// What the outline of a bound says in the legend.
    pub bound_label: String,
    /// One group per entry: its label and its parts, left first.
    pub bars: Vec<(String, Vec<Part>)>,
}

const W: f64 = 560.0;
const H: f64 = 380.0;
const LEFT: f64 = 84.0;
const RIGHT: f64 = 20.0;
const TOP: f64 = 40.0;
const BOTTOM: f64 = 110.0;

impl Bars {
    /// The chart as an SVG document.
    pub fn to_svg(&self) -> String {
        let values: Vec<f64> = self
            .bars
            .iter()
            .flat_map(|(_, p)| p.iter().map(|p| p.value))
            .filter(|v| *v > 0.0 && v.is_finite())
            .collect();
        let (lo, hi) = values
            .iter()
            .fold((f64::MAX, f64::MIN), |(a, b), v| (a.min(*v), b.max(*v)));
        let (lo, hi) = if values.is_empty() {
            (-1.0, 0.0)
        } else {
            // Half a decade of room below the smallest bar and above the tallest.
            (lo.log10().floor().min(lo.log10() - 0.5), hi.log10() + 0.15)
        };
        let py = |v: f64| {
            let t = (v.max(1e-300).log10().max(lo) - lo) / (hi - lo).max(1e-9);
            H - BOTTOM - t * (H - TOP - BOTTOM)
        };
        let slot = (W - LEFT - RIGHT) / self.bars.len().max(1) as f64;
        let last = self.bars.last().map_or(0, |(l, _)| l.chars().count());
        let reach = LEFT + slot * (self.bars.len() as f64 - 0.5) + 0.6 * FONT * last as f64 * 0.87;
        let width = W.max(reach + 6.0);
        let mut legend: Vec<&str> = self.parts.iter().map(String::as_str).collect();
        legend.push(&self.bound_label);
        let (columns, column, rows) = legend_layout(&legend, width);
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
            label_text(&self.title)
        );
        let bulgarian = is_bulgarian(
            [&self.title, &self.y_label]
                .map(String::as_str)
                .into_iter()
                .chain(legend.iter().copied()),
        );
        for t in ticks(lo, hi, Scale::Log) {
            let y = py(10f64.powf(t));
            let _ = writeln!(
                s,
                "<line x1=\"{LEFT}\" y1=\"{y:.1}\" x2=\"{}\" y2=\"{y:.1}\" stroke=\"#ddd\"/><text class=\"{}\" x=\"{}\" y=\"{:.1}\" text-anchor=\"end\">{}</text>",
                W - RIGHT,
                tick_class("y", Scale::Log),
                LEFT - 6.0,
                y + 4.0,
                tick_text(t, Scale::Log, bulgarian)
            );
        }
        let n = self.parts.len().max(1) as f64;
        let bar_w = slot * 0.7 / n;
        for (i, (label, parts)) in self.bars.iter().enumerate() {
            let x0 = LEFT + slot * (i as f64 + 0.15);
            for (k, part) in parts.iter().enumerate() {
                if !(part.value > 0.0 && part.value.is_finite()) {
                    continue;
                }
                let color = COLORS[k % COLORS.len()];
                let (x, y0, y1) = (x0 + bar_w * k as f64, py(10f64.powf(lo)), py(part.value));
                let style = if part.bound {
                    format!(
                        "fill=\"white\" stroke=\"{color}\" stroke-width=\"2\" stroke-dasharray=\"4 3\""
                    )
                } else {
                    format!("fill=\"{color}\"")
                };
                let _ = writeln!(
                    s,
                    "<rect x=\"{:.1}\" y=\"{y1:.1}\" width=\"{:.1}\" height=\"{:.1}\" {style}/>",
                    x + 1.0,
                    bar_w - 2.0,
                    (y0 - y1).max(0.0),
                );
            }
            let cx = x0 + slot * 0.35;
            // Slanted 30° so that long names do not run into each other.
            let _ = writeln!(
                s,
                "<text transform=\"translate({cx:.1} {}) rotate(30)\" text-anchor=\"start\">{}</text>",
                H - BOTTOM + 14.0,
                label_text(label)
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
            label_text(&self.y_label)
        );
        // The legend, under the bars' labels: the parts, then the outline.
        for (k, entry) in legend.iter().enumerate() {
            let lx = 10.0 + column * (k % columns) as f64;
            let ly = H + 14.0 + 22.0 * (k / columns) as f64;
            let swatch = if k < self.parts.len() {
                format!("fill=\"{}\"", COLORS[k % COLORS.len()])
            } else {
                format!(
                    "stroke=\"{GUIDE}\" fill=\"white\" stroke-width=\"2\" stroke-dasharray=\"4 3\""
                )
            };
            let _ = writeln!(
                s,
                "<rect x=\"{lx}\" y=\"{}\" width=\"16\" height=\"12\" {swatch}/><text class=\"legend\" x=\"{}\" y=\"{}\">{}</text>",
                ly - 6.0,
                lx + 22.0,
                ly + 5.0,
                label_text(entry)
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
