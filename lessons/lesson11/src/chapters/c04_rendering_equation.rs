//! Chapter 4 · The rendering equation solved by naive recursive Monte Carlo:
//! N rays at every hit, so a pixel sample costs 1 + N + … + N^(D−1) rays
//! (counted and tabulated), against path tracing's one ray per bounce.

use anyhow::Result;
use raytracer::integrator::{DirectStrategy, NaiveRecursive, PathTracer};

use crate::page::{Section, Table};
use crate::tour::{Chapter, Quality, Tour};

pub const CHAPTER: Chapter = Chapter::new(
    "rendering-equation",
    "4 · The rendering equation: naive recursive Monte Carlo and its N^D rays per pixel",
    render,
);

/// Chapter 4: the rendering equation solved by naive recursion, and its cost.
fn render(tour: &Tour) -> Result<Section> {
    let mut s = tour.chapter(
        "04-rendering-equation",
        "4 · The rendering equation and its recursion",
        "Naive recursive Monte Carlo shoots N rays at every hit and recurses: a pixel sample costs \
         1 + N + N² + … rays, so the cost explodes with depth (the table counts the rays actually traced). \
         Path tracing follows one ray per bounce and spends the same budget on more samples per pixel.",
    )?;
    let (mut scene, mut options) = tour.scene("cornell", 1)?;
    if tour.quality != Quality::Tiny {
        scene.set_resolution(96, 96);
    }
    options.progress = false;
    let mut table = Table::new(
        "Naive recursion on the Cornell box, 1 sample per pixel",
        &[
            "N (branching)",
            "max depth D",
            "rays per pixel (measured)",
            "rays per pixel bound Σ N^d",
            "seconds",
        ],
    );
    let pixels = (scene.camera.width * scene.camera.height) as f64;
    for n in [2u32, 4, 8] {
        for d in [2u32, 3, 4] {
            let naive = NaiveRecursive::new(vec![n], Some(d));
            let result = raytracer::render::render(&scene, &naive, &options);
            table.rows.push(vec![
                n.to_string(),
                d.to_string(),
                format!("{:.1}", naive.rays_traced() as f64 / pixels),
                naive.rays_per_sample_bound().unwrap_or(0).to_string(),
                format!("{:.3}", result.stats.elapsed.as_secs_f64()),
            ]);
        }
    }
    for row in &table.rows {
        println!(
            "  naive N={} D={}: {} rays per pixel, {} s",
            row[0], row[1], row[2], row[4]
        );
    }
    table.write_csv(&s.dir.join("naive-rays.csv"))?;
    s.section.tables.push(table);
    let naive = NaiveRecursive::new(vec![8], Some(4));
    tour.picture(
        &mut s,
        &scene,
        &naive,
        &options,
        "naive-n8-d4",
        "Naive recursion, N = 8, D = 4, 1 spp.",
    )?;
    let pt = PathTracer {
        max_depth: Some(4),
        rr_depth: 5,
        strategy: DirectStrategy::BrdfOnly,
    };
    let mut equal = options.clone();
    equal.spp = if tour.quality == Quality::Tiny { 2 } else { 64 };
    tour.picture(
        &mut s,
        &scene,
        &pt,
        &equal,
        "path-d4",
        "Path tracing (BRDF sampling only, as naive recursion), D = 4.",
    )?;
    Ok(s.section)
}
