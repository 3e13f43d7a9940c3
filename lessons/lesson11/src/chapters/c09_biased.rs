//! Chapter 9 · The lecture's split of the GI algorithms into unbiased and
//! biased, measured: the taxonomy as pictures at equal time, each
//! algorithm's error split into bias² and variance over independent seeds,
//! RMSE against time, and pictures that name each biased algorithm's bias.

use std::sync::atomic::AtomicBool;

use lang::Lang;
use anyhow::{Context, Result, anyhow};
use raytracer::film::Image;
use raytracer::integrator::{
    IrradianceCache, IrradianceCacheSettings, PhotonMapping, PhotonSettings,
};
use raytracer::math::{Color, Vec2};
use raytracer::metrics::mean;
use raytracer::render::RenderOptions;
use raytracer::scene::Scene;

use crate::algorithms::{Algorithm, Knobs, Prepared, Run};
use crate::bias::{BiasVariance, split};
use crate::equal_time::{masked_rmse, off_the_light};
use crate::page::{Figure, Section, Table, seconds_number, seconds_text};
use crate::plots::{Bars, Chart, Part, Scale, Series, round_scale, signed_map_svg};
use crate::reference::{Reference, independent};
use crate::render_files::write_image;
use crate::tour::{Chapter, ChapterOutput, Quality, Tour};

pub const CHAPTER: Chapter = Chapter::new(
    "biased",
    "9 · Unbiased and biased at equal time: photon mapping, SPPM, instant radiosity, irradiance caching",
    render,
);

/// How hard the chapter works at each quality.
pub struct Effort {
    /// The Cornell box's size (the caustic scene's is its reference's,
    /// 128 × 96, or half that at tiny).
    size: Option<u32>,
    /// Seconds per algorithm for the Cornell box's equal-time pictures and
    /// its error-against-time curves: long enough that the build-once
    /// methods render several samples per pixel on top of their build, so
    /// that their pictures show what the lecture says of them (smooth, but
    /// wrong), and their curves have several points.
    budget: f64,
    /// Seconds per algorithm on the caustic scene.
    caustic_budget: f64,
    /// Independent seeds for the bias–variance split, each run at
    /// `budget / seed_share` seconds.
    pub seeds: u64,
    seed_share: f64,
    /// Light paths of the photon maps that show the blur (little noise).
    blur_photons: u64,
    /// Photon mapping's light paths on the caustic scene (its caustic is a
    /// small spot: the k nearest of fewer photons blur it away).
    caustic_photons: u64,
    knobs: Knobs,
}

pub fn effort(quality: Quality) -> Effort {
    let knobs = |photons, sppm_photons, vpl_paths| Knobs {
        photons,
        photon_k: PHOTON_K,
        sppm_photons,
        vpl_paths,
        clamp: VPL_CLAMP,
        ic_error: IC_ERROR,
        ic_rays: 64,
    };
    match quality {
        Quality::Tiny => Effort {
            size: None,
            budget: 0.02,
            caustic_budget: 0.02,
            seeds: 3,
            seed_share: 2.0,
            blur_photons: 5_000,
            caustic_photons: 2_000,
            knobs: knobs(2_000, 1_000, 8),
        },
        Quality::Quick => Effort {
            size: Some(128),
            budget: crate::equal_time::QUICK_SECONDS,
            caustic_budget: 0.2,
            seeds: 16,
            // Each seed's run 1/30 s, as before the budget grew from 0.2 s.
            seed_share: 12.0,
            // 50 000 at 8 spp, not 100 000 at 16: the Cornell box's blur
            // picture was a fifth of the chapter's time (7.3 of 33.8 s
            // under load), and pays for the longer equal-time budget.
            blur_photons: 50_000,
            caustic_photons: 50_000,
            knobs: knobs(1_500, 5_000, 32),
        },
        Quality::Full => Effort {
            size: Some(256),
            budget: 2.0,
            caustic_budget: 2.0,
            seeds: 16,
            seed_share: 4.0,
            blur_photons: 1_000_000,
            caustic_photons: 400_000,
            knobs: knobs(30_000, 20_000, 128),
        },
    }
}

/// Photon mapping's k nearest photons: twice the usual 50, a wider disk
/// whose blur (bias) stands out of the noise of 16 seeds.
const PHOTON_K: usize = 100;
/// On the caustic scene, the usual 50: its caustic is a small spot, and a
/// wider disk would only blur it further (and cost more per lookup).
const CAUSTIC_PHOTON_K: usize = 50;
/// The bound on instant radiosity's geometry term in the chapter.
const VPL_CLAMP: f32 = 0.5;
/// Ward's threshold a of irradiance caching in the equal-time comparison.
const IC_ERROR: f32 = 0.6;

