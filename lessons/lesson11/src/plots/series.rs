//! What every plot draws: named series of points (their colours are the
//! palette's, one per algorithm), and the text of a chart's labels.

/// One curve of a chart.
#[derive(Clone)]
pub struct Series {
    pub label: String,
    pub points: Vec<(f64, f64)>,
}

/// Text escaped for SVG.
pub fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// A chart's label as SVG text: escaped, and with the lecture's subscripts
/// set as subscripts (`f_r` → f with a lowered r, `θ_{o}` likewise), so that
/// a chart shows f<sub>r</sub> and θ<sub>o</sub>, never the raw `_`.
pub fn label_text(s: &str) -> String {
    let mut out = String::new();
    let mut chars = s.chars().peekable();
    while let Some(c) = chars.next() {
        let sub: Option<String> = match (c, chars.peek()) {
            ('_', Some('{')) => {
                chars.next();
                Some(chars.by_ref().take_while(|&c| c != '}').collect())
            }
            ('_', Some(&n)) if n.is_alphanumeric() => {
                chars.next();
                Some(n.to_string())
            }
            _ => None,
        };
        match sub {
            Some(sub) => out.push_str(&format!(
                "<tspan baseline-shift=\"sub\" font-size=\"85%\">{}</tspan>",
                escape(&sub)
            )),
            None => out.push_str(&escape(&c.to_string())),
        }
    }
    out
}
