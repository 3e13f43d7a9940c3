//! Whole integrators against a reference, tile by tile: both are rendered at
//! a small size with fixed seeds, and each tile's mean is compared with a
//! z-test that uses both renders' own variances
//! ([`raytracer::metrics::z_test`]). On failure the two pictures and a map of
//! the tiles' |z| are written under `target/grading/`.

use raytracer::film::Image;
use raytracer::integrator::Integrator;
use raytracer::metrics::{z_test, z_threshold};
use raytracer::render::{RenderOptions, render};
use raytracer::scene::Scene;

use crate::stats::output_dir;

/// Family-wise false-failure probability of one image comparison.
pub const ALPHA: f64 = 1e-4;

/// Settings of a comparison.
pub struct Comparison<'a> {
    /// For file names, e.g. `ex09_cornell`.
    pub name: &'a str,
    pub scene: &'a str,
    pub size: u32,
    pub tile: u32,
    pub spp: u32,
}

fn options(spp: u32, seed: u64) -> RenderOptions {
    RenderOptions {
        spp,
        seed,
        threads: None,
        tile_size: 16,
        progress: false,
        label: String::new(),
    }
}

/// Renders `student` and `reference` and z-tests them tile by tile (threshold
/// for the family of all tiles and channels at level [`ALPHA`]).
pub fn compare(
    c: &Comparison,
    student: &dyn Integrator,
    reference: &dyn Integrator,
) -> Result<(), String> {
    compare_with_seeds(c, student, reference, (11, 12))
}

/// [`compare`] with the seeds of the two renders (the self-test checks the
/// false-failure rate over many seeds).
pub fn compare_with_seeds(
    c: &Comparison,
    student: &dyn Integrator,
    reference: &dyn Integrator,
    seeds: (u64, u64),
) -> Result<(), String> {
    let mut scene = Scene::builtin(c.scene).map_err(|e| format!("grader: {e}"))?;
    scene.set_resolution(c.size, c.size);
    let a = render(&scene, student, &options(c.spp, seeds.0));
    let b = render(&scene, reference, &options(c.spp, seeds.1));
    let (ai, av, bi, bv) = (
        a.film.image(),
        a.film.variance_image(),
        b.film.image(),
        b.film.variance_image(),
    );
    let z = z_test(&ai, &av, &bi, &bv, c.tile);
    let tests = z.z.len() * 3;
    let threshold = z_threshold(tests, ALPHA) as f32;
    if z.max_abs_z <= threshold && a.film.nonfinite_count() == 0 {
        return Ok(());
    }
    let dir = output_dir();
    let written = write_images(&dir, c, &ai, &bi, &z.z, z.grid.x, threshold);
    let mean = |img: &Image| raytracer::metrics::mean(img);
    let mut msg = if a.film.nonfinite_count() > 0 {
        format!(
            "{}: {} of your samples were NaN, infinite or negative",
            c.scene,
            a.film.nonfinite_count()
        )
    } else {
        format!(
            "{}: your picture differs from the reference in tile {} (|z| = {:.1} > {threshold:.1}); mean of your image {:.4}, of the reference {:.4}",
            c.scene,
            z.worst_tile,
            z.max_abs_z,
            mean(&ai).element_sum() / 3.0,
            mean(&bi).element_sum() / 3.0
        )
    };
    match written {
        Ok(()) => msg.push_str(&format!(
            "; see {}/{}_{{student,reference,z}}.png",
            dir.display(),
            c.name
        )),
        Err(e) => msg.push_str(&format!(" (could not write the images: {e})")),
    }
    Err(msg)
}

fn write_images(
    dir: &std::path::Path,
    c: &Comparison,
    student: &Image,
    reference: &Image,
    z: &[raytracer::math::Color],
    grid_x: u32,
    threshold: f32,
) -> std::io::Result<()> {
    std::fs::create_dir_all(dir)?;
    student.write_png(dir.join(format!("{}_student.png", c.name)), 0.0)?;
    reference.write_png(dir.join(format!("{}_reference.png", c.name)), 0.0)?;
    // The error image: each pixel shows its tile's |z| / threshold (1 = just failing).
    let zmap = Image::from_fn(student.width, student.height, |x, y| {
        let t = (y / c.tile * grid_x + x / c.tile) as usize;
        z[t].abs() / threshold
    });
    zmap.write_png(dir.join(format!("{}_z.png", c.name)), 0.0)
}
