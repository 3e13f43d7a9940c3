//! Chapter 7 · Bidirectional path tracing: camera and light subpaths joined
//! in every way, and each (s, t) strategy's image before and after multiple
//! importance sampling.

use std::time::Instant;

use anyhow::Result;
use raytracer::film::Image;
use raytracer::integrator::Bdpt;
use raytracer::integrator::record::{PathRecord, SegmentEnd, VertexRef};
use raytracer::math::UVec2;
use raytracer::render::render_strategies;
use raytracer::scene::Scene;

use crate::page::{Figure, Picture, Section, seconds_text};
use crate::plots::{Labels, in_picture, pick_sample};
use crate::render_files::write_image;
use crate::tour::{Chapter, ChapterOutput, Tour};

pub const CHAPTER: Chapter = Chapter::new(
    "bdpt",
    "7 · Bidirectional path tracing and its (s, t) strategies",
    render,
);

/// The max depth D of the strategy images: every path of 1 to 3 segments.
const STRATEGY_DEPTH: u32 = 3;

/// Exposure of each strategy's own (unweighted) image in stops: each holds
/// the light of one path length only and is dark at exposure 0 (their sum is
/// shown at 0).
const UNWEIGHTED_EXPOSURE: f32 = 2.0;
/// Exposure of each strategy's weighted image: one more stop, as MIS leaves
/// each strategy a share of that light (a quarter, on average, of four).
const WEIGHTED_EXPOSURE: f32 = 3.0;

/// Chapter 7: bidirectional path tracing and its strategies.
fn render(tour: &Tour) -> Result<Section> {
    let mut c = tour.chapter(
        "07-bdpt",
        "7 · Bidirectional path tracing",
        lang::pick(
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
        "Подпът от камерата x₀ … x_{t−1} и подпът от светлината y₀ … y_{s−1} се строят \
         независимо и се съединяват по всички възможни начини с лъч за сянка: s върха от \
         светлината и t върха от камерата дават стратегията (s, t) – път от s + t точки и \
         s + t − 1 отсечки. s = 0 е път от камерата, който сам удря светлина (path tracing с BRDF \
         семплиране), s = 1 е next event estimation, t = 1 е light tracing. Всяка стратегия \
         оценява същата светлина с различна плътност p_{s,t}; multiple importance sampling \
         (степенната евристика, поглед напред към Лекция 12) претегля всяка стратегия там, \
         където плътността ѝ е висока. По-долу: собствената оценка на всяка стратегия (без \
         тегла: същата светлина с различен шум, или черно, където стратегията не може да създаде \
         път) и делът ѝ след MIS (претеглена). Претеглените картини на всички стратегии се \
         събират в bidirectional картина със същите максимална дълбочина, размер и проби на \
         пиксел – не в картината на Cornell box отгоре, която е по-дълбока, по-голяма и с повече \
         проби.",
        ),
    )?;
    let (scene, options) = tour.scene("cornell", 32)?;
    let bd = Bdpt::default();
    let picture = tour.picture(
        &mut c,
        &scene,
        &bd,
        &options,
        "cornell-bdpt",
        lang::pick(
            "Cornell box, bidirectional path tracing, unlimited depth (roulette from depth 5).",
            "Cornell box, bidirectional path tracing, без граница на дълбочината (руска рулетка \
             от дълбочина 5).",
        ),
    )?;
    bdpt_sample(tour, &mut c, &scene, options.seed, &picture)?;
    // At the scene's size (256 × 256, what the slides show them at) and 4
    // spp: each strategy is a render of its own, 18 in all.
    let (scene, mut options) = tour.scene("cornell", 4)?;
    options.progress = false;
    let start = Instant::now();
    let strategies = render_strategies(&scene, &options, STRATEGY_DEPTH);
    let seconds = start.elapsed().as_secs_f64();
    let (w, h) = (scene.camera.width, scene.camera.height);
    let count = 2 * strategies.len();
    let took = seconds_text(seconds);
    let made = |stops: f32| {
        lang::pick(
            format!(
                "max depth {STRATEGY_DEPTH}, {w}×{h}, no roulette, exposure +{stops} stops; one \
                 of {count} strategy images that took {took} together"
            ),
            format!(
                "максимална дълбочина {STRATEGY_DEPTH}, {w}×{h}, без рулетка, експозиция \
                 +{stops} стъпки; една от {count} картини на стратегиите, които заедно отнеха \
                 {took}"
            ),
        )
    };
    // The weighted images of all strategies add up to bidirectional path
    // tracing of max depth D = 3: written, so that the slide shows the sum.
    let mut sum = Image::new(w, h);
    for (_, weighted, _) in &strategies {
        for (a, b) in sum.pixels.iter_mut().zip(&weighted.pixels) {
            *a += *b;
        }
    }
    let sum_picture = write_image(&c.dir, "strategy-sum", &sum, options.spp, 0.0, None)?;
    for ((s, t), weighted, unweighted) in strategies {
        // The share of its own estimate that MIS leaves the strategy, so
        // that a black weighted image says why it is black.
        let total = |i: &Image| -> f64 { i.pixels.iter().map(|p| f64::from(p.x + p.y + p.z)).sum() };
        let share = 100.0 * total(&weighted) / total(&unweighted).max(1e-30);
        let share = if share >= 1.0 {
            format!("{share:.0} %")
        } else if share >= 0.005 {
            lang::pick(format!("{share:.2} %"), format!("{share:.2} %").replace('.', ","))
        } else {
            lang::pick("< 0.01 %", "< 0,01 %").to_string()
        };
        let kept = lang::pick(
            format!("weighted: its share after MIS, {share} of its own estimate's light"),
            format!("претеглена: делът ѝ след MIS, {share} от светлината на собствената ѝ оценка"),
        );
        for (image, kind, what, stops) in [
            (
                &unweighted,
                "unweighted",
                lang::pick(
                    "unweighted: its own estimate of every path it can make",
                    "без тегла: собствената ѝ оценка на всеки път, който може да създаде",
                )
                .to_string(),
                UNWEIGHTED_EXPOSURE,
            ),
            (&weighted, "weighted", kept, WEIGHTED_EXPOSURE),
        ] {
            let stem = format!("strategy-s{s}-t{t}-{kind}");
            let picture = write_image(&c.dir, &stem, image, options.spp, stops, None)?;
            let segments = match (s + t - 1, lang::current()) {
                (1, lang::Lang::En) => "1 segment".to_string(),
                (n, lang::Lang::En) => format!("{n} segments"),
                (1, lang::Lang::Bg) => "1 отсечка".to_string(),
                (n, lang::Lang::Bg) => format!("{n} отсечки"),
            };
            let made = made(stops);
            c.section.figures.push(Figure::new(
                &tour.out,
                &picture,
                &format!("s = {s}, t = {t} ({segments}), {what} ({made})."),
            ));
        }
    }
    c.section.figures.push(Figure::new(
        &tour.out,
        &sum_picture,
        &{
            let spp = options.spp;
            lang::pick(
                format!(
                    "The sum of the weighted images of all strategies: bidirectional path tracing \
                     of max depth {STRATEGY_DEPTH} ({w}×{h}, {spp} spp, no roulette)."
                ),
                format!(
                    "Сборът на претеглените картини на всички стратегии: bidirectional path \
                     tracing с максимална дълбочина {STRATEGY_DEPTH} ({w}×{h}, {spp} spp, без \
                     рулетка)."
                ),
            )
        },
    ));
    crate::console::say!(
        "{}",
        lang::pick(
            format!("  wrote the {count} strategy images of max depth {STRATEGY_DEPTH} in {took}"),
            format!(
                "  записах {count} картини на стратегиите с максимална дълбочина {STRATEGY_DEPTH} за {took}"
            ),
        )
    );
    Ok(c.section)
}

