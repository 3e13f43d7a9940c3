//! Chapter 8 · The GI algorithms compared at equal time: each one's error
//! against an independent reference, its pictures and its convergence plot
//! (the lecture's unbiased algorithms differ only in how fast their noise
//! falls).

use anyhow::Result;
use raytracer::integrator::Bdpt;
use raytracer::metrics::mean;
use raytracer::render::{self as renderer, Metropolis, RenderOptions, render_metropolis};
use raytracer::scene::Scene;

use crate::equal_time::{
    Also, EqualTimeRow, NAIVE_N, QUICK_SECONDS, equal_time, masked_noise_floor, masked_rmse, off_the_light,
};
use crate::page::{Figure, Section, Table, seconds_number, seconds_text};
use crate::plots::{Chart, LANGS, Scale, Series};
use crate::reference::{Reference, independent};
use crate::render_files::write_image;
use crate::tour::{Chapter, ChapterOutput, Quality, Tour};

pub const CHAPTER: Chapter = Chapter::new(
    "compare",
    "8 · Every algorithm at equal time: RMSE against a reference rendered with other random numbers, convergence plots",
    render,
);

/// Exposure of the door pictures in stops: the room is lit only through the
/// gap, its mean radiance is about 0.0015, and +6 stops (×64) brings it to
/// about 0.1, readable; at exposure 0 it is black.
const DOOR_EXPOSURE: f32 = 6.0;

