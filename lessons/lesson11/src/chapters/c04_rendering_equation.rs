//! Chapter 4 · The rendering equation solved by naive recursive Monte Carlo:
//! N rays at every hit, so a pixel sample costs up to 1 + N + … + N^(D−1)
//! rays (counted and tabulated), the ways to stop the recursion (a cut-off
//! on the throughput, biased; Russian roulette, unbiased), many rays at the
//! top and few below, and path tracing's one ray per bounce.

use anyhow::{Context, Result};
use lang::Lang;
use raytracer::film::Image;
use raytracer::integrator::record::VertexKind;
use raytracer::integrator::{DirectStrategy, NaiveRecursive, PathTracer};
use raytracer::math::UVec2;
use raytracer::metrics::mean;
use raytracer::render::RenderOptions;
use raytracer::scene::Scene;

use crate::page::{Figure, Picture, Section, Table, seconds_number};
use crate::plots::{Labels, pick_sample};
use crate::render_files::render_to_files;
use crate::tour::{Chapter, ChapterOutput, Quality, Tour};

pub const CHAPTER: Chapter = Chapter::new(
    "rendering-equation",
    "4 · The rendering equation: naive recursive Monte Carlo, its rays per pixel, and how to stop it",
    render,
);

/// The throughput below which the cut-off picture stops recursing. With
/// N = 4 on the Cornell box, 0.01 drops 6 % of the light (the image's mean,
/// measured), too little to see through the noise of BRDF sampling; 0.05
/// drops 14 % at 16 rays per pixel sample.
const CUTOFF: f32 = 0.05;

/// Mitsuba's max depth: in practice unlimited, so that only the cut-off or
/// the roulette ends the recursion.
const UNLIMITED: u32 = 65;

