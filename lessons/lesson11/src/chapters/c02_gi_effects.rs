//! Chapter 2 · Global illumination effects: what direct light alone misses.
//! The same Cornell box with direct light only, ambient occlusion and full
//! global illumination (path tracing) side by side.

use anyhow::Result;
use raytracer::integrator::{AmbientOcclusion, Direct, DirectStrategy, PathTracer};

use crate::page::Section;
use crate::tour::{Chapter, Tour};

pub const CHAPTER: Chapter = Chapter::new(
    "gi-effects",
    "2 · Global illumination effects: direct light, ambient occlusion and full GI side by side",
    render,
);

/// Chapter 2: what direct light alone misses.
fn render(tour: &Tour) -> Result<Section> {
    let mut s = tour.chapter(
        "02-gi-effects",
        "2 · Global illumination effects",
        "The same Cornell box three ways. Direct light alone (one bounce) leaves the ceiling black and \
         the shadows hard-edged and empty. Ambient occlusion darkens corners and contact regions but knows \
         nothing of the light. Full global illumination (path tracing, unlimited depth) brings the indirect \
         light: a lit ceiling, soft shadows, and colour bleeding — red and green tints on the white boxes.",
    )?;
    let (scene, options) = tour.scene("cornell", 64)?;
    tour.picture(
        &mut s,
        &scene,
        &Direct,
        &options,
        "cornell-direct",
        "Direct light only (max depth 2).",
    )?;
    let ao = AmbientOcclusion { distance: 0.5 };
    tour.picture(
        &mut s,
        &scene,
        &ao,
        &options,
        "cornell-ao",
        "Ambient occlusion (rays of 0.5 m).",
    )?;
    let pt = PathTracer {
        max_depth: None,
        rr_depth: 5,
        strategy: DirectStrategy::Mis,
    };
    tour.picture(
        &mut s,
        &scene,
        &pt,
        &options,
        "cornell-path",
        "Global illumination: path tracing, unlimited depth.",
    )?;
    Ok(s.section)
}
