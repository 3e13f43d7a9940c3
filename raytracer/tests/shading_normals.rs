//! Path and bidirectional tracing on `stereo`, whose torus is a smooth mesh
//! (3072 flat triangles, interpolated normals): they must agree tile by
//! tile, on the torus and on the whole picture.
//!
//! What it catches: BDPT skipped its next-event strategy (`s = 1`, which
//! resamples its light point and needs no light subpath) whenever no light
//! path started, as when the sky was chosen for it: the sun of `stereo` lost
//! most of its direct light (|z| = 19.9 over the floor, 4.7 on the torus).
//! Each light alone agreed; only a scene with an environment and a lamp
//! showed it.
//!
//! Tolerance: z-scores of 8×8 tiles restricted to the pixels that see the
//! mesh (tiles with at least 16 of them), with both films' variances;
//! threshold for a family-wise false-failure probability of 1e-4 over all
//! z-scores of the test (≈ 5σ). Light-path splats of one path landing in
//! the same tile are correlated, which the film's per-pixel variances
//! ignore; measured max |z| stays far below the threshold.

use raytracer::film::{Film, Image};
use raytracer::integrator::{Bdpt, Integrator, PathTracer};
use raytracer::math::{Color, Vec2};
use raytracer::metrics::z_threshold;
use raytracer::render::{RenderOptions, render};
use raytracer::scene::Scene;

const TILE: u32 = 8;

fn film(scene: &Scene, integrator: &dyn Integrator, spp: u32, seed: u64) -> Film {
    let options = RenderOptions {
        spp,
        seed,
        threads: None,
        progress: false,
        ..RenderOptions::default()
    };
    render(scene, integrator, &options).film
}

/// Which pixels see the object `name` through their centre.
fn mask(scene: &Scene, name: &str) -> Vec<bool> {
    let object = scene.objects.iter().position(|o| o.name == name).unwrap() as u32;
    let (w, h) = (scene.camera.width, scene.camera.height);
    (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .map(|(x, y)| {
            let ray = scene
                .camera
                .generate_ray(Vec2::new(x as f32 + 0.5, y as f32 + 0.5), Vec2::ZERO);
            scene.intersect(&ray).is_some_and(|it| it.shape == object)
        })
        .collect()
}

/// z-scores of the masked pixels of each tile: (tile, z per channel).
fn masked_tiles(mask: &[bool], a: &Film, b: &Film) -> Vec<((u32, u32), Color)> {
    let (ia, va, ib, vb): (Image, Image, Image, Image) =
        (a.image(), a.variance_image(), b.image(), b.variance_image());
    let (w, h) = (ia.width, ia.height);
    let mut out = Vec::new();
    for ty in 0..h / TILE {
        for tx in 0..w / TILE {
            let (mut d, mut v, mut n) = (Color::ZERO, Color::ZERO, 0);
            for y in ty * TILE..(ty + 1) * TILE {
                for x in tx * TILE..(tx + 1) * TILE {
                    if mask[(y * w + x) as usize] {
                        d += ia.get(x, y) - ib.get(x, y);
                        v += va.get(x, y) + vb.get(x, y);
                        n += 1;
                    }
                }
            }
            if n >= 16 {
                out.push(((tx, ty), d / v.powf(0.5)));
            }
        }
    }
    out
}

/// The tile with the largest |z| (printed with `what`).
fn worst(what: &str, tiles: &[((u32, u32), Color)], threshold: f32) -> ((u32, u32), f32) {
    let (tile, z) = tiles
        .iter()
        .map(|(t, z)| (*t, z.abs().max_element()))
        .fold(((0, 0), 0.0f32), |a, b| if b.1 > a.1 { b } else { a });
    eprintln!(
        "{what}: {} tiles, max |z| = {z:.2} in tile {tile:?} (threshold {threshold:.2})",
        tiles.len()
    );
    (tile, z)
}

#[test]
fn path_and_bidirectional_tracing_agree_on_the_torus_of_stereo() {
    let mut scene = Scene::builtin("stereo").unwrap();
    scene.set_resolution(96, 72);
    let depth = Some(3);
    let pt = PathTracer {
        max_depth: depth,
        ..PathTracer::default()
    };
    let bdpt = Bdpt {
        max_depth: depth,
        ..Bdpt::default()
    };
    let (a, b) = (film(&scene, &pt, 128, 1), film(&scene, &bdpt, 64, 2));
    let on_torus = masked_tiles(&mask(&scene, "torus"), &a, &b);
    let everywhere = masked_tiles(&vec![true; 96 * 72], &a, &b);
    let threshold = z_threshold(3 * (on_torus.len() + everywhere.len()), 1e-4) as f32;
    for (what, tiles) in [
        ("on the torus", on_torus),
        ("in the whole picture", everywhere),
    ] {
        let (tile, z) = worst(
            &format!("bidirectional and path tracing {what}"),
            &tiles,
            threshold,
        );
        assert!(
            z < threshold,
            "bidirectional and path tracing disagree {what}, tile {tile:?}: |z| = {z:.1}"
        );
    }
}