/// Chapter 9: unbiased and biased, at equal time.
fn render(tour: &Tour) -> Result<Section> {
    let e = effort(tour.quality);
    let k = e.knobs;
    let mut c = tour.chapter(
        "09-biased",
        lang::pick(
            "9 · Unbiased and biased algorithms",
            "9 · Неотместени и отместени алгоритми",
        ),
        &lang::fill(
            lang::pick(
                "The lecture splits the GI algorithms in two. Unbiased ones (path tracing, light \
                 tracing, bidirectional, Metropolis): their error is only noise, and it falls as \
                 1/√t. Biased ones (photon mapping, irradiance caching, instant radiosity): they can \
                 give a picture without noise whose error does not go away — smooth but wrong, and \
                 sooner. Here each algorithm gets the same time on the Cornell box (about {budget} each; \
                 every time below includes building the photon maps, virtual point lights or cache \
                 records), measured against Mitsuba 3's image, and on the caustic scene (about {caustic_budget} \
                 each), measured against a stored bidirectional render with thousands of samples. \
                 Photon mapping: {photons} light paths ({caustic_photons} on the caustic scene, whose caustic is a small \
                 spot), the {photon_k} nearest photons under an Epanechnikov kernel (a wide disk: \
                 smooth, and visibly biased; {caustic_photon_k} on the caustic scene). SPPM: {sppm_photons} \
                 photon paths per pass, radii shrinking with α = 2/3 (consistent: its bias falls \
                 with the passes). Instant radiosity: the VPLs of {vpl_paths} light paths, the geometry term \
                 clamped at {vpl_clamp}. Irradiance caching: a = {ic_error}, {ic_rays} rays per record. The error \
                 of each algorithm is split into bias² and variance over {seeds} runs with independent \
                 seeds ({seed_time} each): the mean of the runs minus the reference is the bias itself, \
                 shown as a picture.",
                "Лекцията дели алгоритмите за глобално осветление на две. Неотместените (path \
                 tracing, light tracing, bidirectional, Metropolis): грешката им е само шум и пада \
                 като 1/√t. Отместените (photon mapping, irradiance caching, instant radiosity): \
                 могат да дадат картинка без шум, чиято грешка не изчезва – гладка, но грешна, и \
                 по-рано. Тук всеки алгоритъм получава едно и също време в Cornell box (около {budget} \
                 всеки; всяко време по-долу включва строежа на фотонните карти, виртуалните \
                 точкови светлини или записите на кеша), сравнен с картината на Mitsuba 3, и в \
                 сцената с каустиката (около {caustic_budget} всеки), сравнен със запазено bidirectional \
                 рендериране с хиляди проби. Photon mapping: {photons} светлинни пътя ({caustic_photons} в сцената с \
                 каустиката, чиято каустика е малко петно), {photon_k}-те най-близки фотона с \
                 ядрото на Епанечников (широк диск: гладко и видимо отместено; \
                 {caustic_photon_k} в сцената с каустиката). SPPM: {sppm_photons} фотонни пътя на проход, \
                 радиусите намаляват с α = 2/3 (състоятелен: отместването му намалява с \
                 проходите). Instant radiosity: VPL на {vpl_paths} светлинни пътя, геометричният член \
                 ограничен до {vpl_clamp}. Irradiance caching: a = {ic_error}, {ic_rays} лъча на запис. Грешката \
                 на всеки алгоритъм е разделена на отместване² и дисперсия по {seeds} рендерирания с \
                 независими случайни числа (по {seed_time} всяко): средното им минус еталона е самото \
                 отместване, показано като картина.",
            ),
            &[
                ("budget", &seconds_text(e.budget)),
                ("caustic_budget", &seconds_text(e.caustic_budget)),
                ("photons", &k.photons),
                ("caustic_photons", &e.caustic_photons),
                ("sppm_photons", &k.sppm_photons),
                ("vpl_paths", &k.vpl_paths),
                ("ic_error", &k.ic_error),
                ("ic_rays", &k.ic_rays),
                ("seeds", &e.seeds),
                ("seed_time", &seconds_text(e.budget / e.seed_share)),
                ("photon_k", &PHOTON_K),
                ("caustic_photon_k", &CAUSTIC_PHOTON_K),
                ("vpl_clamp", &VPL_CLAMP),
            ],
        ),
    )?;
    let mut table = Table::in_both(
        "Equal time on the Cornell box: error against Mitsuba 3's image, split into bias² and variance",
        &[
            ("algorithm", "алгоритъм"),
            ("unbiased", "неотместен"),
            ("spp", "spp"),
            ("seconds", "секунди"),
            ("RMSE", "RMSE"),
            ("bias² ± SE", "отместване² ± SE"),
            ("variance", "дисперсия"),
            ("first time RMSE ≤ target", "първо време с RMSE ≤ целта"),
        ],
    );

    // The Cornell box: the curves, the grid, bias and variance.
    let (mut scene, mut base) = tour.scene("cornell", 1)?;
    if let Some(size) = e.size {
        scene.set_resolution(size, size);
    }
    base.progress = false;
    let builtin = tour.overrides.scene.is_none().then_some("cornell");
    let (reference, max_depth) = independent(builtin, &scene, &base, 5, 256);
    // The lamp and the pixels at its edge are left out of every error.
    let counted = off_the_light(&reference.mean);
    let floor = crate::equal_time::masked_noise_floor(&reference, &counted);
    crate::console::say!(
        "  {}",
        lang::fill(
            lang::pick(
                "{name} {w}×{h}: max depth {max_depth}, reference {source} (noise floor {floor:.5})",
                "{name} {w}×{h}: максимална дълбочина {max_depth}, еталон {source} (дъно на шума \
                 {floor:.5})",
            ),
            &[
                ("name", &scene.name),
                ("w", &scene.camera.width),
                ("h", &scene.camera.height),
                ("max_depth", &max_depth),
                ("source", &reference.source_here()),
                ("floor", &floor),
            ]
        )
    );
    let mut measured = Vec::new();
    for algorithm in Algorithm::ALL {
        let m = measure(&scene, &base, algorithm, &k, max_depth, &reference, &counted, &e)?;
        crate::console::say!(
            "  {} {:20} {:5} spp {:>8} ({} {:>8})  RMSE {:.4}  {}² {}  {} {:.2e}",
            scene.name,
            algorithm.label(),
            m.run.spp,
            seconds_text(m.run.seconds),
            lang::pick("build", "построяване"),
            seconds_text(m.build_seconds),
            m.rmse,
            lang::pick("bias", "отместване"),
            m.split.bias2_text(),
            lang::pick("variance", "дисперсия"),
            m.split.variance
        );
        measured.push(m);
    }
    // The target: halfway (log) between the best and the worst error at
    // equal time, so that some reach it early, some late and some never.
    let (best, worst) = measured
        .iter()
        .fold((f64::MAX, 0.0f64), |(b, w), m| (b.min(m.rmse), w.max(m.rmse)));
    let target = (best * worst).sqrt();
    for m in &measured {
        let reached = first_time_below(&m.curve, target);
        let unbiased = m.algorithm.unbiased();
        let picture = write_image(
            &c.dir,
            &format!("{}-{}", scene.name, m.algorithm.stem()),
            &m.run.image,
            m.run.spp,
            0.0,
            Some(m.run.seconds),
        )?;
        c.section.figures.push(Figure::new(
            &tour.out,
            &picture,
            &lang::pick(
                format!(
                    "Cornell box, {} ({}), equal time: {} spp in {} ({}×{}, max depth {max_depth}), \
                     RMSE {:.4} against {}, off the lamp.",
                    m.algorithm.label(),
                    if unbiased { "unbiased" } else { "biased" },
                    m.run.spp,
                    seconds_text(m.run.seconds),
                    scene.camera.width,
                    scene.camera.height,
                    m.rmse,
                    reference.name
                ),
                format!(
                    "Cornell box, {} ({}), при равно време: {} spp за {} ({}×{}, максимална \
                     дълбочина {max_depth}), RMSE {:.4} спрямо {}, без лампата.",
                    m.algorithm.label(),
                    if unbiased { "неотместен" } else { "отместен" },
                    m.run.spp,
                    seconds_text(m.run.seconds),
                    scene.camera.width,
                    scene.camera.height,
                    m.rmse,
                    reference.name
                ),
            ),
        ));
        table.push(|l| {
            vec![
                m.algorithm.label().into(),
                match (unbiased, l) {
                    (true, Lang::En) => "yes",
                    (false, Lang::En) => "no",
                    (true, Lang::Bg) => "да",
                    (false, Lang::Bg) => "не",
                }
                .into(),
                m.run.spp.to_string(),
                seconds_number(m.run.seconds),
                format!("{:.5}", m.rmse),
                m.split.bias2_text(),
                format!("{:.3e}", m.split.variance),
                reached.map_or_else(
                    || {
                        format!(
                            "{} {}",
                            l.pick("not within", "не и за"),
                            seconds_text(m.run.seconds)
                        )
                    },
                    seconds_number,
                ),
            ]
        });
    }
    let flat: Vec<&str> = measured
        .iter()
        .filter(|m| m.build_once() && flattens(&m.curve))
        .map(|m| m.algorithm.label())
        .collect();
    // The charts in each language of the decks; the page shows its own.
    for language in lang::Lang::ALL {
        lang::with(language, || -> Result<()> {
            let code = language.code();
            let chart = rmse_time_chart(
                &measured,
                &BUILD_ONCE,
                lang::pick("Cornell box: build once", "Cornell box: строят веднъж"),
                None,
            );
            chart.write(&c.dir.join(format!("{}-rmse-time-{code}.svg", scene.name)))?;
            let chart = rmse_time_chart(
                &measured,
                &FALLING,
                lang::pick("Cornell box: unbiased, and SPPM", "Cornell box: неотместени и SPPM"),
                Some(floor),
            );
            chart.write(&c.dir.join(format!("{}-rmse-time-sppm-{code}.svg", scene.name)))?;
            bias_variance_bars(&measured, e.seeds, e.budget / e.seed_share)
                .write(&c.dir.join(format!("{}-bias-variance-{code}.svg", scene.name)))
        })?;
    }
    let code = lang::current().code();
    let svg = c.dir.join(format!("{}-rmse-time-{code}.svg", scene.name));
    let floors: Vec<String> = measured
        .iter()
        .filter(|m| m.build_once() && m.split.resolved())
        .map(|m| format!("{} {:.4}", m.algorithm.label(), m.split.bias2.sqrt()))
        .collect();
    let (w, h) = (scene.camera.width, scene.camera.height);
    c.section.figures.push(Figure::plot(
        &tour.out,
        &svg,
        &lang::pick(
            format!(
                "RMSE against time, log–log, against {} off the lamp, {w}×{h} pixels, max depth \
                 {max_depth}, each point a run of its own with four times the work of the one \
                 before (the last cut to end at the budget): photon mapping, clamped instant radiosity and irradiance caching build \
                 once, then render more samples per pixel that all read what was built, so their \
                 error falls towards the floor that build sets and no further (path tracing, \
                 for scale, is on the next chart). The dashed lines are that floor's part no build removes, \
                 √bias² from {} seeds ({}); a single build's own noise adds to it. {}",
                reference.name,
                e.seeds,
                floors.join(", "),
                flat_text(&flat, e.budget),
            ),
            format!(
                "RMSE спрямо времето, в логаритмичен мащаб, спрямо {} без лампата, {w}×{h} \
                 пиксела, максимална дълбочина {max_depth}; всяка точка е отделно рендериране с \
                 четири пъти повече работа от предишното (последното е съкратено, за да свърши в \
                 срока): photon mapping, instant radiosity с \
                 ограничаване и irradiance caching строят веднъж, после рендерират още проби на \
                 пиксел, които четат построеното, затова грешката им пада към дъното, което \
                 строежът определя, и не по-надолу (path tracing, за сравнение, е на следващата \
                 графика). \
                 Прекъснатите линии са частта от това дъно, която никой строеж не премахва, \
                 √(отместване²) от {} рендерирания ({}); шумът на един строеж се добавя към нея. {}",
                reference.name,
                e.seeds,
                floors.join(", "),
                flat_text(&flat, e.budget),
            ),
        ),
    ));
    let svg = c.dir.join(format!("{}-rmse-time-sppm-{code}.svg", scene.name));
    c.section.figures.push(Figure::plot(
        &tour.out,
        &svg,
        &lang::pick(
            format!(
                "RMSE against time as above, for the unbiased path tracing and bidirectional \
                 path tracing, which fall as t^−1/2 all the way to zero, and SPPM: biased but \
                 consistent, each pass shrinks its radii, so its bias falls with the passes too \
                 and it has no fixed floor to draw; its bias² over {} seeds: {}. The grey dashed \
                 line is the reference's own noise, {floor:.5}, below which no error measured \
                 against it falls.",
                e.seeds,
                sppm_bias(&measured),
            ),
            format!(
                "RMSE спрямо времето както по-горе, за неотместените path tracing и bidirectional \
                 path tracing, които падат като t^−1/2 чак до нула, и SPPM: отместен, но \
                 състоятелен, всеки проход намалява радиусите му, затова и отместването му пада с \
                 проходите и няма постоянно дъно, което да се начертае; отместването² му от {} \
                 рендерирания: {}. Сивата прекъсната линия е шумът на самия еталон, {floor:.5}, \
                 под който не пада никоя грешка, измерена спрямо него.",
                e.seeds,
                sppm_bias(&measured),
            ),
        ),
    ));
    let svg = c.dir.join(format!("{}-bias-variance-{code}.svg", scene.name));
    c.section.figures.push(Figure::plot(
        &tour.out,
        &svg,
        &lang::pick(
            format!(
                "Bias² and variance per algorithm (log scale) at {} each, from {} runs with \
                 independent seeds: variance is their spread per pixel, bias² the squared error of \
                 their mean image against {} off the lamp, less the part the spread and the \
                 reference's own noise (floor {floor:.5}) explain. An outline is a bias² that does \
                 not stand out of its noise, drawn up to its bound (b̂² + 2 SE); the table gives \
                 each bias² with its standard error",
                seconds_text(e.budget / e.seed_share),
                e.seeds,
                reference.name
            ),
            format!(
                "Отместване² и дисперсия за всеки алгоритъм (логаритмична скала) при {} на \
                 рендериране, от {} рендерирания с независими случайни числа: дисперсията е \
                 разсейването им във всеки пиксел, отместването² – квадратът на грешката на \
                 средната им картинка спрямо {} без лампата, без частта, която разсейването и \
                 шумът на самия еталон (дъно {floor:.5}) обясняват. Контурът е отместване², което \
                 не се откроява от шума си, начертано до горната му граница (b̂² + 2 SE); \
                 таблицата дава всяко отместване² със стандартната му грешка",
                seconds_text(e.budget / e.seed_share),
                e.seeds,
                reference.name
            ),
        ),
    ));
    bias_pictures(tour, &mut c, &scene.name, &measured, &reference, e.seeds)?;

    // The bias, named.
    photon_blur(
        tour,
        &mut c,
        (&scene, &base, max_depth),
        &reference,
        e.blur_photons,
        0.15,
        lang::pick(
            "besides the photon map's noise (blotches), it sits along the edges and in the \
             corners, where the disk reaches onto the neighbouring wall and averages its light in",
            "освен шума на фотонната карта (петната), то е по ръбовете и в ъглите, където дискът \
             стига до съседната стена и осреднява и нейната светлина",
        ),
    )?;
    let vpl = &measured[4];
    let unclamped = Knobs { clamp: 0.0, ..k };
    let prepared = Algorithm::Vpl
        .prepare(&scene, &unclamped, max_depth, base.seed)
        .map_err(|e| anyhow!(e))?;
    let full = prepared.run(&scene, &base, vpl.run.spp);
    let picture = write_image(
        &c.dir,
        &format!("{}-vpl-unclamped", scene.name),
        &full.image,
        full.spp,
        0.0,
        Some(full.seconds),
    )?;
    c.section.figures.push(Figure::new(
        &tour.out,
        &picture,
        &lang::pick(
            format!(
                "Instant radiosity without clamping: the same VPLs and {} spp as the clamped \
                 picture of the equal-time comparison; each bright blob is a VPL close to the \
                 surface it lights, where G grows as 1/r².",
                full.spp
            ),
            format!(
                "Instant radiosity без ограничаване: същите VPL и {} spp като ограничената картина \
                 от сравнението при равно време; всяко ярко петно е VPL близо до повърхността, \
                 която осветява, където G расте като 1/r².",
                full.spp
            ),
        ),
    ));
    let (lost, total) = (mean(&full.image) - mean(&vpl.run.image), mean(&full.image));
    let removed: Vec<f32> = full
        .image
        .pixels
        .iter()
        .zip(&vpl.run.image.pixels)
        .map(|(&a, &b)| luminance(a - b))
        .collect();
    signed_figure(
        tour,
        &mut c,
        &format!("{}-vpl-clamping", scene.name),
        &removed,
        (scene.camera.width, scene.camera.height),
        &lang::pick(
            format!(
                "What clamping G at {VPL_CLAMP} removes: unclamped minus clamped instant radiosity, \
                 the same VPLs and pixel samples, in luminance. Each blob is one VPL close to the \
                 surface it lights (most lie near where two surfaces meet); the clamped image is \
                 {:.1}% darker overall.",
                100.0 * luminance(lost) / luminance(total).max(1e-9)
            ),
            format!(
                "Какво премахва ограничаването на G при {VPL_CLAMP}: instant radiosity без минус с \
                 ограничаване, при същите VPL и проби, в яркост. Всяко петно е една VPL близо до \
                 повърхността, която осветява (повечето са близо до мястото, където две повърхности \
                 се срещат); ограничената картина е с {:.1}% по-тъмна общо.",
                100.0 * luminance(lost) / luminance(total).max(1e-9)
            ),
        ),
    )?;
    irradiance_records(tour, &mut c, (&scene, &base, max_depth), &k, &reference, &counted)?;

    // The caustic scene: the grid at equal time, for the algorithms that
    // find a caustic (instant radiosity and irradiance caching, like path
    // tracing, see it only through their camera paths).
    let (mut scene, mut base) = tour.scene("caustic", 1)?;
    if e.size.is_some() {
        scene.set_resolution(128, 96);
    }
    base.progress = false;
    let (reference, max_depth) = independent(Some("caustic"), &scene, &base, 8, 256);
    crate::console::say!(
        "  {}",
        lang::fill(
            lang::pick(
                "caustic {w}×{h}: max depth {max_depth}, reference {source}",
                "caustic {w}×{h}: максимална дълбочина {max_depth}, еталон {source}",
            ),
            &[
                ("w", &scene.camera.width),
                ("h", &scene.camera.height),
                ("max_depth", &max_depth),
                ("source", &reference.source_here()),
            ]
        )
    );
    let everywhere = vec![true; reference.mean.pixels.len()];
    let caustic_knobs = Knobs {
        photons: e.caustic_photons,
        photon_k: CAUSTIC_PHOTON_K,
        ..k
    };
    for algorithm in [
        Algorithm::Path,
        Algorithm::Bdpt,
        Algorithm::Photon,
        Algorithm::Sppm,
    ] {
        let prepared = algorithm
            .prepare(&scene, &caustic_knobs, max_depth, base.seed)
            .map_err(|e| anyhow!(e))?;
        let (run, _) = equal_time(&prepared, &scene, &base, e.caustic_budget, |image| {
            masked_rmse(image, &reference.mean, &everywhere)
        });
        let error = masked_rmse(&run.image, &reference.mean, &everywhere);
        crate::console::say!(
            "  caustic {:20} {:5} spp {:>8}  RMSE {error:.4}",
            algorithm.label(),
            run.spp,
            seconds_text(run.seconds)
        );
        let picture = write_image(
            &c.dir,
            &format!("caustic-{}", algorithm.stem()),
            &run.image,
            run.spp,
            0.0,
            Some(run.seconds),
        )?;
        c.section.figures.push(Figure::new(
            &tour.out,
            &picture,
            &lang::pick(
                format!(
                    "Caustic scene, {}, {} spp in {} ({}×{}, max depth {max_depth}): RMSE \
                     {error:.4} against {}. At few samples per pixel the glass ball shows dark \
                     dots: a sample that reflects there (Fresnel, most often at the rim) sees the \
                     black sky above the open box.",
                    algorithm.label(),
                    run.spp,
                    seconds_text(run.seconds),
                    scene.camera.width,
                    scene.camera.height,
                    reference.name
                ),
                format!(
                    "Сцената с каустиката, {}, {} spp за {} ({}×{}, максимална дълбочина \
                     {max_depth}): RMSE {error:.4} спрямо {}. При малко проби на пиксел \
                     стъклената топка има тъмни точки: проба, която там се отразява (Френел, \
                     най-често по ръба), вижда черното небе над отворената кутия.",
                    algorithm.label(),
                    run.spp,
                    seconds_text(run.seconds),
                    scene.camera.width,
                    scene.camera.height,
                    reference.name
                ),
            ),
        ));
    }
    photon_blur(
        tour,
        &mut c,
        (&scene, &base, max_depth),
        &reference,
        4 * e.blur_photons,
        0.15,
        lang::pick(
            "the error is largest at the caustic, where the light changes fastest; elsewhere the \
             blotches are the photon map's own noise",
            "грешката е най-голяма при каустиката, където светлината се мени най-бързо; другаде \
             петната са собственият шум на фотонната карта",
        ),
    )?;
    table.caption = lang::pick(
        format!(
            "{}; errors over the pixels off the lamp and its edge (there the error is the \
             anti-aliasing noise of an edge 18.6 times brighter than white, the same for all); \
             bias² ± its standard error (jackknife over the seeds), or \"< bound\" where it does \
             not stand out of its noise; the target RMSE, {target:.4}, lies halfway (log) between \
             the best and the worst error at equal time.",
            table.caption
        ),
        format!(
            "Равно време в Cornell box: грешката спрямо картината на Mitsuba 3, разделена на \
             отместване² и дисперсия; грешките са по пикселите без лампата и ръба ѝ (там грешката \
             е шумът от изглаждането на ръб, 18,6 пъти по-ярък от бялото, еднакъв за всички); \
             отместване² ± стандартната му грешка (jackknife по рендериранията) или \"< граница\", \
             когато не се откроява от шума; целевата RMSE, {target:.4}, е по средата (в \
             логаритмичен мащаб) между най-добрата и най-лошата грешка при равно време."
        ),
    );
    table.write_csv(&c.dir.join("biased.csv"))?;
    c.section.tables.push(table);
    Ok(c.section)
}

