//! Line charts with linear or log–log axes, ticks, labels and a legend: the
//! convergence plots (error against time) and the directional albedo.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::{Context, Result};

use super::palette::{curve_color, dashed};
use super::series::{Series, label_text};

/// Scale of an axis.
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum Scale {
    Linear,
    Log,
}

/// A chart with axes, ticks, labels and a legend.
pub struct Chart {
    pub title: String,
    pub x_label: String,
    pub y_label: String,
    pub x_scale: Scale,
    pub y_scale: Scale,
    pub series: Vec<Series>,
}

const W: f64 = 560.0;
/// The plot area and the text: sizes chosen so that a chart shown at 0.8 of
/// its size (two side by side on a 1280×720 slide) still has text of 12 px.
const H: f64 = 360.0;
const LEFT: f64 = 78.0;
const RIGHT: f64 = 22.0;
const TOP: f64 = 40.0;
const BOTTOM: f64 = 56.0;
/// Font sizes of the ticks, labels and legend, and of the title.
pub const FONT: f64 = 15.0;
pub const TITLE_FONT: f64 = 17.0;

/// The legend under the plot area, in as many columns as the longest label
/// lets fit in the chart's width: `(columns, column width, rows)`. A
/// character of the sans-serif font is taken as 0.6 of the font size wide,
/// more than most glyphs need, so that no label runs off the chart.
pub fn legend_layout(labels: &[&str], width: f64) -> (usize, f64, usize) {
    let longest = labels.iter().map(|l| l.chars().count()).max().unwrap_or(0);
    let entry = 30.0 + 0.6 * FONT * longest as f64;
    let columns = ((width - 20.0) / entry).floor().max(1.0) as usize;
    let columns = columns.min(labels.len().max(1));
    let rows = labels.len().div_ceil(columns);
    (columns, (width - 20.0) / columns as f64, rows)
}

/// Tick positions covering `[lo, hi]` (in the axis' own units: log10 for logs).
/// A log axis gets at least three labelled ticks: the decades, then 2 and 5
/// times them, then every integer multiple, then round steps of the values,
/// as the range narrows.
pub fn ticks(lo: f64, hi: f64, scale: Scale) -> Vec<f64> {
    if scale == Scale::Log {
        let inside = |t: &f64| *t >= lo - 1e-9 && *t <= hi + 1e-9;
        let all: [&[f64]; 3] = [
            &[1.0],
            &[1.0, 2.0, 5.0],
            &[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0],
        ];
        for multiples in all {
            let out: Vec<f64> = (lo.floor() as i32..=hi.ceil() as i32)
                .flat_map(|d| {
                    multiples
                        .iter()
                        .map(move |m: &f64| f64::from(d) + m.log10())
                })
                .filter(inside)
                .collect();
            if out.len() >= 3 {
                return out;
            }
        }
        // Less than three integer multiples of a power of ten inside (from
        // 0.51 to 0.59, say): round steps of the values themselves.
        // The step shrinks through 1, 0.5, 0.2, 0.1 × a power of ten until
        // three multiples of it fall inside.
        let (a, b) = (10f64.powf(lo), 10f64.powf(hi));
        let mut step = 10f64.powf((b - a).log10().floor());
        for k in 0.. {
            let out: Vec<f64> = ((a / step).ceil() as i64..=(b / step).floor() as i64)
                .map(|m| (m as f64 * step).log10())
                .collect();
            if out.len() >= 3 || k > 60 {
                return out;
            }
            step /= [2.0, 2.5, 2.0][k % 3];
        }
        unreachable!("the loop returns")
    }
    let span = (hi - lo).max(1e-12);
    let raw = span / 5.0;
    let mag = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 5.0, 10.0]
        .iter()
        .map(|m| m * mag)
        .find(|s| span / s <= 6.0)
        .unwrap_or(10.0 * mag);
    let mut t = (lo / step).ceil() * step;
    let mut out = Vec::new();
    while t <= hi + 1e-9 * span {
        out.push(t);
        t += step;
    }
    out
}

