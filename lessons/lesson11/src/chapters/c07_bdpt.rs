//! Chapter 7 · Bidirectional path tracing: camera and light subpaths joined
//! in every way, and each (s, t) strategy's image before and after multiple
//! importance sampling.

use std::time::Instant;

use anyhow::Result;
use raytracer::integrator::Bdpt;
use raytracer::render::render_strategies;

use crate::page::{Figure, Section, seconds_text};
use crate::render_files::write_image;
use crate::tour::{Chapter, Quality, Tour};

pub const CHAPTER: Chapter = Chapter::new(
    "bdpt",
    "7 · Bidirectional path tracing and its (s, t) strategies",
    render,
);

/// The max depth D of the strategy images: every path of 1 to 3 segments.
const STRATEGY_DEPTH: u32 = 3;

/// Chapter 7: bidirectional path tracing and its strategies.
fn render(tour: &Tour) -> Result<Section> {
    let mut c = tour.chapter(
        "07-bdpt",
        "7 · Bidirectional path tracing",
        "A camera subpath x₀ … x_{t−1} and a light subpath y₀ … y_{s−1} are grown independently and \
         joined in every possible way by a shadow ray: s light vertices and t camera vertices make \
         the strategy (s, t), a path of s + t points and s + t − 1 segments. s = 0 is a camera path \
         that hits a light by itself (path tracing with BRDF sampling), s = 1 is next event \
         estimation, t = 1 is light tracing. Every strategy estimates the same light with a \
         different density p_{s,t}; multiple importance sampling (the power heuristic, a preview of \
         Lecture 12) weights each one where its density is high. Below, each strategy's own estimate \
         (unweighted: the same light, with different noise, or black where it cannot make a path) \
         and its share after MIS (weighted). The weighted images of all strategies add up to a \
         bidirectional image of the same max depth, size and samples per pixel — not to the \
         Cornell box picture above, which goes deeper, is larger and has more samples.",
    )?;
    let (scene, options) = tour.scene("cornell", 32)?;
    let bd = Bdpt::default();
    tour.picture(
        &mut c,
        &scene,
        &bd,
        &options,
        "cornell-bdpt",
        "Cornell box, bidirectional path tracing, unlimited depth (roulette from depth 5).",
    )?;
    let (mut scene, mut options) = tour.scene("cornell", 16)?;
    if tour.quality != Quality::Tiny {
        scene.set_resolution(96, 96);
    }
    options.progress = false;
    let start = Instant::now();
    let strategies = render_strategies(&scene, &options, STRATEGY_DEPTH);
    let seconds = start.elapsed().as_secs_f64();
    let (w, h) = (scene.camera.width, scene.camera.height);
    let count = 2 * strategies.len();
    let made = format!(
        "max depth {STRATEGY_DEPTH}, {w}×{h}, no roulette; one of {count} strategy images that took \
         {} together",
        seconds_text(seconds)
    );
    for ((s, t), weighted, unweighted) in strategies {
        for (image, kind, what) in [
            (
                &unweighted,
                "unweighted",
                "its own estimate of every path it can make",
            ),
            (&weighted, "weighted", "its share after MIS"),
        ] {
            let stem = format!("strategy-s{s}-t{t}-{kind}");
            let picture = write_image(&c.dir, &stem, image, options.spp, 0.0, None)?;
            c.section.figures.push(Figure::new(
                &tour.out,
                &picture,
                &format!(
                    "s = {s}, t = {t} ({}), {kind}: {what} ({made}).",
                    match s + t - 1 {
                        1 => "1 segment".to_string(),
                        n => format!("{n} segments"),
                    }
                ),
            ));
        }
    }
    println!(
        "  wrote the {count} strategy images of max depth {STRATEGY_DEPTH} in {}",
        seconds_text(seconds)
    );
    Ok(c.section)
}