/// One algorithm measured on one scene.
struct Measured {
    algorithm: Algorithm,
    /// The equal-time run.
    run: Run,
    rmse: f64,
    /// (seconds, RMSE) of runs with doubling work.
    curve: Vec<(f64, f64)>,
    /// Bias² and variance over independent seeds.
    split: BiasVariance,
    build_seconds: f64,
}

impl Measured {
    /// Whether the algorithm builds once and then only renders more samples
    /// per pixel (photon mapping, instant radiosity, irradiance caching):
    /// those whose curve flattens at what they built.
    fn build_once(&self) -> bool {
        matches!(
            self.algorithm,
            Algorithm::Photon | Algorithm::Vpl | Algorithm::IrradianceCache
        )
    }
}

/// Runs `algorithm` with growing work until the next run would pass the
/// budget (the curve), then once at the work that fits the budget (the
/// picture), then `effort.seeds` times with independent seeds at
/// `budget / seed_share` (bias² and variance).
#[allow(clippy::too_many_arguments)]
fn measure(
    scene: &Scene,
    base: &RenderOptions,
    algorithm: Algorithm,
    knobs: &Knobs,
    max_depth: u32,
    reference: &Reference,
    counted: &[bool],
    effort: &Effort,
) -> Result<Measured> {
    let error = |image: &Image| masked_rmse(image, &reference.mean, counted);
    let prepared = algorithm
        .prepare(scene, knobs, max_depth, base.seed)
        .map_err(|e| anyhow!(e))?;
    let (run, curve) = equal_time(&prepared, scene, base, effort.budget, error);
    let work = prepared.fit(run.spp, run.seconds, effort.budget / effort.seed_share);
    let images: Vec<Image> = (0..effort.seeds)
        .map(|s| {
            let seed = base.seed.wrapping_add(1 + s).wrapping_mul(0x9e37_79b9);
            let p: Prepared = algorithm
                .prepare(scene, knobs, max_depth, seed)
                .map_err(|e| anyhow!(e))?;
            Ok(p.run(scene, base, work).image)
        })
        .collect::<Result<_>>()?;
    Ok(Measured {
        algorithm,
        rmse: error(&run.image),
        run,
        curve,
        split: split(&images, &reference.mean, &reference.variance, counted),
        build_seconds: prepared.build_seconds,
    })
}

