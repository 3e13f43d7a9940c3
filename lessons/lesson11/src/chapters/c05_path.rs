//! Chapter 5 · Path tracing: one continuation per bounce, a ladder of samples
//! per pixel, and the three ways of finding the light (BRDF sampling, light
//! sampling, both under multiple importance sampling), on the Cornell box and
//! on Veach's scene of glossy plates and lights of rising size.

use anyhow::Result;
use raytracer::brdf::Brdf;
use raytracer::integrator::{DirectStrategy, PathTracer};
use raytracer::light::{AreaLight, AreaShape, Light};
use raytracer::math::UVec2;
use raytracer::scene::Scene;

use crate::page::{Figure, Picture, Section};
use crate::plots::{Labels, SolidAngle, pick_sample, solid_angle_svg};
use crate::tour::{Chapter, ChapterOutput, Tour};

pub const CHAPTER: Chapter = Chapter::new(
    "path",
    "5 · Path tracing: a samples-per-pixel ladder; BRDF sampling, light sampling and MIS, on Veach's scene too",
    render,
);

/// The samples per pixel of the ladder, at every quality (the slides name
/// the pictures by them).
const LADDER: [u32; 4] = [1, 4, 16, 64];

/// Chapter 5: path tracing, samples per pixel, and light sampling with MIS.
fn render(tour: &Tour) -> Result<Section> {
    let mut s = tour.chapter(
        "05-path",
        "5 · Path tracing",
        lang::pick(
        "Path tracing, which Kajiya proposed in the same paper as the rendering equation: one random \
         continuation per bounce instead of N, and many samples per pixel instead, which also give \
         anti-aliasing for free. The throughput is updated at every bounce as in the recursion with \
         N = 1, β ← β f_r cos θ_i / p(ω_i), and Russian roulette (a preview of Lecture 12) ends the \
         paths at no fixed depth. The noise falls as 1/√spp: each picture of the ladder has four \
         times the samples of the one before and half its noise. Then the ways of finding the light \
         at equal samples, a preview of Lecture 12: BRDF sampling alone must hit a lamp by chance; \
         light sampling (next event estimation) joins every vertex to a point on a light by a shadow \
         ray; multiple importance sampling (MIS) uses both and weights each sample by the power \
         heuristic. On the all-diffuse Cornell box the three pictures differ little. Veach's scene \
         shows why MIS matters: light sampling wins with small lights and rough plates (bottom left), \
         BRDF sampling with large lights and shiny plates (top right), and MIS is good at both.",
        "Path tracing, който Каджия предлага в същата статия, в която е транспортното \
         уравнение: по едно случайно продължение на отражение вместо N, а вместо това много \
         проби на пиксел, които дават и безплатен anti-aliasing. Throughput-ът се обновява при \
         всяко отражение както при рекурсията с N = 1, β ← β f_r cos θ_i / p(ω_i), а руската \
         рулетка (поглед напред към Лекция 12) прекратява пътищата без фиксирана дълбочина. \
         Шумът намалява като 1/√spp: всяка картина от редицата има четири пъти повече проби \
         от предишната и наполовина по-малко шум. После – начините да намерим светлината при \
         равен брой проби, поглед напред към Лекция 12: само с BRDF семплиране пътят трябва да \
         удари лампа случайно; семплирането на светлините (next event estimation) свързва всеки \
         връх с точка от светлина чрез лъч за сянка; multiple importance sampling (MIS) ползва \
         и двете и претегля всяка проба със степенната евристика (power heuristic). В изцяло \
         дифузната Cornell box трите картини се различават малко. Сцената на Veach показва защо \
         MIS е важно: семплирането на светлините печели при малки светлини и грапави пластини \
         (долу вляво), BRDF семплирането – при големи светлини и лъскави пластини (горе вдясно), \
         а MIS се справя добре и с двете.",
        ),
    )?;
    let pt = PathTracer::default();
    let mut done = Vec::new();
    let mut last = None;
    for nominal in LADDER {
        let (scene, mut options) = tour.scene("cornell", nominal)?;
        options.spp = tour.overrides.spp.unwrap_or(nominal);
        if done.contains(&options.spp) {
            continue;
        }
        done.push(options.spp);
        let picture = tour.picture(
            &mut s,
            &scene,
            &pt,
            &options,
            &format!("cornell-path-{:03}spp", options.spp),
            lang::pick(
                "Path tracing (light and BRDF sampling under MIS, unlimited depth, roulette from \
                 depth 5).",
                "Path tracing (семплиране на светлините и по BRDF с MIS, без граница на \
                 дълбочината, руска рулетка от дълбочина 5).",
            ),
        )?;
        last = Some((scene, options.seed, picture));
    }
    if let Some((scene, seed, picture)) = last {
        path_sample(tour, &mut s, &scene, seed, &picture)?;
    }
    // Light sampling's change of variables, drawn from its geometry.
    let figure = s.dir.join("solid-angle.svg");
    raytracer::film::output::write_file(&figure, solid_angle_svg(&SolidAngle::default()))?;
    s.section.figures.push(Figure::plot(
        &tour.out,
        &figure,
        &{
            let theta = SolidAngle::default().theta_y_deg;
            lang::pick(
                format!(
                    "From area to solid angle: a patch dA at y, turned by θ_y = {theta}° from the \
                     direction to x, shows x only dA cos θ_y of itself (dashed), and at distance r \
                     that covers dω = cos θ_y dA / r² of the unit sphere around x (the arc)."
                ),
                format!(
                    "От площ към пространствен ъгъл: площадка dA в y, завъртяна на θ_y = {theta}° \
                     спрямо посоката към x, показва на x само dA cos θ_y от себе си (пунктирът), а \
                     на разстояние r това заема dω = cos θ_y dA / r² от единичната сфера около x \
                     (дъгата)."
                ),
            )
        },
    ));
    let (scene, options) = tour.scene("cornell", 16)?;
    for (strategy, stem, caption) in [
        (
            DirectStrategy::BrdfOnly,
            "cornell-brdf-only",
            lang::pick(
                "Cornell box, BRDF sampling only: the lamp is found only by paths that happen to \
                 hit it.",
                "Cornell box, само BRDF семплиране: лампата намират само пътищата, които случайно \
                 я ударят.",
            ),
        ),
        (
            DirectStrategy::LightOnly,
            "cornell-light-only",
            lang::pick(
                "Cornell box, light sampling only (next event estimation, no MIS).",
                "Cornell box, само семплиране на светлините (next event estimation, без MIS).",
            ),
        ),
        (
            DirectStrategy::Mis,
            "cornell-mis",
            lang::pick(
                "Cornell box, light and BRDF sampling under MIS (power heuristic): on diffuse \
                 walls hardly different from light sampling alone.",
                "Cornell box, семплиране на светлините и по BRDF с MIS (степенна евристика): \
                 върху дифузните стени почти не се различава от семплирането само на светлините.",
            ),
        ),
    ] {
        let pt = PathTracer {
            strategy,
            ..PathTracer::default()
        };
        tour.picture(&mut s, &scene, &pt, &options, stem, caption)?;
    }
    let (scene, options) = tour.scene("veach-mis", 16)?;
    for (strategy, stem, caption) in [
        (
            DirectStrategy::BrdfOnly,
            "veach-brdf",
            lang::pick(
                "Veach's scene, BRDF sampling only: clean where the light is large and the plate \
                 shiny (top right), noisy where a small light meets a rough plate (bottom left), \
                 whose directions rarely hit it.",
                "Сцената на Veach, само BRDF семплиране: чисто там, където светлината е голяма, а \
                 пластината лъскава (горе вдясно), шумно там, където малка светлина среща \
                 грапава пластина (долу вляво), чиито посоки рядко я улучват.",
            ),
        ),
        (
            DirectStrategy::LightOnly,
            "veach-light",
            lang::pick(
                "Veach's scene, light sampling only: clean where the light is small and the plate \
                 rough (bottom left), noisy where a large light meets a shiny plate (top right), \
                 where most points on the light fall outside the narrow lobe.",
                "Сцената на Veach, само семплиране на светлините: чисто там, където светлината е \
                 малка, а пластината грапава (долу вляво), шумно там, където голяма светлина \
                 среща лъскава пластина (горе вдясно) – там повечето точки от светлината падат \
                 извън тесния лоб.",
            ),
        ),
        (
            DirectStrategy::Mis,
            "veach-mis",
            lang::pick(
                "Veach's scene, both under MIS (power heuristic): each sample weighted by how \
                 likely the other strategy was to make it, good everywhere.",
                "Сцената на Veach, двете с MIS (степенна евристика): всяка проба е претеглена \
                 според това колко вероятно е другата стратегия да я създаде – добре навсякъде.",
            ),
        ),
    ] {
        let pt = PathTracer {
            strategy,
            max_depth: scene.settings.max_depth,
            rr_depth: scene.settings.rr_depth,
        };
        let caption = format!("{caption} {}", plates_and_lights(&scene));
        tour.picture(&mut s, &scene, &pt, &options, stem, &caption)?;
    }
    Ok(s.section)
}