/// Chapter 8: every algorithm at equal time against an independent reference.
fn render(tour: &Tour) -> Result<Section> {
    let budget = match tour.quality {
        Quality::Tiny => 0.05,
        Quality::Quick => QUICK_SECONDS,
        Quality::Full => 15.0,
    };
    let mut c = tour.chapter(
        "08-compare",
        lang::pick("8 · Comparison at equal time", "8 · Сравнение при равно време"),
        &lang::pick(
            format!(
                "Each algorithm gets the same time (about {budget} s here) and the same maximum depth, \
                 and its error is the RMSE against an independent reference, never a render that shares \
                 its samples, over the pixels off the lights (as in chapter 9: at the lamp's edge the \
                 error is anti-aliasing noise, the same for all). For the Cornell box the reference is Mitsuba 3's image (2048 spp, max \
                 depth 65, roulette from depth 5), reduced exactly to this size by averaging blocks of \
                 its pixels, so every algorithm here also runs to max depth 65. For the door scene it is \
                 our bidirectional path tracer with a seed of its own and thousands of samples, stored \
                 with the lesson (max depth 5). A reference is an estimate too: its noise floor, \
                 √(mean variance of the reference), is printed with the table and drawn in the plots, \
                 and no RMSE measured against it can fall below it (at these times every curve is far \
                 above it). In the door scene the only lamp is \
                 in the next room: a path tracer must find the gap by chance, light paths pass through \
                 it on their own, and bidirectional path tracing joins the two rooms directly; Metropolis \
                 light transport, Markov chains over bidirectional paths, keeps a path that found the gap \
                 and explores its neighbours (its spp are mutations per pixel, its time includes the \
                 bootstrap that estimates the brightness b). On the \
                 Cornell box naive recursion (N = {NAIVE_N} rays at every hit, the full tree to depth 5 \
                 — at most 341 rays per pixel sample — and below it one ray per hit, ended by Russian \
                 roulette) spends its time on \
                 the trees of a few pixel samples, path tracing on many samples per pixel. Unbiased \
                 algorithms differ only in their noise: at equal time, the lowest error wins."
            ),
            format!(
                "Всеки алгоритъм получава едно и също време (тук около {budget} s) и една и съща \
                 максимална дълбочина, а грешката му е RMSE спрямо независим еталон, никога спрямо \
                 рендериране, което споделя пробите му, по пикселите без лампите (както в глава 9: \
                 по ръба на лампата грешката е шумът от изглаждането, еднакъв за всички). За Cornell box еталонът е картината на \
                 Mitsuba 3 (2048 spp, максимална дълбочина 65, руска рулетка от дълбочина 5), \
                 намалена точно до този размер чрез осредняване на блокове пиксели, затова всеки \
                 алгоритъм тук също стига до дълбочина 65. За сцената с вратата това е нашият \
                 bidirectional path tracer с отделни случайни числа и хиляди проби, запазен с урока \
                 (максимална дълбочина 5). И еталонът е оценка: дъното на шума му, √(средната \
                 дисперсия на еталона), е отпечатано с таблицата и начертано в графиките, и никоя \
                 RMSE, измерена спрямо него, не пада под него (при тези времена всички криви са \
                 далеч над него). В сцената с вратата единствената \
                 лампа е в съседната стая: path tracer трябва да намери процепа случайно, \
                 светлинните пътища минават през него сами, а bidirectional path tracing свързва \
                 двете стаи направо; Metropolis light transport, вериги на Марков върху пътищата \
                 на bidirectional path tracing, пази път, намерил процепа, и изследва съседите му \
                 (spp при него \
                 са мутации на пиксел, а времето включва bootstrap, който оценява яркостта b). В \
                 Cornell box наивната рекурсия (N = {NAIVE_N} лъча във всяка точка, цялото дърво \
                 до дълбочина 5 – най-много 341 лъча на проба на пиксел – и под него по един \
                 лъч, спиран от руска рулетка) харчи времето си за дърветата на няколко проби, а \
                 path tracing – за много проби на пиксел. Неотместените алгоритми се различават \
                 само по шума си: при равно време печели най-малката грешка."
            ),
        ),
    )?;
    let mut table = Table::in_both(
        "Equal-time comparison (RMSE against a reference rendered with other random numbers, off the lights; lower is better)",
        &[
            ("scene", "сцена"),
            ("algorithm", "алгоритъм"),
            ("max depth D", "максимална дълбочина D"),
            ("spp", "spp"),
            ("seconds", "секунди"),
            ("RMSE", "RMSE"),
            ("reference", "еталон"),
            ("reference noise floor", "дъно на шума на еталона"),
        ],
    );
    let mut floors = Vec::new();
    for asked in ["door", "cornell"] {
        let (mut scene, mut base) = tour.scene(asked, 128)?;
        // `--scene` replaces the Cornell box: the files, charts and lines
        // are named after the scene rendered (they said "cornell").
        let name = if asked == "cornell" {
            scene.name.clone()
        } else {
            asked.to_string()
        };
        let name = name.as_str();
        if tour.quality != Quality::Tiny {
            let (w, h) = (scene.settings.width, scene.settings.height);
            scene.set_resolution(w.min(128), (h * w.min(128) / w).max(1));
        }
        base.progress = false;
        // `--scene` replaces the Cornell box: then Mitsuba's image is no reference.
        let builtin = (asked != "cornell" || tour.overrides.scene.is_none()).then_some(asked);
        let (reference, max_depth) = independent(builtin, &scene, &base, 5, base.spp);
        // Errors off the lights, as in chapter 9; the floor over the same pixels.
        let counted = off_the_light(&reference.mean);
        let floor = masked_noise_floor(&reference, &counted);
        crate::console::say!(
            "  {}",
            lang::fill(
                lang::pick(
                    "{name}: max depth {max_depth}, reference {source} (noise floor {floor:.5})",
                    "{name}: максимална дълбочина {max_depth}, еталон {source} (дъно на шума \
                     {floor:.5})",
                ),
                &[
                    ("name", &name),
                    ("max_depth", &max_depth),
                    ("source", &reference.source_here()),
                    ("floor", &floor),
                ]
            )
        );
        floors.push(format!("{name} {floor:.5} ({})", reference.source_here()));
        if name == "door" {
            // What the door renders converge to, at the same exposure (the
            // Cornell box's reference is shown in chapter 2).
            let picture = write_image(
                &c.dir,
                &format!("door-reference-ev{DOOR_EXPOSURE}"),
                &reference.mean,
                reference.spp,
                DOOR_EXPOSURE,
                None,
            )?;
            c.section.figures.push(Figure::new(
                &tour.out,
                &picture,
                &lang::pick(
                    format!(
                        "door, the reference: {}, max depth {max_depth}, exposure +{DOOR_EXPOSURE} \
                         EV; what every render below converges to.",
                        reference.source
                    ),
                    format!(
                        "вратата, еталонът: {}, максимална дълбочина {max_depth}, експозиция \
                         +{DOOR_EXPOSURE} EV; към това се приближава всяко рендериране по-долу.",
                        reference.source_here()
                    ),
                ),
            ));
        }
        let also = Also {
            naive: asked == "cornell",
            metropolis: name == "door",
        };
        let rows = equal_time(&scene, &base, budget, &reference, max_depth, also);
        if name == "door" {
            metropolis_noise(tour, &mut c, &scene, &base, max_depth, (&reference, &counted), &rows)?;
        }
        let times = rows.iter().flat_map(|r| r.curve.iter().map(|p| p.0));
        let (t0, t1) = times.fold((f64::MAX, 0.0f64), |(a, b), t| (a.min(t), b.max(t)));
        // The chart in each language of the decks (the page shows English).
        for lang in LANGS {
            let bg = lang == "bg";
            let word = |en: &str| {
                let en = short(en);
                if bg { in_bulgarian(en) } else { en.to_string() }
            };
            let mut series: Vec<Series> = rows
                .iter()
                .map(|r| Series {
                    label: word(r.algorithm),
                    points: r.curve.clone(),
                })
                .collect();
            // The floor spans a quarter more time on each side than the
            // curves: the axis then ends past the first and last points
            // (a point on the frame is cut in half).
            series.push(Series {
                label: word("reference noise floor"),
                points: vec![(t0 / 1.25, floor), (t1 * 1.25, floor)],
            });
            let chart = Chart {
                title: format!("{}: {}", word(name), word("error against time")),
                x_label: word("seconds"),
                y_label: "RMSE".into(),
                x_scale: Scale::Log,
                y_scale: Scale::Log,
                series,
            };
            chart.write(&c.dir.join(format!("{name}-convergence-{lang}.svg")))?;
        }
        let svg = c.dir.join(format!("{name}-convergence-{}.svg", lang::current().code()));
        c.section.figures.push(Figure::plot(
            &tour.out,
            &svg,
            &lang::pick(
                format!(
                    "{name}: RMSE against render time, log–log (a slope of −1/2 is Monte Carlo's \
                     1/√N), {}×{}, {budget} s per algorithm, max depth {max_depth}, RMSE off the \
                     lights (the table gives each one's spp); the dashed line is the reference's \
                     own noise floor, {floor:.5}.",
                    scene.camera.width, scene.camera.height
                ),
                format!(
                    "{}: RMSE спрямо времето, в логаритмичен мащаб (наклон −1/2 е 1/√N на Monte Carlo), \
                     {}×{}, по {budget} s на алгоритъм, максимална дълбочина {max_depth}, RMSE без \
                     лампите (таблицата дава spp на всеки); прекъснатата линия е дъното на \
                     шума на самия еталон, {floor:.5}.",
                    in_bulgarian(name),
                    scene.camera.width,
                    scene.camera.height
                ),
            ),
        ));
        let exposure = if name == "door" { DOOR_EXPOSURE } else { 0.0 };
        for row in rows {
            let stem = if exposure == 0.0 {
                row.stem.clone()
            } else {
                format!("{}-ev{exposure}", row.stem)
            };
            let picture = write_image(
                &c.dir,
                &stem,
                &row.image,
                row.spp,
                exposure,
                Some(row.seconds),
            )?;
            let (w, h) = (scene.camera.width, scene.camera.height);
            let caption = lang::pick(
                format!(
                    "{name}, {}, equal time: {} spp in {} ({w}×{h}, max depth {max_depth}): RMSE \
                     {:.5} against {} off the lights (noise floor {floor:.5}).",
                    row.algorithm,
                    row.spp,
                    seconds_text(row.seconds),
                    row.rmse,
                    reference.name
                ),
                format!(
                    "{}, {}, при равно време: {} spp за {} ({w}×{h}, максимална дълбочина \
                     {max_depth}): RMSE {:.5} спрямо {} без лампите (дъно на шума {floor:.5}).",
                    in_bulgarian(name),
                    crate::equal_time::label_in_bulgarian(row.algorithm),
                    row.spp,
                    seconds_text(row.seconds),
                    row.rmse,
                    reference.name
                ),
            );
            c.section
                .figures
                .push(Figure::new(&tour.out, &picture, &caption));
            table.push(|l| {
                vec![
                    name.into(),
                    l.pick(row.algorithm, crate::equal_time::label_in_bulgarian(row.algorithm))
                        .into(),
                    max_depth.to_string(),
                    row.spp.to_string(),
                    seconds_number(row.seconds),
                    format!("{:.5}", row.rmse),
                    lang::with(l, || reference.source_here()),
                    format!("{floor:.5}"),
                ]
            });
        }
    }
    table.caption = lang::pick(
        format!(
            "{}. The references' noise floors, √(mean variance of the reference): {}.",
            table.caption.trim_end_matches('.'),
            floors.join("; ")
        ),
        format!(
            "Сравнение при равно време (RMSE спрямо еталон, рендериран с други случайни числа, \
             без лампите; по-малкото е по-добре). Дъната на шума на еталоните, √(средната дисперсия на \
             еталона): {}.",
            floors.join("; ")
        ),
    );
    table.write_csv(&c.dir.join("equal-time.csv"))?;
    c.section.tables.push(table);
    Ok(c.section)
}

