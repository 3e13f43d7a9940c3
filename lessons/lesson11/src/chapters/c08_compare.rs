//! Chapter 8 · The GI algorithms compared at equal time: each one's error
//! against a reference, its pictures and its convergence plot (the lecture's
//! unbiased algorithms differ only in how fast their noise falls).

use anyhow::Result;
use raytracer::film::Image;
use raytracer::integrator::Bdpt;
use raytracer::metrics::{mean, rmse};
use raytracer::render::{self as renderer, Metropolis, RenderOptions, render_metropolis};
use raytracer::scene::Scene;

use crate::equal_time::{Also, EqualTimeRow, equal_time};
use crate::page::{Figure, Section, Table};
use crate::plots::{Chart, Scale, Series};
use crate::render_files::{write_image, write_png_and_exr};
use crate::tour::{Chapter, ChapterOutput, Quality, Tour};

pub const CHAPTER: Chapter = Chapter::new(
    "compare",
    "8 · Every algorithm at equal time: RMSE against a reference, convergence plots",
    render,
);

/// Chapter 8: every algorithm at equal time against a high-sample reference.
fn render(tour: &Tour) -> Result<Section> {
    let max_depth = 5;
    let mut c = tour.chapter(
        "08-compare",
        "8 · Comparison at equal time",
        "Each algorithm gets the same time and the same maximum depth (5); the error is the RMSE against a \
         bidirectional reference with many samples. In the door scene the only light is in the next room: \
         path tracing must find it through the gap by chance, bidirectional tracing connects the two rooms \
         directly; Metropolis light transport, running Markov chains over bidirectional paths, keeps a path \
         that found the gap and explores its neighbours (its spp are mutations per pixel, its time includes \
         the bootstrap). On the Cornell box, naive recursion spends its rays on the N^D tree of one pixel sample, \
         path tracing on more samples per pixel.",
    )?;
    let budget = match tour.quality {
        Quality::Tiny => 0.05,
        Quality::Quick => 1.0,
        Quality::Full => 15.0,
    };
    let mut table = Table::new(
        "Equal-time comparison (RMSE against the reference; lower is better)",
        &["scene", "algorithm", "spp", "seconds", "RMSE"],
    );
    for name in ["door", "cornell"] {
        let (mut scene, mut base) = tour.scene(name, 128)?;
        if tour.quality != Quality::Tiny {
            let (w, h) = (scene.settings.width, scene.settings.height);
            scene.set_resolution(w.min(128), (h * w.min(128) / w).max(1));
        }
        base.progress = false;
        let reference_spp = base.spp;
        let comparison = equal_time(
            &scene,
            &base,
            budget,
            reference_spp,
            max_depth,
            Also {
                naive: name == "cornell",
                metropolis: name == "door",
            },
        );
        let rows = comparison.rows;
        if name == "door" {
            let reference = &comparison.reference;
            metropolis_noise(tour, &mut c, &scene, &base, max_depth, reference, &rows)?;
        }
        let chart = Chart {
            title: format!("{name}: error against time"),
            x_label: "seconds".into(),
            y_label: "RMSE".into(),
            x_scale: Scale::Log,
            y_scale: Scale::Log,
            series: rows
                .iter()
                .map(|r| Series {
                    label: r.algorithm.into(),
                    points: r.curve.clone(),
                })
                .collect(),
        };
        let svg = c.dir.join(format!("{name}-convergence.svg"));
        chart.write(&svg)?;
        c.section.figures.push(Figure::plot(
            &tour.out,
            &svg,
            &format!(
                "{name}: RMSE against render time, log–log (a slope of −1/2 is Monte Carlo's 1/√N)."
            ),
        ));
        for row in rows {
            let picture = write_image(&c.dir, &row.stem, &row.image, row.spp)?;
            let caption = format!("{name}, {}, RMSE {:.4}.", row.algorithm, row.rmse);
            c.section
                .figures
                .push(Figure::new(&tour.out, &picture, &caption));
            table.rows.push(vec![
                name.into(),
                row.algorithm.into(),
                row.spp.to_string(),
                format!("{:.2}", row.seconds),
                format!("{:.5}", row.rmse),
            ]);
        }
    }
    table.write_csv(&c.dir.join("equal-time.csv"))?;
    c.section.tables.push(table);
    Ok(c.section)
}

/// "Not all noise is white": Metropolis light transport at a few mutations
/// per pixel beside bidirectional tracing given the same time, both at +4
/// stops (the door room is dark), with each one's RMSE and, for Metropolis,
/// the RMSE its independent chains predict.
fn metropolis_noise(
    tour: &Tour,
    c: &mut ChapterOutput,
    scene: &Scene,
    base: &RenderOptions,
    max_depth: u32,
    reference: &Image,
    rows: &[EqualTimeRow],
) -> Result<()> {
    let bdpt = Bdpt {
        max_depth: Some(max_depth),
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
    let mlt = render_metropolis(scene, &bdpt, &options(mutations, base.seed), &metropolis);
    let seconds = mlt.stats.elapsed.as_secs_f64();
    // Bidirectional tracing at the same time, from the equal-time row's
    // seconds per sample, with another seed than the reference's.
    let per_spp = rows
        .iter()
        .find(|r| r.algorithm == "bidirectional")
        .map_or(seconds, |r| r.seconds / r.spp as f64);
    let spp = ((seconds / per_spp).round() as u32).max(1);
    let other = renderer::render(scene, &bdpt, &options(spp, base.seed + 1));
    // The chains' prediction: the variance of each pixel's mean over the
    // chains, plus the bootstrap's b̂ error that scales the whole image.
    let (image, variance) = (mlt.film.image(), mlt.film.variance_image());
    let rel = mlt.bootstrap.as_ref().map_or(0.0, |b| b.relative_error()) as f32;
    let b_part = image.pixels.iter().map(|p| (*p * rel).length_squared() / 3.0).sum::<f32>()
        / image.pixels.len() as f32;
    let predicted = (mean(&variance).element_sum() / 3.0 + b_part).sqrt();
    let pictures = [
        (
            "door-mlt-streaks-ev4",
            image.clone(),
            format!(
                "Door, Metropolis light transport over bidirectional paths, {mutations} mutations per pixel in {} \
                 chains ({seconds:.1} s), +4 stops: the errors come in streaks and blobs, each the trail of a chain \
                 that lingered on a bright path — not all noise is white. RMSE {:.4}; the spread of the independent \
                 chains predicts {predicted:.4}.",
                mlt.chains,
                rmse(&image, reference)
            ),
        ),
        (
            "door-bdpt-streaks-ev4",
            other.film.image(),
            format!(
                "Door, bidirectional path tracing in the same time ({spp} spp, {:.1} s), +4 stops: independent \
                 samples, white noise, pixel by pixel. RMSE {:.4}.",
                other.stats.elapsed.as_secs_f64(),
                rmse(&other.film.image(), reference)
            ),
        ),
    ];
    for (stem, image, caption) in pictures {
        let (png, exr) = write_png_and_exr(&image, &c.dir, stem, 4.0)?;
        println!("  wrote {}", png.display());
        c.section
            .figures
            .push(Figure::image(&tour.out, &png, &exr, caption));
    }
    Ok(())
}