/// Whether a curve has flattened: its last doubling of work (or more)
/// lowered the error by less than a fifth (an unbiased one falls by 29%).
pub fn flattens(curve: &[(f64, f64)]) -> bool {
    let Some(&(t1, e1)) = curve.last() else {
        return false;
    };
    curve
        .iter()
        .rev()
        .find(|&&(t, _)| t <= t1 / 2.0)
        .is_some_and(|&(_, e0)| e1 > 0.8 * e0)
}

/// The mean of each algorithm's runs minus the reference, in luminance and
/// on one colour scale (a round number above the 99th percentile of the
/// biased algorithms' |values|): the bias itself, with the noise of a mean.
fn bias_pictures(
    tour: &Tour,
    c: &mut ChapterOutput,
    name: &str,
    measured: &[Measured],
    reference: &Reference,
    seeds: u64,
) -> Result<()> {
    let values: Vec<Vec<f32>> = measured
        .iter()
        .map(|m| m.split.signed.pixels.iter().map(|&d| luminance(d)).collect())
        .collect();
    let mut biased: Vec<f32> = measured
        .iter()
        .zip(&values)
        .filter(|(m, _)| !m.algorithm.unbiased())
        .flat_map(|(_, v)| v.iter().map(|x| x.abs()))
        .collect();
    biased.sort_by(f32::total_cmp);
    let p99 = biased.get(biased.len() * 99 / 100).copied().unwrap_or(0.0);
    let scale = round_scale(p99 as f64);
    let size = (reference.mean.width, reference.mean.height);
    for (m, v) in measured.iter().zip(&values) {
        let noise = (m.split.variance / seeds as f64).sqrt();
        signed_figure_at(
            tour,
            c,
            &format!("{name}-{}-bias", m.algorithm.stem()),
            v,
            size,
            scale,
            &lang::pick(
                format!(
                    "{}: the mean of {seeds} runs with independent seeds minus {}, in luminance \
                     (red: too bright, blue: too dark): its bias, with the noise of a mean of \
                     {seeds} (standard deviation {noise:.3} per pixel and channel); bias² {}.",
                    m.algorithm.label(),
                    reference.name,
                    m.split.bias2_text()
                ),
                format!(
                    "{}: средното от {seeds} рендерирания с независими случайни числа минус {}, в \
                     яркост (червено: твърде светло, синьо: твърде тъмно): отместването му, с \
                     шума на средно от {seeds} (стандартно отклонение {noise:.3} на пиксел и \
                     канал); отместване² {}.",
                    m.algorithm.label(),
                    reference.name,
                    m.split.bias2_text()
                ),
            ),
        )?;
    }
    Ok(())
}