/// Chapter 4: the rendering equation solved by naive recursion, and its cost.
fn render(tour: &Tour) -> Result<Section> {
    let mut s = tour.chapter(
        "04-rendering-equation",
        lang::pick(
            "4 · The rendering equation and its recursion",
            "4 · Транспортното уравнение и неговата рекурсия",
        ),
        lang::pick(
        "The rendering equation is recursive: the light arriving at x from ω_i is the light leaving \
         the first point x′ that the ray from x in direction ω_i hits, towards x, L_i(x, ω_i) = \
         L_o(x′, −ω_i), itself given by the same equation. Naive recursive Monte Carlo solves it as \
         written: at every hit it shoots N random rays, finds by recursion what each one brings, \
         and averages f_r L_i cos θ_i / p over them. Depth D counts the rays (segments) of a path \
         from the camera, as Mitsuba's max depth does: D = 1 sees only the lights, D = 2 is direct \
         light. One pixel sample then traces at most 1 + N + … + N^(D−1) = (N^D − 1)/(N − 1) rays; \
         the table counts the rays actually traced, fewer because some leave through the open \
         front of the box. The recursion may also stop once the throughput β, the product of the \
         factors f_r cos θ_i / (N p) from the camera on, is almost 0 — the lecture's idea, and \
         biased: the light it drops is small, not zero, so the picture comes out darker — or by \
         Russian roulette (a preview of Lecture 12), which stops at random and divides what \
         survives by its chance, and stays unbiased; it ends a path, not a tree that keeps \
         splitting, so its picture splits only at the first hit. Many rays at the top and few below (16, 4, \
         2, 1) tames the tree, but not enough. Path tracing follows one ray per bounce and spends \
         the same rays on many samples per pixel.",
        "Транспортното уравнение е рекурсивно: светлината, идваща в x от ω_i, е светлината, \
         която напуска към x първата точка x′, в която лъчът от x в посока ω_i удря сцената, \
         L_i(x, ω_i) = L_o(x′, −ω_i), а тя се дава от същото уравнение. Наивната рекурсия с \
         Monte Carlo го решава така, както е записано: при всяко пресичане пуска N случайни \
         лъча, намира с рекурсия какво носи всеки от тях и усреднява f_r L_i cos θ_i / p по тях. \
         Дълбочината D брои лъчите (отсечките) на пътя от камерата, както максималната \
         дълбочина в Mitsuba: D = 1 вижда само светлините, D = 2 е директното осветление. Тогава \
         една проба на пиксел трасира най-много 1 + N + … + N^(D−1) = (N^D − 1)/(N − 1) лъча; \
         таблицата брои действително трасираните лъчи – по-малко, защото някои излизат през \
         отворената предна страна на кутията. Рекурсията може да спре и щом throughput-ът β, \
         произведението на множителите f_r cos θ_i / (N p) от камерата насам, стане почти 0 – \
         идеята на лекцията, и тя е отместена: светлината, която изпуска, е малка, но не е нула, \
         затова картината излиза по-тъмна – или чрез руска рулетка (поглед напред към Лекция \
         12), която спира случайно, дели оцелелите на шанса им и остава неотместена; тя \
         прекратява път, а не дърво, което продължава да се разклонява, затова в нейната \
         картина рекурсията се разклонява само при първото пресичане. Много лъчи горе и малко \
         долу (16, 4, 2, 1) обуздава дървото, но недостатъчно. Path tracing следва по един лъч \
         на отражение и харчи същите лъчи за много проби на пиксел.",
        ),
    )?;
    // The pictures at the scene's size (256 × 256: the slides show them at
    // about that width); the ladder of N and D, which only counts rays and
    // seconds, on a 96 × 96 copy.
    let (scene, mut options) = tour.scene("cornell", 1)?;
    options.progress = false;
    let mut ladder_scene = scene.clone();
    if tour.quality != Quality::Tiny {
        ladder_scene.set_resolution(96, 96);
    }
    let mut table = Table::in_both(
        lang::pick(
            "Naive recursion on the Cornell box: rays per pixel sample, counted",
            "Наивна рекурсия в Cornell box: лъчи за проба на пиксел, преброени",
        ),
        &[
            ("N (branching)", "N (разклоняване)"),
            ("max depth D", "максимална дълбочина D"),
            (
                "rays per pixel sample (measured)",
                "лъчи за проба на пиксел (измерени)",
            ),
            (
                "rays per pixel sample at most",
                "лъчи за проба на пиксел, най-много",
            ),
            ("seconds", "секунди"),
            ("ended by", "край чрез"),
        ],
    );
    // The ladder of N and D at 1 spp; N = 8, D = 4 is also the chapter's
    // picture, at full size.
    let mut ladder = options.clone();
    ladder.spp = 1;
    for n in [2u32, 4, 8] {
        for d in [2u32, 3, 4] {
            let naive = NaiveRecursive::new(vec![n], Some(d));
            // The pictured case's row is the picture's own count, so that
            // its caption and the table say the same.
            let rays = if (n, d) == (8, 4) {
                picture(
                    tour,
                    &mut s,
                    &scene,
                    &naive,
                    &options,
                    "naive-n8-d4",
                    lang::pick(
                        "Naive recursion, N = 8, D = 4",
                        "Наивна рекурсия, N = 8, D = 4",
                    ),
                )?
                .0
            } else {
                measure(&ladder_scene, &naive, &ladder)
            };
            table.push(|l| row(l, &naive, &rays, MAX_DEPTH, None));
            let r = table.rows.last().expect("a row");
            let (rays, seconds) = (&r[2], &r[4]);
            crate::console::say!(
                "{}",
                lang::pick(
                    format!("  naive N={n} D={d}: {rays} rays per pixel sample, {seconds} s"),
                    format!("  наивна N={n} D={d}: {rays} лъча за проба на пиксел, {seconds} s"),
                )
            );
        }
    }

    // Stopping the recursion: the same N, and a depth limit that neither
    // reaches. Without light sampling both are noisy; roulette, with fewer
    // rays per pixel sample, gets twice the samples. (Their means are
    // compared over the whole picture, so what matters is the pixel samples
    // in all: 256² × 8 is 64² × 128.)
    let small = scene.clone();
    let (cut_spp, roulette_spp) = match tour.quality {
        Quality::Tiny => (options.spp, options.spp),
        Quality::Quick => (8, 16),
        Quality::Full => (64, 128),
    };
    let spp = |n: u32| RenderOptions {
        spp: tour.overrides.spp.unwrap_or(n),
        ..options.clone()
    };
    // Roulette first, so that the cut-off's caption can compare their means;
    // on the page the cut-off comes first, as on the slide.
    // Roulette keeps a ray with a chance near the albedo, so with N = 4 at
    // every hit each ray would have about 4 × 0.6 > 1 children on average and
    // the tree would grow to the depth limit: it splits at the first hit only.
    let roulette = NaiveRecursive::try_new(vec![4, 1], Some(UNLIMITED), Some(1), None)
        .expect("a bounded recursion with a valid branching factor");
    let (roulette_rays, roulette_mean) = picture(
        tour,
        &mut s,
        &small,
        &roulette,
        &spp(roulette_spp),
        "naive-roulette",
        lang::pick(
            "Naive recursion, N = 4 rays at the first hit and one at each later hit, ended by \
             Russian roulette (a preview of Lecture 12), unbiased. With 4 rays at every hit the \
             roulette could not end the tree: it keeps a ray with a chance near the albedo, so \
             each ray would have more than one child on average",
            "Наивна рекурсия, N = 4 лъча при първото пресичане и по един при всяко следващо, \
             прекратена с руска рулетка (поглед напред към Лекция 12), неотместена. С 4 лъча при \
             всяко пресичане рулетката не би спряла дървото: тя запазва лъча с шанс близо до \
             албедото, така че всеки лъч би имал средно повече от едно продължение",
        ),
    )?;
    let cutoff = NaiveRecursive::try_new(vec![4], Some(UNLIMITED), None, Some(CUTOFF))
        .expect("a bounded recursion with a valid branching factor and cutoff");
    // Its caption is completed below, once its mean is known.
    let cut_spp_used = spp(cut_spp).spp;
    let biased = lang::pick(", biased", ", отместена");
    let (rays, cut_mean) = picture(
        tour,
        &mut s,
        &small,
        &cutoff,
        &spp(cut_spp),
        "naive-cutoff",
        &lang::pick(
            format!("Naive recursion, N = 4, stopped once the throughput β < {CUTOFF}{biased}"),
            format!("Наивна рекурсия, N = 4, спряна, щом throughput-ът β < {CUTOFF}{biased}"),
        ),
    )?;
    // Darker by more than 4 standard errors of the difference (a false claim
    // has probability below 4·10⁻⁵), or the caption says the samples are too few.
    let (cut, roulette_b) = (&cut_mean, &roulette_mean);
    let gap = roulette_b.mean - cut.mean;
    let se = cut.se.hypot(roulette_b.se);
    let lower = 100.0 * gap / roulette_b.mean;
    let roulette_mean = roulette_b.mean;
    let verdict = if gap > 4.0 * se {
        lang::pick(
            format!(
                ", biased: {lower:.0} % darker than the roulette picture (mean \
                 {roulette_mean:.4}), the light of the paths it cut, small but not zero."
            ),
            format!(
                ", отместена: с {lower:.0} % по-тъмна от картината с рулетката (средно \
                 {roulette_mean:.4}) – светлината на отрязаните пътища, малка, но не нула."
            ),
        )
    } else {
        lang::pick(
            format!(
                ", biased, though at {cut_spp_used} spp the difference from the roulette picture \
                 (mean {roulette_mean:.4}) is still within the noise."
            ),
            format!(
                ", отместена, макар че при {cut_spp_used} spp разликата от картината с рулетката \
                 (средно {roulette_mean:.4}) още е в рамките на шума."
            ),
        )
    };
    let figures = &mut s.section.figures;
    let n = figures.len();
    figures[n - 1].caption = figures[n - 1]
        .caption
        .replacen(&format!("{biased}."), &verdict, 1);
    figures.swap(n - 2, n - 1);
    let (en, bg) = (
        format!("β < {CUTOFF} (biased)"),
        format!("β < {CUTOFF} (отместено)"),
    );
    table.push(|l| row(l, &cutoff, &rays, (&en, &bg), None));
    table.push(|l| row(l, &roulette, &roulette_rays, ROULETTE, Some("4 1")));
    // A black picture (a scene lit only where these depths do not reach)
    // has no percentage: "(-inf % lower)" said nothing.
    let lower_text = if lower.is_finite() {
        lang::pick(
            format!(" ({lower:.0} % lower)"),
            format!(" (с {lower:.0} % по-ниско)"),
        )
    } else {
        String::new()
    };
    let (c, c_se, r, r_se) = (cut.mean, cut.se, roulette_b.mean, roulette_b.se);
    crate::console::say!(
        "{}",
        lang::pick(
            format!(
                "  mean of the image: cut-off {c:.4} ± {c_se:.4}, roulette {r:.4} ± {r_se:.4}{lower_text}"
            ),
            format!(
                "  средно на картината: спиране {c:.4} ± {c_se:.4}, рулетка {r:.4} ± {r_se:.4}{lower_text}"
            ),
        )
    );

    let top_heavy = NaiveRecursive::new(vec![16, 4, 2, 1], Some(5));
    let (rays, _) = picture(
        tour,
        &mut s,
        &scene,
        &top_heavy,
        &options,
        "naive-16-4-2-1",
        lang::pick(
            "Naive recursion with 16, 4, 2, 1 rays by level (many rays at the top, few below), \
             D = 5",
            "Наивна рекурсия с 16, 4, 2, 1 лъча по нива (много лъчи горе, малко долу), D = 5",
        ),
    )?;
    table.push(|l| row(l, &top_heavy, &rays, MAX_DEPTH, Some("16 4 2 1")));

    table.write_csv(&s.dir.join("naive-rays.csv"))?;
    s.section.tables.push(table);

    let pt = PathTracer {
        max_depth: Some(4),
        rr_depth: 5,
        strategy: DirectStrategy::BrdfOnly,
    };
    let mut equal = options.clone();
    equal.spp = tour.overrides.spp.unwrap_or(64);
    tour.picture(
        &mut s,
        &scene,
        &pt,
        &equal,
        "path-d4",
        &{
            let paths = equal.spp;
            lang::pick(
                format!(
                    "Path tracing, BRDF sampling only (as naive recursion), D = 4: {paths} paths \
                     of at most 4 rays per pixel."
                ),
                format!(
                    "Path tracing, само BRDF семплиране (като наивната рекурсия), D = 4: {paths} \
                     пътя от най-много 4 лъча на пиксел."
                ),
            )
        },
    )?;
    // The trees are drawn over a clean picture of the same size (light
    // sampling under MIS, 8 spp: a fraction of a second), not on the page.
    let clean = RenderOptions {
        spp: tour.overrides.spp.unwrap_or(8),
        ..options.clone()
    };
    let picture = render_to_files(
        &scene,
        &PathTracer::default(),
        &clean,
        &s.dir,
        "naive-tree-background",
        0.0,
    )?;
    for (branching, depth, stem, caption) in [
        (
            vec![3],
            3,
            "naive-tree",
            lang::pick(
                "The recursion of one pixel sample, recorded by the renderer and drawn over the \
                 picture: N = 3 rays from every hit, D = 3 (at most 1 + 3 + 9 rays); hits on the \
                 lamp are ringed.",
                "Рекурсията на една проба от пиксел, записана от рендерера и нарисувана върху \
                 картината: N = 3 лъча от всяко пресичане, D = 3 (най-много 1 + 3 + 9 лъча); \
                 ударите в лампата са оградени с кръгче.",
            ),
        ),
        (
            vec![4, 2, 1],
            4,
            "naive-tree-4-2-1",
            lang::pick(
                "The same pixel with 4, 2, 1 rays by level (many at the top, few below), D = 4: \
                 at most 1 + 4 + 8 + 8 rays.",
                "Същият пиксел с 4, 2, 1 лъча по нива (много горе, малко долу), D = 4: най-много \
                 1 + 4 + 8 + 8 лъча.",
            ),
        ),
    ] {
        let naive = NaiveRecursive::new(branching, Some(depth));
        naive_tree(tour, &mut s, (&scene, &picture), &naive, equal.seed, stem, caption)?;
    }
    Ok(s.section)
}

