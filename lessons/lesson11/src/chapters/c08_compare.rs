//! Chapter 8 · The GI algorithms compared at equal time: each one's error
//! against a reference, its pictures and its convergence plot (the lecture's
//! unbiased algorithms differ only in how fast their noise falls).

use anyhow::Result;

use crate::equal_time::equal_time;
use crate::page::{Figure, Section, Table};
use crate::plots::{Chart, Scale, Series};
use crate::render_files::write_image;
use crate::tour::{Chapter, Quality, Tour};

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