/// Writes `values` as a signed picture on a round scale of its own (above
/// its 99th percentile of |value|) and adds it to the chapter.
fn signed_figure(
    tour: &Tour,
    c: &mut ChapterOutput,
    stem: &str,
    values: &[f32],
    size: (u32, u32),
    caption: &str,
) -> Result<()> {
    let mut sorted: Vec<f32> = values.iter().map(|v| v.abs()).collect();
    sorted.sort_by(f32::total_cmp);
    let p99 = sorted.get(sorted.len() * 99 / 100).copied().unwrap_or(0.0);
    signed_figure_at(tour, c, stem, values, size, round_scale(p99 as f64), caption)
}

/// Writes `values` as `stem.svg`, a signed picture spanning [−scale, scale]
/// with its numbered colour bar, and adds it to the chapter.
fn signed_figure_at(
    tour: &Tour,
    c: &mut ChapterOutput,
    stem: &str,
    values: &[f32],
    (width, height): (u32, u32),
    scale: f64,
    caption: &str,
) -> Result<()> {
    let svg = c.dir.join(format!("{stem}.svg"));
    let text = signed_map_svg(values, width, height, scale)?;
    raytracer::film::output::write_file(&svg, text)
        .with_context(|| format!("cannot write {}", svg.display()))?;
    c.section
        .figures
        .push(Figure::plot(&tour.out, &svg, caption));
    Ok(())
}

