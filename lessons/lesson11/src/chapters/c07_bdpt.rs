//! Chapter 7 · Bidirectional path tracing: camera and light subpaths joined
//! in every way, and each (s, t) strategy's image before and after multiple
//! importance sampling.

use anyhow::Result;
use raytracer::integrator::Bdpt;
use raytracer::render::render_strategies;

use crate::page::{Figure, Section};
use crate::render_files::write_image;
use crate::tour::{Chapter, Quality, Tour};

pub const CHAPTER: Chapter = Chapter::new(
    "bdpt",
    "7 · Bidirectional path tracing and its (s, t) strategies",
    render,
);

/// Chapter 7: bidirectional path tracing and its strategies.
fn render(tour: &Tour) -> Result<Section> {
    let mut c = tour.chapter(
        "07-bdpt",
        "7 · Bidirectional path tracing",
        "A camera subpath and a light subpath, joined in every possible way: s light vertices and t camera \
         vertices give the strategy (s, t). s = 0 is a camera path that hits a light, s = 1 next event \
         estimation, t = 1 light tracing. Multiple importance sampling (power heuristic) weights every \
         strategy where it is good. Below: each strategy's own estimate (unweighted) and its share after \
         MIS (weighted); the weighted images add up to the bidirectional image.",
    )?;
    let (scene, options) = tour.scene("cornell", 32)?;
    let bd = Bdpt::default();
    tour.picture(
        &mut c,
        &scene,
        &bd,
        &options,
        "cornell-bdpt",
        "Cornell box, bidirectional path tracing.",
    )?;
    let (mut scene, mut options) = tour.scene("cornell", 16)?;
    if tour.quality != Quality::Tiny {
        scene.set_resolution(96, 96);
    }
    options.progress = false;
    let max_depth = 3;
    for ((s, t), weighted, unweighted) in render_strategies(&scene, &options, max_depth) {
        for (image, kind) in [(&unweighted, "unweighted"), (&weighted, "weighted")] {
            let stem = format!("strategy-s{s}-t{t}-{kind}");
            let picture = write_image(&c.dir, &stem, image, options.spp)?;
            c.section.figures.push(Figure::new(
                &tour.out,
                &picture,
                &format!("s = {s}, t = {t}, {kind}."),
            ));
        }
    }
    println!(
        "  wrote the {} strategy images of max depth {max_depth}",
        c.section.figures.len() - 1
    );
    Ok(c.section)
}
