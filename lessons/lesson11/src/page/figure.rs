//! A figure of the page: a rendered picture or a plot, with its caption,
//! linked relative to the page.

use std::path::{Path, PathBuf};

/// What a rendered picture left on disk.
pub struct Picture {
    pub png: PathBuf,
    pub exr: PathBuf,
    pub seconds: f64,
    pub spp: u32,
}

/// A picture with its caption, linked relative to the page.
pub struct Figure {
    pub src: String,
    /// The linear image to measure, if the figure is a render.
    pub exr: Option<String>,
    pub caption: String,
}

impl Figure {
    /// A render, its caption followed by its samples per pixel and seconds.
    pub fn new(root: &Path, picture: &Picture, caption: &str) -> Self {
        Figure {
            src: relative(&picture.png, root),
            exr: Some(relative(&picture.exr, root)),
            caption: format!("{caption} ({} spp, {:.1} s)", picture.spp, picture.seconds),
        }
    }

    /// An image written as PNG (to look at) and EXR (to measure), with its caption as given.
    pub fn image(root: &Path, png: &Path, exr: &Path, caption: String) -> Self {
        Figure {
            src: relative(png, root),
            exr: Some(relative(exr, root)),
            caption,
        }
    }

    /// A plot (an SVG file) with its caption.
    pub fn plot(root: &Path, svg: &Path, caption: &str) -> Self {
        Figure {
            src: relative(svg, root),
            exr: None,
            caption: caption.into(),
        }
    }
}

/// `path` as the page at `root` links it: relative, with forward slashes.
fn relative(path: &Path, root: &Path) -> String {
    path.strip_prefix(root)
        .unwrap_or(path)
        .to_string_lossy()
        .replace('\\', "/")
}