/// One recorded pixel sample of `naive` over `picture`: of a pixel on the
/// back wall, the sample with the most rays that reach the lamp.
fn naive_tree(
    tour: &Tour,
    s: &mut ChapterOutput,
    (scene, picture): (&Scene, &Picture),
    naive: &NaiveRecursive,
    seed: u64,
    stem: &str,
    caption: &str,
) -> Result<()> {
    let (w, h) = (scene.camera.width, scene.camera.height);
    let pixel = UVec2::new(w / 2, h * 2 / 5);
    let record = pick_sample(naive, scene, pixel, seed, |r| {
        let lamp = r.paths.iter().flat_map(|p| &p.vertices);
        lamp.filter(|v| v.kind == VertexKind::Light).count() as u32
    });
    tour.path_figure(s, &record, (scene, picture), Labels::None, stem, caption)
}

/// What a naive render measured: rays per pixel sample and seconds.
struct Rays {
    per_sample: f64,
    seconds: f64,
}

/// Renders `naive` without a picture: its rays per pixel sample and seconds.
fn measure(scene: &Scene, naive: &NaiveRecursive, options: &RenderOptions) -> Rays {
    // The counter keeps what `naive` traced before (its picture, for N = 8, D = 4).
    let before = naive.rays_traced();
    let result = raytracer::render::render(scene, naive, options);
    let samples = scene.camera.width as f64 * scene.camera.height as f64 * options.spp as f64;
    Rays {
        per_sample: (naive.rays_traced() - before) as f64 / samples,
        seconds: result.stats.elapsed.as_secs_f64(),
    }
}

