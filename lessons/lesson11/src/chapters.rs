//! The chapters after path tracing: light tracing, bidirectional path
//! tracing, and the comparison of all the algorithms at equal time.

use anyhow::Result;
use raytracer::integrator::{Bdpt, LightTracer, PathTracer, render_strategies};

use crate::equal_time::equal_time;
use crate::page::{Figure, Section, Table};
use crate::plots::{Chart, Scale, Series};
use crate::render_files::write_image;
use crate::tour::{Quality, Tour};

/// Chapter 6: light tracing, and the caustic only light paths can find.
pub fn light(tour: &Tour) -> Result<Section> {
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

/// Chapter 7: bidirectional path tracing and its strategies.
pub fn bdpt(tour: &Tour) -> Result<Section> {
    let mut c = tour.chapter(
        "07-bdpt",
        "7 · Bidirectional path tracing",
        "A camera subpath and a light subpath, joined in every possible way: s light vertices and t camera \
         vertices give the strategy (s, t). s = 0 is a camera path that hits a light, s = 1 next event \
         estimation, t = 1 light tracing. Multiple importance sampling (power heuristic) weights every \
         strategy where it is good. Below: each strategy's own estimate (unweighted) and its share after \
         MIS (weighted); the weighted images add up to the bidirectional image.",
    )?;
    let (scene, options) = tour.scene("cornell", 32)?;
    let bd = Bdpt::default();
    tour.picture(
        &mut c,
        &scene,
        &bd,
        &options,
        "cornell-bdpt",
        "Cornell box, bidirectional path tracing.",
    )?;
    let (mut scene, mut options) = tour.scene("cornell", 16)?;
    if tour.quality != Quality::Tiny {
        scene.set_resolution(96, 96);
    }
    options.progress = false;
    let max_depth = 3;
    for ((s, t), weighted, unweighted) in render_strategies(&scene, &options, max_depth) {
        for (image, kind) in [(&unweighted, "unweighted"), (&weighted, "weighted")] {
            let stem = format!("strategy-s{s}-t{t}-{kind}");
            let picture = write_image(&c.dir, &stem, image, options.spp)?;
            c.section.figures.push(Figure::new(
                &tour.out,
                &picture,
                &format!("s = {s}, t = {t}, {kind}."),
            ));
        }
    }
    println!(
        "  wrote the {} strategy images of max depth {max_depth}",
        c.section.figures.len() - 1
    );
    Ok(c.section)
}

/// Chapter 8: every algorithm at equal time against a high-sample reference.
pub fn compare(tour: &Tour) -> Result<Section> {
    let max_depth = 5;
    let mut c = tour.chapter(
        "08-compare",
        "8 · Comparison at equal time",
        "Each algorithm gets the same time and the same maximum depth (5); the error is the RMSE against a \
         bidirectional reference with many samples. In the door scene the only light is in the next room: \
         path tracing must find it through the gap by chance, bidirectional tracing connects the two rooms \
         directly. On the Cornell box, naive recursion spends its rays on the N^D tree of one pixel sample, \
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
        let rows = equal_time(
            &scene,
            &base,
            budget,
            reference_spp,
            max_depth,
            name == "cornell",
        );
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