/// One recorded bidirectional sample over the picture: its camera subpath
/// x₀ x₁ …, its light subpath y₀ y₁ …, and one connection between them
/// (s ≥ 2 light and t ≥ 2 camera vertices: neither next event estimation
/// nor light tracing), the one that contributed most (D = 5).
fn bdpt_sample(
    tour: &Tour,
    c: &mut ChapterOutput,
    scene: &Scene,
    seed: u64,
    picture: &Picture,
) -> Result<()> {
    let bd = Bdpt {
        max_depth: Some(5),
        ..Bdpt::default()
    };
    let (w, h) = (scene.camera.width, scene.camera.height);
    let mut record = pick_sample(&bd, scene, UVec2::new(w / 2, h * 3 / 4), seed, |r| {
        let Some(i) = strongest_connection(r) else {
            return 0;
        };
        // Every vertex of the path it makes is in the picture.
        let [s, t] = r.segments[i].strategy.unwrap_or_default().map(|n| n as usize);
        let seen = |path, n| (0..n).all(|vertex| in_picture(r, VertexRef { path, vertex }, (w, h)));
        100 + 50 * u32::from(seen(0, t) && seen(1, s))
            + r.paths.iter().map(|p| p.vertices.len().min(4) as u32).sum::<u32>()
    });
    let keep = strongest_connection(&record);
    record.segments = keep
        .map(|i| vec![record.segments[i].clone()])
        .unwrap_or_default();
    let st = record
        .segments
        .first()
        .and_then(|s| s.strategy)
        .map_or_else(String::new, |[s, t]| {
            lang::pick(
                format!(" (here s = {s}, t = {t})"),
                format!(" (тук s = {s}, t = {t})"),
            )
        });
    tour.path_figure(
        c,
        &record,
        (scene, picture),
        Labels::Subpaths,
        "bdpt-sample",
        &lang::pick(
            format!(
                "One bidirectional sample, recorded by the renderer and drawn over the picture: \
                 the camera subpath x₀ x₁ …, the light subpath y₀ y₁ … from the lamp, and the \
                 connection of y_(s−1) to x_(t−1) that makes the strategy (s, t){st}."
            ),
            format!(
                "Една bidirectional проба, записана от рендерера и нарисувана върху картината: \
                 подпътят от камерата x₀ x₁ …, подпътят от светлината y₀ y₁ … от лампата и \
                 свързването на y_(s−1) с x_(t−1), което прави стратегията (s, t){st}."
            ),
        ),
    )
}

/// The index of the recorded connection between two subpath vertices
/// (s ≥ 2, t ≥ 2) with the largest contribution.
fn strongest_connection(r: &PathRecord) -> Option<usize> {
    let brightness = |i: &usize| r.segments[*i].contribution.iter().sum::<f32>();
    (0..r.segments.len())
        .filter(|&i| {
            let s = &r.segments[i];
            matches!(s.to, SegmentEnd::Vertex(_))
                && s.strategy.is_some_and(|[s, t]| s >= 2 && t >= 2)
                && brightness(&i) > 0.0
        })
        .max_by(|a, b| brightness(a).total_cmp(&brightness(b)))
}