/// Runs `prepared` with four times the work each time until the next run
/// would pass `budget` (the curve of (seconds, `error`)), then once at the
/// work that fits the budget: the equal-time run and the curve, in time
/// order. Steps of four, not two, keep the curve's cost near a third of the
/// budget on top of the equal-time run. A curve of one point gets a second,
/// past the budget.
fn equal_time(
    prepared: &Prepared,
    scene: &Scene,
    base: &RenderOptions,
    budget: f64,
    error: impl Fn(&Image) -> f64,
) -> (Run, Vec<(f64, f64)>) {
    let mut curve = Vec::new();
    let mut n = 1;
    let last = loop {
        let run = prepared.run(scene, base, n);
        curve.push((run.seconds, error(&run.image)));
        let next = prepared.build_seconds + 4.0 * (run.seconds - prepared.build_seconds);
        if next > budget || n >= 1 << 14 {
            break run;
        }
        n *= 4;
    };
    let fitted = prepared.fit(last.spp, last.seconds, budget);
    let run = if fitted > last.spp {
        let run = prepared.run(scene, base, fitted);
        curve.push((run.seconds, error(&run.image)));
        run
    } else {
        last
    };
    // A curve is at least two points: when one sample per pixel already
    // takes most of the budget, one run with twice the work goes past it.
    if curve.len() < 2 {
        let more = prepared.run(scene, base, 2 * run.spp);
        curve.push((more.seconds, error(&more.image)));
    }
    curve.sort_by(|a, b| a.0.total_cmp(&b.0));
    (run, curve)
}