/// One recorded path-tracing sample over the picture: a sample of a pixel
/// on the floor that makes all its bounces (D = 5: four hits), preferring
/// shadow rays that reach the lamp.
fn path_sample(
    tour: &Tour,
    s: &mut ChapterOutput,
    scene: &Scene,
    seed: u64,
    picture: &Picture,
) -> Result<()> {
    let pt = PathTracer {
        max_depth: Some(5),
        ..PathTracer::default()
    };
    let (w, h) = (scene.camera.width, scene.camera.height);
    let pixel = UVec2::new(w / 2, h * 3 / 4);
    let record = pick_sample(&pt, scene, pixel, seed, |r| {
        let hits = r.paths[0].vertices.len() as u32;
        let lit = r.segments.iter().filter(|s| !s.occluded).count() as u32;
        10 * hits + lit
    });
    tour.path_figure(
        s,
        &record,
        (scene, picture),
        Labels::Subpaths,
        "path-sample",
        &{
            let (x, y) = (pixel.x, pixel.y);
            lang::pick(
                format!(
                    "One path-tracing sample of pixel ({x}, {y}), recorded by the renderer and \
                     drawn over the picture: the camera ray from the lens x₀, the bounces x₁ … \
                     (D = 5), and from every vertex but the last a shadow ray to a point on the \
                     lamp (green; red where blocked). The last vertex has none, since its shadow \
                     ray would be segment D + 1, nor has a vertex whose lamp point lies behind its \
                     surface (f_r = 0 there)."
                ),
                format!(
                    "Една проба на path tracing от пиксел ({x}, {y}), записана от рендерера и \
                     нарисувана върху картината: лъчът от камерата, тръгнал от лещата x₀, \
                     отраженията x₁ … (D = 5) и от всеки връх без последния лъч за сянка до точка \
                     от лампата (зелен; червен, където е препречен). Последният връх няма такъв, \
                     защото лъчът му за сянка би бил отсечка D + 1; няма и връх, за който точката \
                     от лампата е зад повърхността му (там f_r = 0)."
                ),
            )
        },
    )
}

