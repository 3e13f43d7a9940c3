//! A figure of the page: a rendered picture or a plot, with its caption,
//! linked relative to the page.

use std::path::{Path, PathBuf};

/// What a rendered picture left on disk, and what its caption must say of it.
pub struct Picture {
    pub png: PathBuf,
    pub exr: PathBuf,
    /// Samples per pixel of the estimate.
    pub spp: u32,
    /// Exposure of the PNG in stops (+1 doubles the brightness); the EXR is linear, unscaled.
    pub exposure: f32,
    /// Wall-clock time of the render that made exactly this picture; `None`
    /// for pictures computed from other renders (a difference, a strategy of
    /// a bidirectional render), whose caption says where they come from.
    pub seconds: Option<f64>,
}

/// A picture with its caption, linked relative to the page.
pub struct Figure {
    pub src: String,
    /// The linear image to measure, if the figure is a render.
    pub exr: Option<String>,
    pub caption: String,
    /// Samples per pixel, for a render (written into the page beside the caption).
    pub spp: Option<u32>,
    /// Exposure of the PNG in stops, for a render.
    pub exposure: Option<f32>,
    /// The PNG's width in pixels: the page never shows it wider than twice that.
    pub width: Option<u32>,
}

/// The width of a PNG, from its header (`None` if it is not one).
pub fn png_width(png: &Path) -> Option<u32> {
    use std::io::Read as _;
    let mut head = [0u8; 24];
    std::fs::File::open(png).ok()?.read_exact(&mut head).ok()?;
    (head[..8] == *b"\x89PNG\r\n\x1a\n" && head[12..16] == *b"IHDR")
        .then(|| u32::from_be_bytes([head[16], head[17], head[18], head[19]]))
}

impl Figure {
    /// A render: its caption followed by its samples per pixel, exposure and
    /// time, e.g. "(64 spp, exposure 0, 1.94 s)", in the run's language.
    pub fn new(root: &Path, picture: &Picture, caption: &str) -> Self {
        let mut facts = vec![
            format!("{} spp", picture.spp),
            exposure_text(picture.exposure),
        ];
        if let Some(t) = picture.seconds {
            facts.push(seconds_text(t));
        }
        Figure {
            src: relative(&picture.png, root),
            exr: Some(relative(&picture.exr, root)),
            caption: format!("{caption} ({})", facts.join(", ")),
            spp: Some(picture.spp),
            exposure: Some(picture.exposure),
            width: png_width(&picture.png),
        }
    }

    /// An image written as PNG (to look at) and EXR (to measure), with its caption as given.
    pub fn image(root: &Path, png: &Path, exr: &Path, caption: String) -> Self {
        Figure {
            src: relative(png, root),
            exr: Some(relative(exr, root)),
            caption,
            spp: None,
            exposure: None,
            width: png_width(png),
        }
    }

    /// A plot (an SVG file) with its caption.
    pub fn plot(root: &Path, svg: &Path, caption: &str) -> Self {
        Figure {
            src: relative(svg, root),
            exr: None,
            caption: caption.into(),
            spp: None,
            exposure: None,
            width: None,
        }
    }
}

/// A time as a caption states it: never `0.0 s` for a render that took a
/// few milliseconds ("4.2 ms", "0.31 s", "2.5 s", "41 s").
pub fn seconds_text(t: f64) -> String {
    if t >= 100.0 {
        format!("{t:.0} s")
    } else if t >= 1.0 {
        format!("{t:.1} s")
    } else if t >= 0.01 {
        format!("{t:.2} s")
    } else if t * 1e3 >= 0.1 {
        format!("{:.1} ms", t * 1e3)
    } else {
        "< 0.1 ms".into()
    }
}

/// A time for a table or CSV: a number of seconds with three significant
/// digits (0.000412, 0.970, 12.3), never rounded to zero.
pub fn seconds_number(t: f64) -> String {
    if t <= 0.0 {
        return "0".into();
    }
    let decimals = (2 - t.log10().floor() as i32).max(0) as usize;
    format!("{t:.decimals$}")
}

/// The exposure as a caption states it: "exposure 0" or "exposure +4 stops
/// (×16)"; in Bulgarian "експозиция 0", "експозиция +4 стъпки (×16)".
pub fn exposure_text(stops: f32) -> String {
    let word = lang::pick("exposure", "експозиция");
    if stops == 0.0 {
        format!("{word} 0")
    } else {
        let factor = stops.exp2();
        let factor = if factor >= 1.0 {
            format!("×{factor}")
        } else {
            format!("×{factor:.3}")
        };
        let unit = match (lang::current(), stops.abs() == 1.0) {
            (lang::Lang::En, _) => "stops",
            (lang::Lang::Bg, true) => "стъпка",
            (lang::Lang::Bg, false) => "стъпки",
        };
        format!("{word} {stops:+} {unit} ({factor})")
    }
}

/// `path` as the page at `root` links it: relative, with forward slashes.
fn relative(path: &Path, root: &Path) -> String {
    path.strip_prefix(root)
        .unwrap_or(path)
        .to_string_lossy()
        .replace('\\', "/")
}