/// The mean of an image over pixels and channels, and its standard error.
struct Brightness {
    mean: f64,
    se: f64,
}

/// Renders `naive` into a picture whose caption states the rays it traced
/// per pixel sample, as its row of `naive-rays.csv` does, and the mean of
/// the image (its brightness, with far less noise than any pixel): returns
/// both, the mean with its standard error.
fn picture(
    tour: &Tour,
    s: &mut ChapterOutput,
    scene: &Scene,
    naive: &NaiveRecursive,
    options: &RenderOptions,
    stem: &str,
    caption: &str,
) -> Result<(Rays, Brightness)> {
    let before = naive.rays_traced();
    let picture = render_to_files(scene, naive, options, &s.dir, stem, 0.0)?;
    let traced = naive.rays_traced() - before;
    let per_sample = traced as f64
        / (scene.camera.width as f64 * scene.camera.height as f64 * options.spp as f64);
    let rays = Rays {
        per_sample,
        seconds: picture.seconds.unwrap_or_default(),
    };
    let read = |path: &std::path::Path| {
        Image::read_exr(path).with_context(|| format!("cannot read back {}", path.display()))
    };
    let image = read(&picture.exr)?;
    let variance = read(&picture.exr.with_file_name(format!("{stem}-variance.exr")))?;
    let mean = mean(&image).element_sum() as f64 / 3.0;
    // The variance of a pixel's channel average is at most (Σ_c σ_c)²/9,
    // whatever the correlation of the channels; pixels are independent.
    let pixels = variance.pixels.len().max(1) as f64;
    let var_sum: f64 = variance
        .pixels
        .iter()
        .map(|v| {
            let s = v.x.max(0.0).sqrt() + v.y.max(0.0).sqrt() + v.z.max(0.0).sqrt();
            (s * s) as f64 / 9.0
        })
        .sum();
    let brightness = Brightness {
        mean,
        se: var_sum.sqrt() / pixels,
    };
    let bound = match bound(naive) {
        Some(b) => lang::pick(format!(" (at most {b})"), format!(" (най-много {b})")),
        None => String::new(),
    };
    let measured = rays_text(per_sample);
    s.section.figures.push(Figure::new(
        &tour.out,
        &picture,
        &lang::pick(
            format!(
                "{caption}. Measured: {measured} rays per pixel sample{bound}; mean of the image \
                 {mean:.4}."
            ),
            format!(
                "{caption}. Измерено: {measured} лъча за проба на пиксел{bound}; средно на \
                 картината {mean:.4}."
            ),
        ),
    ));
    Ok((rays, brightness))
}