/// The class of an axis' tick labels, `tick x log` or `tick y linear`: the
/// slides' test counts the labelled ticks of every log axis by it.
pub fn tick_class(axis: &str, scale: Scale) -> String {
    let scale = match scale {
        Scale::Log => "log",
        Scale::Linear => "linear",
    };
    format!("tick {axis} {scale}")
}

/// Whether a chart speaks Bulgarian: some of its words are Cyrillic. Its
/// numbers then take the decimal comma (0,05), as the Bulgarian slides do.
pub fn is_bulgarian<'a>(texts: impl IntoIterator<Item = &'a str>) -> bool {
    texts
        .into_iter()
        .any(|t| t.chars().any(|c| ('\u{0400}'..='\u{04ff}').contains(&c)))
}

/// A tick's label with the decimal separator of the chart's language.
pub fn tick_text(t: f64, scale: Scale, bulgarian: bool) -> String {
    let text = tick_label(t, scale);
    if bulgarian {
        text.replace('.', ",")
    } else {
        text
    }
}

pub fn tick_label(t: f64, scale: Scale) -> String {
    match scale {
        Scale::Log => {
            let v = 10f64.powf(t);
            if (1e-3..1e4).contains(&v) {
                // Four significant digits at most (a narrow axis' ticks
                // differ in the third): 0.002, 0.05, 20, 5.15.
                let digits = (3 - v.log10().floor() as i32).max(0) as usize;
                let text = format!("{v:.digits$}");
                if text.contains('.') {
                    text.trim_end_matches('0').trim_end_matches('.').to_string()
                } else {
                    text
                }
            } else {
                let mut e = t.floor();
                let mut m = (10f64.powf(t - e) * 100.0).round() / 100.0;
                if m >= 10.0 {
                    (m, e) = (m / 10.0, e + 1.0);
                }
                if m == 1.0 {
                    format!("1e{e}")
                } else {
                    format!("{m}e{e}")
                }
            }
        }
        Scale::Linear => format!("{}", (t * 1e6).round() / 1e6),
    }
}

