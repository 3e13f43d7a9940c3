//! Rendering to files: PNG to look at, EXR to measure, and the variance of
//! each pixel's mean, written where a chapter or a command asks.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result};
use raytracer::film::Image;
use raytracer::integrator::Integrator;
use raytracer::render::{RenderOptions, render};
use raytracer::scene::Scene;

use crate::options::create_dir;
use crate::page::{Picture, seconds_text};

/// Renders and writes `dir/stem.png`, `dir/stem.exr` and `dir/stem-variance.exr`,
/// then prints one summary line. An interrupted render (Ctrl-C) still writes
/// what it computed.
pub fn render_to_files(
    scene: &Scene,
    integrator: &dyn Integrator,
    options: &RenderOptions,
    dir: &Path,
    stem: &str,
    exposure: f32,
) -> Result<Picture> {
    create_dir(dir)?;
    let result = render(scene, integrator, options);
    let png = dir.join(format!("{stem}.png"));
    let exr = dir.join(format!("{stem}.exr"));
    let variance = dir.join(format!("{stem}-variance.exr"));
    result
        .film
        .write_png(&png, exposure)
        .with_context(|| format!("cannot write {}", png.display()))?;
    result
        .film
        .write_exr(&exr)
        .with_context(|| format!("cannot write {}", exr.display()))?;
    result
        .film
        .variance_image()
        .write_exr(&variance)
        .with_context(|| format!("cannot write {}", variance.display()))?;
    let stats = &result.stats;
    let seconds = stats.elapsed.as_secs_f64();
    println!(
        "  wrote {} and .exr ({} spp, {})",
        png.display(),
        options.spp,
        seconds_text(seconds)
    );
    if stats.nonfinite > 0 {
        println!(
            "  note: {} samples were NaN, infinite or negative and counted as zero",
            stats.nonfinite
        );
    }
    if stats.interrupted {
        anyhow::bail!(
            "interrupted by Ctrl-C; what was rendered so far is in {}",
            exr.display()
        );
    }
    Ok(Picture {
        png,
        exr,
        spp: options.spp,
        exposure,
        seconds: Some(seconds),
    })
}

/// Writes `image` as `dir/stem.png` (at `exposure` stops, to look at) and
/// `dir/stem.exr` (linear, to measure); returns the two paths.
pub fn write_png_and_exr(
    dir: &Path,
    stem: &str,
    image: &Image,
    exposure: f32,
) -> Result<(PathBuf, PathBuf)> {
    let png = dir.join(format!("{stem}.png"));
    let exr = dir.join(format!("{stem}.exr"));
    image
        .write_png(&png, exposure)
        .with_context(|| format!("cannot write {}", png.display()))?;
    image
        .write_exr(&exr)
        .with_context(|| format!("cannot write {}", exr.display()))?;
    Ok((png, exr))
}

/// Writes an image computed outside `render` as `dir/stem.png` (at
/// `exposure` stops) and `dir/stem.exr`, recorded as a picture of `spp`
/// samples per pixel that took `seconds` to render (`None` if it was not
/// one render of its own).
pub fn write_image(
    dir: &Path,
    stem: &str,
    image: &Image,
    spp: u32,
    exposure: f32,
    seconds: Option<f64>,
) -> Result<Picture> {
    let (png, exr) = write_png_and_exr(dir, stem, image, exposure)?;
    Ok(Picture {
        png,
        exr,
        spp,
        exposure,
        seconds,
    })
}