/// The most rays one pixel sample can trace, if that is a number worth printing.
fn bound(naive: &NaiveRecursive) -> Option<u64> {
    naive
        .rays_per_sample_bound()
        .filter(|&b| b < 1_000_000_000_000)
}

/// A measured ray count as captions and the CSV print it.
fn rays_text(per_sample: f64) -> String {
    format!("{per_sample:.1}")
}

/// What ended a naive recursion, as its row says it: (English, Bulgarian).
type Ended<'a> = (&'a str, &'a str);

const MAX_DEPTH: Ended = ("max depth", "максималната дълбочина");
const ROULETTE: Ended = ("Russian roulette", "руска рулетка");

/// The row of `naive-rays.csv` (in English) or of the page (in `l`) for a
/// render of `naive`.
fn row(
    l: Lang,
    naive: &NaiveRecursive,
    rays: &Rays,
    (en, bg): Ended,
    branching: Option<&str>,
) -> Vec<String> {
    let n = branching.map_or_else(|| naive.branching()[0].to_string(), String::from);
    vec![
        n,
        naive
            .max_depth()
            .map_or_else(|| l.pick("unlimited", "без граница").into(), |d| d.to_string()),
        rays_text(rays.per_sample),
        bound(naive).map_or_else(|| "—".into(), |b| b.to_string()),
        seconds_number(rays.seconds),
        l.pick(en, bg).into(),
    ]
}