impl Chart {
    /// The chart as an SVG document.
    pub fn to_svg(&self) -> String {
        let map = |v: f64, s: Scale| {
            if s == Scale::Log {
                v.max(1e-30).log10()
            } else {
                v
            }
        };
        let pts: Vec<(f64, f64)> = self
            .series
            .iter()
            .flat_map(|s| {
                s.points
                    .iter()
                    .map(|&(x, y)| (map(x, self.x_scale), map(y, self.y_scale)))
            })
            .collect();
        let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
        for &(x, y) in &pts {
            x0 = x0.min(x);
            x1 = x1.max(x);
            y0 = y0.min(y);
            y1 = y1.max(y);
        }
        if pts.is_empty() {
            (x0, x1, y0, y1) = (0.0, 1.0, 0.0, 1.0);
        }
        if self.y_scale == Scale::Linear {
            y0 = y0.min(0.0);
        }
        if x1 - x0 < 1e-12 {
            x1 = x0 + 1.0;
        }
        if y1 - y0 < 1e-12 {
            y1 = y0 + 1.0;
        }
        let pad = 0.05 * (y1 - y0);
        let (y0, y1) = (
            y0 - if self.y_scale == Scale::Log { pad } else { 0.0 },
            y1 + pad,
        );
        let px = |x: f64| LEFT + (x - x0) / (x1 - x0) * (W - LEFT - RIGHT);
        let py = |y: f64| H - BOTTOM - (y - y0) / (y1 - y0) * (H - TOP - BOTTOM);
        let labels: Vec<&str> = self.series.iter().map(|s| s.label.as_str()).collect();
        let (columns, column, rows) = legend_layout(&labels, W);
        let words = [&self.title, &self.x_label, &self.y_label].map(String::as_str);
        let bulgarian = is_bulgarian(words.into_iter().chain(labels.iter().copied()));
        let height = H + 22.0 * rows as f64 + 8.0;
        let mut s = String::new();
        let _ = writeln!(
            s,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{W}\" height=\"{height}\" viewBox=\"0 0 {W} {height}\" \
             font-family=\"sans-serif\" font-size=\"{FONT}\"><rect width=\"100%\" height=\"100%\" fill=\"white\"/>"
        );
        let _ = writeln!(
            s,
            "<text x=\"{}\" y=\"24\" text-anchor=\"middle\" font-size=\"{TITLE_FONT}\">{}</text>",
            W / 2.0,
            label_text(&self.title)
        );
        for t in ticks(x0, x1, self.x_scale) {
            let x = px(t);
            let _ = writeln!(
                s,
                "<line x1=\"{x:.1}\" y1=\"{}\" x2=\"{x:.1}\" y2=\"{}\" stroke=\"#ddd\"/><text class=\"{}\" x=\"{x:.1}\" y=\"{}\" text-anchor=\"middle\">{}</text>",
                TOP,
                H - BOTTOM,
                tick_class("x", self.x_scale),
                H - BOTTOM + 19.0,
                tick_text(t, self.x_scale, bulgarian)
            );
        }
        for t in ticks(y0, y1, self.y_scale) {
            let y = py(t);
            let _ = writeln!(
                s,
                "<line x1=\"{LEFT}\" y1=\"{y:.1}\" x2=\"{}\" y2=\"{y:.1}\" stroke=\"#ddd\"/><text class=\"{}\" x=\"{}\" y=\"{:.1}\" text-anchor=\"end\">{}</text>",
                W - RIGHT,
                tick_class("y", self.y_scale),
                LEFT - 6.0,
                y + 4.0,
                tick_text(t, self.y_scale, bulgarian)
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
            "<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>",
            (LEFT + W - RIGHT) / 2.0,
            H - 14.0,
            label_text(&self.x_label)
        );
        let _ = writeln!(
            s,
            "<text transform=\"translate(16 {}) rotate(-90)\" text-anchor=\"middle\">{}</text>",
            (TOP + H - BOTTOM) / 2.0,
            label_text(&self.y_label)
        );
        for (i, series) in self.series.iter().enumerate() {
            let color = curve_color(&series.label, i);
            let path: Vec<String> = series
                .points
                .iter()
                .map(|&(x, y)| {
                    format!(
                        "{:.1},{:.1}",
                        px(map(x, self.x_scale)),
                        py(map(y, self.y_scale))
                    )
                })
                .collect();
            // A flat guide (two points at one height: a noise floor, a
            // bias floor) is dashed and has no dots: it is no measurement.
            let guide = series.points.len() == 2 && series.points[0].1 == series.points[1].1;
            let dash = if guide || dashed(&series.label) {
                " stroke-dasharray=\"7 5\""
            } else {
                ""
            };
            let _ = writeln!(
                s,
                "<polyline fill=\"none\" stroke=\"{color}\" stroke-width=\"2\"{dash} points=\"{}\"/>",
                path.join(" ")
            );
            if series.points.len() <= 12 && !guide {
                for p in &path {
                    let (x, y) = p.split_once(',').unwrap_or(("0", "0"));
                    let _ = writeln!(
                        s,
                        "<circle cx=\"{x}\" cy=\"{y}\" r=\"3\" fill=\"{color}\"/>"
                    );
                }
            }
            // The legend, under the plot: row by row, `columns` to a row.
            let lx = 10.0 + column * (i % columns) as f64;
            let ly = H + 14.0 + 22.0 * (i / columns) as f64;
            let _ = writeln!(
                s,
                "<line x1=\"{lx}\" y1=\"{ly}\" x2=\"{}\" y2=\"{ly}\" stroke=\"{color}\" stroke-width=\"3\"{dash}/><text class=\"legend\" x=\"{}\" y=\"{}\">{}</text>",
                lx + 20.0,
                lx + 26.0,
                ly + 5.0,
                label_text(&series.label)
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
