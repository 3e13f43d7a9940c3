//! Chapter 5 · Path tracing: one continuation per bounce, a ladder of samples
//! per pixel, and the three ways of finding the light (BRDF sampling, light
//! sampling, both under multiple importance sampling).

use anyhow::Result;
use raytracer::integrator::{DirectStrategy, PathTracer};

use crate::page::Section;
use crate::tour::{Chapter, Tour};

pub const CHAPTER: Chapter = Chapter::new(
    "path",
    "5 · Path tracing: a samples-per-pixel ladder; BRDF sampling, light sampling and MIS",
    render,
);

/// Chapter 5: path tracing, samples per pixel, and light sampling with MIS.
fn render(tour: &Tour) -> Result<Section> {
    let mut s = tour.chapter(
        "05-path",
        "5 · Path tracing",
        "One continuation per bounce and many samples per pixel: the noise falls as 1/√spp (each row of \
         pictures quadruples the samples and halves the noise). Below, the three ways of finding light at \
         equal samples: BRDF sampling only (lights are found by chance), light sampling only, and both \
         combined by multiple importance sampling.",
    )?;
    let pt = PathTracer::default();
    for spp in [1u32, 4, 16, 64] {
        let (scene, mut options) = tour.scene("cornell", spp)?;
        options.spp = options.spp.min(spp.max(1) * 8);
        let stem = format!("cornell-path-{spp:03}spp");
        tour.picture(
            &mut s,
            &scene,
            &pt,
            &options,
            &stem,
            &format!("Path tracing, {spp} spp."),
        )?;
    }
    let (scene, options) = tour.scene("cornell", 16)?;
    for (strategy, stem, caption) in [
        (
            DirectStrategy::BrdfOnly,
            "cornell-brdf-only",
            "BRDF sampling only.",
        ),
        (
            DirectStrategy::LightOnly,
            "cornell-light-only",
            "Light sampling only (no MIS).",
        ),
        (
            DirectStrategy::Mis,
            "cornell-mis",
            "Light and BRDF sampling under MIS (power heuristic).",
        ),
    ] {
        let pt = PathTracer {
            strategy,
            ..PathTracer::default()
        };
        tour.picture(&mut s, &scene, &pt, &options, stem, caption)?;
    }
    Ok(s.section)
}