/// Chapter 9's error against time in the current language, for the
/// algorithms `shown` (the others are left out: six curves and three floors
/// on one chart were too many to tell apart): each one's curve, and for each
/// build-once method whose bias² stands out of its noise a dashed line at
/// √bias² in its colour, the floor no amount of rendering removes. Every
/// chart spans the times of all the algorithms, a quarter more on each side
/// (a point on the frame is cut in half), so the two read on one time axis.
///
/// `noise_floor`, when given, is drawn too: the reference's own noise, the
/// floor of the unbiased curves as measured here.
fn rmse_time_chart(
    measured: &[Measured],
    shown: &[Algorithm],
    title: &str,
    noise_floor: Option<f64>,
) -> Chart {
    let times = measured.iter().flat_map(|m| m.curve.iter().map(|p| p.0));
    let (t0, t1) = times.fold((f64::MAX, 0.0f64), |(a, b), t| (a.min(t), b.max(t)));
    let (t0, t1) = (t0 / 1.25, t1 * 1.25);
    let shown: Vec<&Measured> = measured
        .iter()
        .filter(|m| shown.contains(&m.algorithm))
        .collect();
    let mut series: Vec<Series> = shown
        .iter()
        .map(|m| Series {
            label: m.algorithm.label().into(),
            points: m.curve.clone(),
        })
        .collect();
    for m in shown.iter().filter(|m| m.build_once() && m.split.resolved()) {
        series.push(Series {
            // "floor", not "√bias²": the longest label sets the legend's
            // columns, and "irradiance caching: √отместване²" took one a row.
            label: format!("{}: {}", m.algorithm.label(), lang::pick("floor", "дъно")),
            points: vec![(t0, m.split.bias2.sqrt()), (t1, m.split.bias2.sqrt())],
        });
    }
    if let Some(floor) = noise_floor {
        series.push(Series {
            label: lang::pick("reference noise floor", "дъното на шума на еталона").into(),
            points: vec![(t0, floor), (t1, floor)],
        });
    }
    Chart {
        title: title.into(),
        x_label: lang::pick("seconds (build included)", "секунди (със строежа)").into(),
        y_label: "RMSE".into(),
        x_scale: Scale::Log,
        y_scale: Scale::Log,
        series,
    }
}

/// The algorithms of the first error-against-time chart, the build-once
/// methods (with their floors, seven legend entries would shrink the chart);
/// the second has the unbiased ones and SPPM.
const BUILD_ONCE: [Algorithm; 3] = [Algorithm::Photon, Algorithm::Vpl, Algorithm::IrradianceCache];
const FALLING: [Algorithm; 3] = [Algorithm::Path, Algorithm::Bdpt, Algorithm::Sppm];

/// Bias² beside variance per algorithm, on a log axis, in the current
/// language; a bias² that does not stand out of its noise is an outline up
/// to its bound.
fn bias_variance_bars(measured: &[Measured], seeds: u64, seconds: f64) -> Bars {
    let each = seconds_text(seconds);
    Bars {
        title: lang::pick(
            format!("Cornell box: bias² and variance, {seeds} runs of {each}"),
            format!(
                "Cornell box: отместване² и дисперсия, {seeds} рендерирания по {}",
                each.replace('.', ",")
            ),
        ),
        y_label: "MSE".into(),
        parts: vec![
            lang::pick("bias²", "отместване²").into(),
            lang::pick("variance", "дисперсия").into(),
        ],
        bound_label: lang::pick("outline: at most (within noise)", "контур: най-много (в шума)").into(),
        bars: measured
            .iter()
            .map(|m| {
                let bias = Part {
                    value: if m.split.resolved() {
                        m.split.bias2
                    } else {
                        m.split.bound()
                    },
                    bound: !m.split.resolved(),
                };
                let variance = Part {
                    value: m.split.variance,
                    bound: false,
                };
                (m.algorithm.label().to_string(), vec![bias, variance])
            })
            .collect(),
    }
}

/// SPPM's bias² as the table gives it.
fn sppm_bias(measured: &[Measured]) -> String {
    measured
        .iter()
        .find(|m| m.algorithm == Algorithm::Sppm)
        .map_or_else(String::new, |m| m.split.bias2_text())
}

/// Which build-once methods flattened within `budget`, in the current
/// language.
fn flat_text(flat: &[&str], budget: f64) -> String {
    if flat.is_empty() {
        lang::pick(
            format!(
                "Within {} none has flattened yet: none has a last doubling of work that lowered \
                 its error by less than a fifth, so the render's noise still dominates.",
                seconds_text(budget)
            ),
            format!(
                "За {} още никой не е спрял да пада: при никой последното удвояване на работата не \
                 е намалило грешката с по-малко от една пета, така че шумът на рендерирането още \
                 преобладава.",
                seconds_text(budget)
            ),
        )
    } else {
        lang::pick(
            format!(
                "Within {}, {} flattened: a doubling of work lowered the error by less than a fifth.",
                seconds_text(budget),
                flat.join(", ")
            ),
            format!(
                "За {} спря да пада: {} (удвояването на работата намали грешката с по-малко от една \
                 пета).",
                seconds_text(budget),
                flat.join(", ")
            ),
        )
    }
}