/// What Veach's scene is made of, read from the scene: the plates' Phong
/// exponents, the lights' radii, and the depth.
fn plates_and_lights(scene: &Scene) -> String {
    let exponents: Vec<String> = scene
        .objects
        .iter()
        .filter_map(|o| match &scene.brdfs[o.brdf as usize] {
            Brdf::Phong(p) if o.light.is_none() => Some(p.exponent.to_string()),
            _ => None,
        })
        .collect();
    let radii: Vec<String> = scene
        .lights
        .iter()
        .filter_map(|l| match l {
            Light::Area(AreaLight {
                shape: AreaShape::Sphere(s),
                ..
            }) => Some(format!("{}", s.radius)),
            _ => None,
        })
        .collect();
    let (exponents, radii) = (exponents.join(", "), radii.join(", "));
    let depth = scene.settings.max_depth.map_or_else(
        || lang::pick("unlimited", "без граница").into(),
        |d| d.to_string(),
    );
    lang::pick(
        format!(
            "Plates (shiniest at the top) Phong n = {exponents}; lights of radius {radii} (left to \
             right), equal power; max depth {depth}; the same samples per pixel for all three."
        ),
        format!(
            "Пластини (най-лъскавата е горе) Phong n = {exponents}; светлини с радиус {radii} \
             (отляво надясно), с еднаква мощност; максимална дълбочина {depth}; еднакъв брой \
             проби на пиксел и за трите."
        ),
    )
}
