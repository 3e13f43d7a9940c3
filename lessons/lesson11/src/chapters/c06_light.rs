//! Chapter 6 · Light tracing: paths start on the lights and are connected to
//! the camera, and the caustic under a point light that only light paths find.

use anyhow::Result;
use raytracer::integrator::{Bdpt, LightTracer, PathTracer};
use raytracer::math::UVec2;
use raytracer::scene::Scene;

use crate::page::{Picture, Section};
use crate::plots::{Labels, pick_sample};
use crate::tour::{Chapter, ChapterOutput, Tour};

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
        lang::pick(
        "Light tracing starts its paths on the lights: a point and a direction on a lamp, then \
         bounces as in path tracing. Every vertex is connected to the camera lens, weighted by the \
         camera's importance W_e (which plays the role L_e plays for the lights), and splatted \
         wherever it lands on the film. Under a point light, the caustic a glass ball focuses onto \
         the floor is found by light tracing and by bidirectional path tracing; a path tracer \
         cannot find it, since its paths would have to hit the point light after a refraction, \
         with probability 0 — the lecture's remark that path tracing cannot produce caustics \
         from non-glossy refraction and a point light. Light tracing has a blind spot of its \
         own: the glass ball is black in its picture, because the camera sees the ball only \
         through specular chains, and a pinhole camera cannot be reached along one.",
        "Light tracing започва пътищата си от светлините: точка и посока от лампа, после \
         отражения както при path tracing. Всеки връх се свързва с лещата на камерата, претеглен \
         с важността (importance) на камерата W_e (която играе ролята, която L_e има за \
         светлините), и приносът му се добавя там, където попадне върху филма (splatting). Под \
         точкова светлина каустиката, която стъклена топка фокусира върху пода, се намира от \
         light tracing и от bidirectional path tracing; path tracing не може да я намери, защото \
         пътищата му би трябвало да ударят точковата светлина след пречупване, а вероятността \
         за това е 0 – забележката от лекцията, че path tracing не може да получи каустики от \
         не-glossy пречупване и точкова светлина. И light tracing има своето сляпо петно: \
         стъклената топка е черна в неговата картина, защото камерата вижда топката само през \
         огледални вериги, а pinhole камера не може да бъде достигната по такава.",
        ),
    )?;
    let (scene, options) = tour.scene("cornell", 64)?;
    let lt = LightTracer::default();
    let picture = tour.picture(
        &mut c,
        &scene,
        &lt,
        &options,
        "cornell-light",
        lang::pick(
            "Cornell box, light tracing (unlimited depth, roulette from depth 5): the same \
             picture as path tracing, its noise spread differently, since each path lands where \
             it may.",
            "Cornell box, light tracing (без граница на дълбочината, руска рулетка от дълбочина \
             5): същата картина като при path tracing, но шумът е разпределен иначе, защото всеки \
             път попада, където се случи.",
        ),
    )?;
    light_sample(tour, &mut c, &scene, options.seed, &picture)?;
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
        lang::pick(
            "Path tracing, max depth 8: no caustic under the ball, since its paths would have to \
             hit the point light through the glass.",
            "Path tracing, максимална дълбочина 8: под топката няма каустика, защото пътищата му \
             би трябвало да ударят точковата светлина през стъклото.",
        ),
    )?;
    tour.picture(
        &mut c,
        &scene,
        &lt,
        &options,
        "caustic-light",
        lang::pick(
            "Light tracing, max depth 8: the caustic appears, but the glass ball is black. The \
             camera sees the ball only through specular chains (refraction and mirror \
             reflection), and a pinhole camera cannot be reached along one: a light path leaving \
             the glass hits the pinhole with probability 0, and a connection from a point on the \
             glass to the lens has f_r = 0 in every given direction.",
            "Light tracing, максимална дълбочина 8: каустиката се появява, но стъклената топка е \
             черна. Камерата вижда топката само през огледални вериги (пречупване и огледално \
             отражение), а pinhole камера не може да бъде достигната по такава: светлинен път, \
             излязъл от стъклото, уцелва отвора с вероятност 0, а свързване от точка върху \
             стъклото до лещата има f_r = 0 във всяка дадена посока.",
        ),
    )?;
    tour.picture(
        &mut c,
        &scene,
        &bd,
        &options,
        "caustic-bdpt",
        lang::pick(
            "Bidirectional path tracing, max depth 8: the caustic comes from the light subpaths, \
             the glass ball from the camera subpaths.",
            "Bidirectional path tracing, максимална дълбочина 8: каустиката идва от подпътищата \
             от светлината, стъклената топка – от подпътищата от камерата.",
        ),
    )?;
    Ok(c.section)
}

/// One recorded light-tracing sample over the picture: a light path that
/// bounces (D = 5), preferring one with many vertices seen by the camera.
fn light_sample(
    tour: &Tour,
    c: &mut ChapterOutput,
    scene: &Scene,
    seed: u64,
    picture: &Picture,
) -> Result<()> {
    let lt = LightTracer {
        max_depth: Some(5),
        ..LightTracer::default()
    };
    let (w, h) = (scene.camera.width, scene.camera.height);
    let record = pick_sample(&lt, scene, UVec2::new(w / 2, h / 2), seed, |r| {
        let vertices = r.paths.first().map_or(0, |p| p.vertices.len()) as u32;
        10 * r.segments.len() as u32 + vertices
    });
    tour.path_figure(
        c,
        &record,
        (scene, picture),
        Labels::Subpaths,
        "light-sample",
        lang::pick(
            "One light-tracing sample, recorded by the renderer and drawn over the picture: a \
             light path y₀ y₁ … from a point on the lamp, each vertex joined to the camera \
             (dashed), its contribution splatted where the camera sees it.",
            "Една проба на light tracing, записана от рендерера и нарисувана върху картината: \
             светлинен път y₀ y₁ … от точка на лампата, всеки връх свързан с камерата (с \
             пунктир), а приносът му – добавен там, където камерата го вижда.",
        ),
    )
}