/// The first time a curve reaches `target`, interpolated log–log between
/// its points (`None` if it never does).
fn first_time_below(curve: &[(f64, f64)], target: f64) -> Option<f64> {
    let i = curve.iter().position(|&(_, e)| e <= target)?;
    if i == 0 {
        return Some(curve[0].0);
    }
    let ((t0, e0), (t1, e1)) = (curve[i - 1], curve[i]);
    let f = (target.ln() - e0.ln()) / (e1.ln() - e0.ln());
    Some((t0.ln() + f * (t1.ln() - t0.ln())).exp())
}

fn luminance(c: Color) -> f32 {
    raytracer::math::luminance(c)
}

/// Photon mapping with many photons and a fixed search `radius` (little
/// noise, so that the blur shows), and its error against `reference`.
fn photon_blur(
    tour: &Tour,
    c: &mut ChapterOutput,
    (scene, base, max_depth): (&Scene, &RenderOptions, u32),
    reference: &Reference,
    photons: u64,
    radius: f32,
    what: &str,
) -> Result<()> {
    let start = std::time::Instant::now();
    let pm = PhotonMapping::build(
        scene,
        PhotonSettings {
            photons,
            radius: Some(radius),
            max_depth: Some(max_depth),
            rr_depth: scene.settings.rr_depth,
            seed: base.seed,
            ..PhotonSettings::default()
        },
        &AtomicBool::new(false),
    )
    .map_err(|e| anyhow!(e))?;
    let options = RenderOptions {
        spp: 8,
        progress: false,
        ..base.clone()
    };
    let image = raytracer::render::render(scene, &pm, &options).film.image();
    let seconds = start.elapsed().as_secs_f64();
    let name = &scene.name;
    let picture = write_image(
        &c.dir,
        &format!("{name}-photon-blur"),
        &image,
        options.spp,
        0.0,
        Some(seconds),
    )?;
    c.section.figures.push(Figure::new(
        &tour.out,
        &picture,
        &lang::pick(
            format!(
                "{name}, photon mapping with {photons} light paths and a fixed search radius of \
                 {radius}: little noise, so the blur shows."
            ),
            format!(
                "{name}, photon mapping с {photons} светлинни пътя и постоянен радиус на търсене \
                 {radius}: малко шум, затова размазването се вижда."
            ),
        ),
    ));
    let error: Vec<f32> = image
        .pixels
        .iter()
        .zip(&reference.mean.pixels)
        .map(|(&a, &b)| luminance(a - b))
        .collect();
    signed_figure(
        tour,
        c,
        &format!("{name}-photon-error"),
        &error,
        (image.width, image.height),
        &lang::pick(
            format!(
                "{name}, photon mapping − {} for the picture before, in luminance (red: too \
                 bright, blue: too dark): {what}.",
                reference.name
            ),
            format!(
                "{name}, photon mapping − {} за картината преди това, в яркост (червено: твърде \
                 светло, синьо: твърде тъмно): {what}.",
                reference.name
            ),
        ),
    )
}

/// Irradiance caching at three thresholds `a`: the records as red dots over
/// each picture, and the error growing with `a`.
fn irradiance_records(
    tour: &Tour,
    c: &mut ChapterOutput,
    (scene, base, max_depth): (&Scene, &RenderOptions, u32),
    knobs: &Knobs,
    reference: &Reference,
    counted: &[bool],
) -> Result<()> {
    let spp = 4;
    for a in [0.15f32, 0.3, 0.6] {
        let start = std::time::Instant::now();
        let cache = IrradianceCache::build(
            scene,
            IrradianceCacheSettings {
                error: a,
                rays: knobs.ic_rays,
                max_depth: Some(max_depth),
                rr_depth: scene.settings.rr_depth,
                seed: base.seed,
                gradients: false,
            },
            &AtomicBool::new(false),
        )
        .map_err(|e| anyhow!(e))?;
        let options = RenderOptions {
            spp,
            progress: false,
            ..base.clone()
        };
        let r = raytracer::render::render(scene, &cache, &options);
        let seconds = start.elapsed().as_secs_f64();
        let image = r.film.image();
        let error = masked_rmse(&image, &reference.mean, counted);
        let mut dots = image.clone();
        let first = cache.records().iter().map(|r| r.depth).min().unwrap_or(1);
        let lens = scene.camera.position();
        let mut shown = 0;
        for record in cache.records().iter().filter(|r| r.depth == first) {
            if let Some(Vec2 { x, y }) = scene.camera.raster_of(record.p, lens) {
                dots.set(x as u32, y as u32, Color::new(1.0, 0.05, 0.05));
                shown += 1;
            }
        }
        let stem = format!("{}-ic-a{a:.2}", scene.name);
        let picture = write_image(&c.dir, &stem, &image, spp, 0.0, Some(seconds))?;
        c.section.figures.push(Figure::new(
            &tour.out,
            &picture,
            &lang::pick(
                format!(
                    "Irradiance caching, a = {a}: {} records, RMSE {error:.4} against {} off the \
                     lamp; a larger a lets each record cover more, and its interpolation shows as \
                     blotches.",
                    cache.records().len(),
                    reference.name
                ),
                format!(
                    "Irradiance caching, a = {a}: {} записа, RMSE {error:.4} спрямо {} без \
                     лампата; по-голямо a дава на всеки запис по-голяма област, а интерполацията \
                     му личи като петна.",
                    cache.records().len(),
                    reference.name
                ),
            ),
        ));
        let picture = write_image(&c.dir, &format!("{stem}-records"), &dots, spp, 0.0, None)?;
        c.section.figures.push(Figure::new(
            &tour.out,
            &picture,
            &lang::pick(
                format!(
                    "Irradiance caching, a = {a}: the {shown} records seen from the camera as red \
                     dots, dense where the irradiance changes fast (corners, edges), sparse on open \
                     walls."
                ),
                format!(
                    "Irradiance caching, a = {a}: {shown}-те записа, видими от камерата, като \
                     червени точки, гъсти там, където облъчеността се мени бързо (ъгли, ръбове), \
                     редки по откритите стени."
                ),
            ),
        ));
    }
    Ok(())
}
