//! One colour per algorithm, on every chart of both decks and the page: a
//! curve of path tracing is the same blue in chapter 8's convergence plots
//! and in chapter 9's, whatever else the chart shows. Curves that are not an
//! algorithm (BRDF lobes, a noise floor) take the colours of [`OTHERS`],
//! none of which an algorithm uses; a BRDF keeps its colour from chart to
//! chart too (Phong with n = 10 is the same blue in chapter 3's lobes, their
//! true heights and the directional albedo), and an unnormalized variant of
//! one is drawn dashed in its colour.

/// Every algorithm a chart draws a curve of.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Drawn {
    Naive,
    /// Path tracing with light sampling and MIS (the default path tracer).
    Path,
    /// Path tracing with BRDF sampling only.
    PathBrdf,
    Light,
    Bdpt,
    Metropolis,
    Photon,
    Sppm,
    Vpl,
    IrradianceCache,
}

impl Drawn {
    pub const ALL: [Drawn; 10] = [
        Drawn::Naive,
        Drawn::Path,
        Drawn::PathBrdf,
        Drawn::Light,
        Drawn::Bdpt,
        Drawn::Metropolis,
        Drawn::Photon,
        Drawn::Sppm,
        Drawn::Vpl,
        Drawn::IrradianceCache,
    ];

    /// Its colour, the same on every chart.
    pub fn color(self) -> &'static str {
        match self {
            Drawn::Naive => "#7f7f00",
            Drawn::Path => "#0060c0",
            Drawn::PathBrdf => "#56b4e9",
            Drawn::Light => "#e69f00",
            Drawn::Bdpt => "#009e73",
            Drawn::Metropolis => "#cc3399",
            Drawn::Photon => "#d55e00",
            Drawn::Sppm => "#8b1a1a",
            Drawn::Vpl => "#6a3d9a",
            Drawn::IrradianceCache => "#8c6d31",
        }
    }

    /// The algorithm a curve's label names, in either language of the
    /// decks (chapter 8's "path (BRDF only)", chapter 9's "photon mapping",
    /// "фотонни карти", …), or `None` for a curve that is no algorithm.
    pub fn of_label(label: &str) -> Option<Drawn> {
        let l = label.to_lowercase();
        let has = |words: &[&str]| words.iter().any(|w| l.contains(w));
        Some(if has(&["naive", "наивна"]) {
            Drawn::Naive
        } else if has(&["metropolis"]) {
            Drawn::Metropolis
        } else if has(&["bidirectional", "bdpt"]) {
            Drawn::Bdpt
        } else if has(&["sppm"]) {
            Drawn::Sppm
        } else if has(&["photon", "фотон"]) {
            Drawn::Photon
        } else if has(&["instant radiosity", "vpl"]) {
            Drawn::Vpl
        } else if has(&["irradiance", "кеширане"]) {
            Drawn::IrradianceCache
        } else if has(&["brdf"]) && has(&["path"]) {
            Drawn::PathBrdf
        } else if l.starts_with("light") || has(&["light tracing"]) {
            Drawn::Light
        } else if has(&["path"]) {
            Drawn::Path
        } else {
            return None;
        })
    }
}

/// The colours of curves that are no algorithm, in order.
pub const OTHERS: [&str; 8] = [
    "#e6194b", "#3cb44b", "#4363d8", "#f58231", "#911eb4", "#42d4f4", "#f032e6", "#9a6324",
];

/// The grey of a reference's noise floor and other guide lines.
pub const GUIDE: &str = "#777777";

/// The colour of a BRDF a label names, the same on every chart: Lambert,
/// Phong by its exponent (`Phong n=10`, `n = 10 unnorm.`), the mirror.
fn brdf_color(label: &str) -> Option<&'static str> {
    let l: String = label.to_lowercase().split_whitespace().collect();
    if l.contains("lambert") {
        return Some(OTHERS[0]);
    }
    if l.contains("mirror") || l.contains("огледало") {
        return Some(OTHERS[4]);
    }
    let start = l.find("n=")? + 2;
    let digits: String = l[start..]
        .chars()
        .take_while(char::is_ascii_digit)
        .collect();
    match digits.as_str() {
        "1" => Some(OTHERS[1]),
        "10" => Some(OTHERS[2]),
        "100" => Some(OTHERS[3]),
        _ => None,
    }
}

/// Whether a curve is drawn dashed: an unnormalized BRDF (beside its
/// normalized self, in the same colour).
pub fn dashed(label: &str) -> bool {
    let l = label.to_lowercase();
    l.contains("unnorm") || l.contains("ненорм")
}

/// The colour of the `i`-th curve of a chart, labelled `label`.
pub fn curve_color(label: &str, i: usize) -> &'static str {
    if let Some(d) = Drawn::of_label(label) {
        return d.color();
    }
    let l = label.to_lowercase();
    if l.contains("noise floor") || l.contains("шум") {
        return GUIDE;
    }
    brdf_color(label).unwrap_or(OTHERS[i % OTHERS.len()])
}
