//! Chapter 6 · Light tracing: paths start on the lights and are connected to
//! the camera, and the caustic under a point light that only light paths find.

use anyhow::Result;
use raytracer::integrator::{Bdpt, LightTracer, PathTracer};

use crate::page::Section;
use crate::tour::{Chapter, Tour};

pub const CHAPTER: Chapter = Chapter::new(
    "light",
    "6 · Light tracing, and the caustic that only light paths find",
    render,
);

/// Chapter 6: light tracing, and the caustic only light paths can find.
fn render(tour: &Tour) -> Result<Section> {
    let mut c = tour.chapter(
        "06-light",
        "6 · Light tracing",
        "Paths start on the lights and every vertex is connected to the camera lens, weighted by the \
         camera's importance W_e, and splatted wherever it lands on the film. Under a point light, the \
         caustic a glass ball focuses onto the floor is found by light tracing and by bidirectional \
         tracing; a path tracer cannot find it (its paths would have to hit the point light through \
         the glass), which is the lecture's remark about point lights and non-glossy refraction.",
    )?;
    let (scene, options) = tour.scene("cornell", 64)?;
    let lt = LightTracer::default();
    tour.picture(
        &mut c,
        &scene,
        &lt,
        &options,
        "cornell-light",
        "Cornell box, light tracing.",
    )?;
    let (scene, options) = tour.scene("caustic", 32)?;
    let max_depth = Some(8);
    let pt = PathTracer {
        max_depth,
        ..PathTracer::default()
    };
    let lt = LightTracer {
        max_depth,
        ..LightTracer::default()
    };
    let bd = Bdpt {
        max_depth,
        ..Bdpt::default()
    };
    tour.picture(
        &mut c,
        &scene,
        &pt,
        &options,
        "caustic-path",
        "Path tracing: no caustic under the ball.",
    )?;
    tour.picture(
        &mut c,
        &scene,
        &lt,
        &options,
        "caustic-light",
        "Light tracing: the caustic appears.",
    )?;
    tour.picture(
        &mut c,
        &scene,
        &bd,
        &options,
        "caustic-bdpt",
        "Bidirectional path tracing: caustic and the rest.",
    )?;
    Ok(c.section)
}