/// "Not all noise is white": Metropolis light transport at a few mutations
/// per pixel beside bidirectional path tracing given the same time, both at
/// the door's exposure, with each one's RMSE and, for Metropolis, the RMSE
/// its independent chains predict.
fn metropolis_noise(
    tour: &Tour,
    c: &mut ChapterOutput,
    scene: &Scene,
    base: &RenderOptions,
    max_depth: u32,
    (reference, counted): (&Reference, &[bool]),
    rows: &[EqualTimeRow],
) -> Result<()> {
    let rmse = |image: &raytracer::film::Image, truth: &raytracer::film::Image| {
        masked_rmse(image, truth, counted)
    };
    let bdpt = Bdpt {
        max_depth: Some(max_depth),
        rr_depth: scene.settings.rr_depth,
        ..Bdpt::default()
    };
    let mutations = if tour.quality == Quality::Tiny { 1 } else { 4 };
    let options = |spp, seed| RenderOptions {
        spp,
        seed,
        progress: false,
        ..base.clone()
    };
    let metropolis = Metropolis::default();
    // Seeds of their own: the equal-time row may have taken the same number
    // of mutations, and its picture is on the page already.
    let mlt = render_metropolis(scene, &bdpt, &options(mutations, base.seed + 1), &metropolis);
    let seconds = mlt.stats.elapsed.as_secs_f64();
    // Bidirectional tracing at the same time, from the equal-time row's
    // seconds per sample.
    let per_spp = rows
        .iter()
        .find(|r| r.algorithm == "bidirectional")
        .map_or(seconds, |r| r.seconds / r.spp as f64);
    let spp = ((seconds / per_spp).round() as u32).max(1);
    let other = renderer::render(scene, &bdpt, &options(spp, base.seed + 2));
    // The chains' prediction: the variance of each pixel's mean over the
    // chains, plus the bootstrap's b̂ error that scales the whole image.
    let (image, variance) = (mlt.film.image(), mlt.film.variance_image());
    let rel = mlt.bootstrap.as_ref().map_or(0.0, |b| b.relative_error()) as f32;
    let b_part = image
        .pixels
        .iter()
        .map(|p| (*p * rel).length_squared() / 3.0)
        .sum::<f32>()
        / image.pixels.len() as f32;
    let predicted = (mean(&variance).element_sum() / 3.0 + b_part).sqrt();
    let truth = &reference.mean;
    let pictures = [
        (
            format!("door-mlt-streaks-ev{DOOR_EXPOSURE}"),
            image.clone(),
            mutations,
            seconds,
            lang::pick(
                format!(
                    "door, Metropolis light transport over bidirectional paths, {mutations} \
                     mutations per pixel in {} chains ({}), max depth {max_depth}: the errors come \
                     in streaks and blobs, each the trail of a chain that lingered on a bright path \
                     — not all noise is white. RMSE {:.5} against {}; the spread of the independent \
                     chains predicts {predicted:.5}.",
                    mlt.chains,
                    seconds_text(seconds),
                    rmse(&image, truth),
                    reference.name
                ),
                format!(
                    "вратата, Metropolis light transport върху пътищата на bidirectional path tracing, {mutations} \
                     мутации на пиксел в {} вериги ({}), максимална дълбочина {max_depth}: \
                     грешките идват на ивици и петна, всяко – следа от верига, задържала се на ярък \
                     път: не всеки шум е бял. RMSE {:.5} спрямо {}; разсейването на независимите \
                     вериги предсказва {predicted:.5}.",
                    mlt.chains,
                    seconds_text(seconds),
                    rmse(&image, truth),
                    reference.name
                ),
            ),
        ),
        (
            format!("door-bdpt-streaks-ev{DOOR_EXPOSURE}"),
            other.film.image(),
            spp,
            other.stats.elapsed.as_secs_f64(),
            lang::pick(
                format!(
                    "door, bidirectional path tracing in the same time ({spp} spp, {}), max depth \
                     {max_depth}: independent samples, white noise, pixel by pixel. RMSE {:.5} \
                     against {}.",
                    seconds_text(other.stats.elapsed.as_secs_f64()),
                    rmse(&other.film.image(), truth),
                    reference.name
                ),
                format!(
                    "вратата, bidirectional path tracing за същото време ({spp} spp, {}), \
                     максимална дълбочина {max_depth}: независими проби, бял шум, пиксел по \
                     пиксел. RMSE {:.5} спрямо {}.",
                    seconds_text(other.stats.elapsed.as_secs_f64()),
                    rmse(&other.film.image(), truth),
                    reference.name
                ),
            ),
        ),
    ];
    for (stem, image, spp, seconds, caption) in pictures {
        let picture = write_image(&c.dir, &stem, &image, spp, DOOR_EXPOSURE, Some(seconds))?;
        c.section
            .figures
            .push(Figure::new(&tour.out, &picture, &caption));
    }
    Ok(())
}

/// An algorithm's name in a chart's legend: short enough for three to a row.
fn short(algorithm: &str) -> &str {
    match algorithm {
        "naive recursion, N = 4 then 1" => "naive recursion",
        "door" => "door scene",
        "cornell" => "Cornell box",
        "path (MIS)" => "path tracing (MIS)",
        "path (BRDF only)" => "path tracing (BRDF only)",
        "light" => "light tracing",
        "Metropolis (over bidirectional)" => "Metropolis",
        "reference noise floor" => "noise floor",
        other => other,
    }
}

/// The Bulgarian of a word on the convergence charts (the algorithms keep
/// the lecture's English names, as on the slides).
fn in_bulgarian(en: &str) -> String {
    match en {
        "door" | "door scene" => "сцената с вратата",
        "cornell" => "Cornell box",
        "error against time" => "грешка спрямо времето",
        "seconds" => "секунди",
        "noise floor" => "дъното на шума",
        "path tracing (BRDF only)" => "path tracing (само BRDF)",
        other => crate::equal_time::label_in_bulgarian(other),
    }
    .to_string()
}
