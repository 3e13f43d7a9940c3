//! Polar plots of BRDF lobes in the plane of incidence.

use std::fmt::Write as _;

use super::chart::{FONT, TITLE_FONT};
use super::palette::curve_color;
use super::series::{Series, label_text};

/// A polar plot of BRDF lobes in the plane of incidence: each series gives
/// `(θ, r)` pairs, θ measured from the normal (positive towards the mirror
/// side), drawn as `r (sin θ, cos θ)` above a horizontal surface line, the
/// legend on the right; `incoming` labels the direction of the light.
pub fn polar_svg(title: &str, series: &[Series], incoming_deg: f64, incoming: &str) -> String {
    let (cx, cy, radius) = (200.0, 250.0, 180.0);
    let r_max = series
        .iter()
        .flat_map(|s| s.points.iter().map(|p| p.1))
        .fold(1e-12f64, f64::max);
    let mut s = String::new();
    let _ = writeln!(
        s,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"560\" height=\"300\" viewBox=\"0 0 560 300\" font-family=\"sans-serif\" \
         font-size=\"{FONT}\"><rect width=\"100%\" height=\"100%\" fill=\"white\"/>"
    );
    let _ = writeln!(
        s,
        "<text x=\"280\" y=\"22\" text-anchor=\"middle\" font-size=\"{TITLE_FONT}\">{}</text>",
        label_text(title)
    );
    for k in 1..=4 {
        let r = radius * k as f64 / 4.0;
        let _ = writeln!(
            s,
            "<path d=\"M {} {cy} A {r} {r} 0 0 1 {} {cy}\" fill=\"none\" stroke=\"#ddd\"/>",
            cx - r,
            cx + r
        );
    }
    let _ = writeln!(
        s,
        "<line x1=\"{}\" y1=\"{cy}\" x2=\"{}\" y2=\"{cy}\" stroke=\"black\" stroke-width=\"2\"/>",
        cx - radius - 10.0,
        cx + radius + 10.0
    );
    let a = incoming_deg.to_radians();
    let _ = writeln!(
        s,
        "<line x1=\"{:.1}\" y1=\"{:.1}\" x2=\"{cx}\" y2=\"{cy}\" stroke=\"#888\" stroke-dasharray=\"6 4\"/><text x=\"{:.1}\" y=\"{:.1}\" fill=\"#888\">{}</text>",
        cx - radius * a.sin(),
        cy - radius * a.cos(),
        cx - radius * a.sin() - 20.0,
        cy - radius * a.cos() - 6.0,
        label_text(incoming)
    );
    for (i, series) in series.iter().enumerate() {
        let color = curve_color(&series.label, i);
        let pts: Vec<String> = series
            .points
            .iter()
            .map(|&(theta, r)| {
                let rr = radius * r / r_max;
                format!("{:.1},{:.1}", cx + rr * theta.sin(), cy - rr * theta.cos())
            })
            .collect();
        let _ = writeln!(
            s,
            "<polyline fill=\"none\" stroke=\"{color}\" stroke-width=\"2\" points=\"{}\"/>",
            pts.join(" ")
        );
        let ly = 50.0 + 22.0 * i as f64;
        let _ = writeln!(
            s,
            "<line x1=\"384\" y1=\"{ly}\" x2=\"402\" y2=\"{ly}\" stroke=\"{color}\" stroke-width=\"3\"/><text class=\"legend\" x=\"408\" y=\"{}\">{}</text>",
            ly + 4.0,
            label_text(&series.label)
        );
    }
    s.push_str("</svg>\n");
    s
}
