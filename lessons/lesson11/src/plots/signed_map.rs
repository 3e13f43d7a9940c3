//! A signed picture with a numbered colour bar: an error or a bias image
//! (chapter 9: where each biased algorithm's bias sits) painted in the
//! diverging map of the z-map — blue below zero, grey at zero, red above —
//! with the bar under it saying which colour is which value.
//!
//! The picture lies in the SVG as a PNG at its own pixels (a data URI, as
//! the slides show SVG with `<img>`), drawn at a whole multiple of its size
//! (twice at least, the drawing at least 256 units wide) without smoothing;
//! the bar's numbers are SVG text a sixteenth of the drawing's width high
//! (16 units at least), so that they stay 12 px or more on a slide that
//! shows the figure at three quarters of its drawing's size. At that
//! height five numbers do not fit in a row: the bar numbers its ends and 0
//! and leaves the half-way ticks bare.

use std::fmt::Write as _;

use raytracer::film::Image;

use super::data_uri::png_data_uri;
use super::zmap::diverging;

/// The least width of the drawing, in its units.
const LEAST_WIDTH: u32 = 256;
/// The least height of the bar's numbers, in drawing units.
const LEAST_FONT: u32 = 16;

/// A round bound for a colour scale: the smallest of 1, 2, 5 × 10ⁿ at or
/// above `v` (and 1 for a `v` that is not a positive number).
pub fn round_scale(v: f64) -> f64 {
    if !(v > 0.0 && v.is_finite()) {
        return 1.0;
    }
    let mag = 10f64.powf(v.log10().floor());
    [1.0, 2.0, 5.0, 10.0]
        .iter()
        .map(|m| m * mag)
        .find(|&s| s >= v * (1.0 - 1e-12))
        .unwrap_or(10.0 * mag)
}

/// A number as the bar prints it: `−0.05`, `0`, `+0.025`, with as few
/// digits as the bar's ticks (at halves of `scale`) need.
pub fn label(v: f64, scale: f64) -> String {
    if v == 0.0 {
        return "0".into();
    }
    // The fewest decimals that print a quarter of the scale exactly.
    let digits = (0..12)
        .find(|&d| {
            let q = scale / 2.0 * 10f64.powi(d);
            (q - q.round()).abs() < 1e-6 * q.max(1.0)
        })
        .unwrap_or(12) as usize;
    let text = format!("{:.*}", digits, v.abs());
    format!("{}{text}", if v < 0.0 { '−' } else { '+' })
}

/// The SVG of `values` (one signed number per pixel of a `width`×`height`
/// picture, row by row) in colours spanning [−scale, scale], with a bar of
/// five ticks, three of them numbered. An error, for pictures that cannot be encoded.
pub fn signed_map_svg(
    values: &[f32],
    width: u32,
    height: u32,
    scale: f64,
) -> std::io::Result<String> {
    let s = scale as f32;
    let image = Image::from_fn(width, height, |x, y| {
        diverging(values[(y * width + x) as usize] / s)
    });
    let png = image.png_bytes(0.0)?;
    let zoom = LEAST_WIDTH.div_ceil(width.max(1)).max(2);
    let (w, h) = (width * zoom, height * zoom);
    // The numbers' height, and the bar's.
    let font = (w / 16).max(LEAST_FONT);
    let bar = font;
    let margin = 3 * font;
    let (bar_x, bar_w) = (margin, w - 2 * margin);
    let bar_y = h + font / 2;
    let total_h = bar_y + bar + 6 + font + 4;
    let mut svg = String::new();
    let _ = writeln!(
        svg,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{total_h}\" \
         viewBox=\"0 0 {w} {total_h}\" font-family=\"sans-serif\" font-size=\"{font}\">\
         <rect width=\"100%\" height=\"100%\" fill=\"white\"/>"
    );
    let _ = writeln!(
        svg,
        "<image width=\"{w}\" height=\"{h}\" preserveAspectRatio=\"none\" \
         style=\"image-rendering:pixelated\" href=\"{}\"/>",
        png_data_uri(&png)
    );
    // The bar: the map sampled at 21 stops, as the PNG writer encodes it.
    let _ = write!(
        svg,
        "<defs><linearGradient id=\"bar\" x1=\"0\" x2=\"1\" y1=\"0\" y2=\"0\">"
    );
    for i in 0..=20 {
        let t = i as f32 / 20.0;
        let c = diverging(2.0 * t - 1.0);
        let hex: Vec<String> = [c.x, c.y, c.z]
            .iter()
            .map(|&v| format!("{:02x}", raytracer::film::output::srgb8(v)))
            .collect();
        let _ = write!(
            svg,
            "<stop offset=\"{t}\" stop-color=\"#{}\"/>",
            hex.concat()
        );
    }
    let _ = writeln!(svg, "</linearGradient></defs>");
    let _ = writeln!(
        svg,
        "<rect x=\"{bar_x}\" y=\"{bar_y}\" width=\"{bar_w}\" height=\"{bar}\" fill=\"url(#bar)\" \
         stroke=\"#333\" stroke-width=\"0.5\"/>"
    );
    // Numbers at the ends and at 0 only: five of this height do not fit in
    // a row (a number of 5 characters is some 3 of its heights wide).
    for i in 0..5 {
        let x = bar_x as f64 + bar_w as f64 * i as f64 / 4.0;
        let _ = write!(
            svg,
            "<line x1=\"{x:.1}\" x2=\"{x:.1}\" y1=\"{bar_y}\" y2=\"{}\" stroke=\"#111\"/>",
            bar_y + bar + 4,
        );
        if i % 2 == 0 {
            let _ = write!(
                svg,
                "<text x=\"{x:.1}\" y=\"{}\" text-anchor=\"middle\">{}</text>",
                bar_y + bar + 4 + font,
                // As few digits as the numbered ticks need: −0.05, not −0.050.
                label(scale * (i as f64 / 2.0 - 1.0), 2.0 * scale)
            );
        }
        svg.push('\n');
    }
    svg.push_str("</svg>\n");
    Ok(svg)
}
