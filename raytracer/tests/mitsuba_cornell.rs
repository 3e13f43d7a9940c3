//! The built-in Cornell box against an independent renderer: Mitsuba 3.
//!
//! `data/cornell-mitsuba.exr` is Mitsuba 3.9.1's path tracer on its own
//! `cornell_box()` at 256×256 (max depth 65, Russian roulette from depth 5,
//! box filter, 2048 samples per pixel), and `data/cornell-mitsuba-variance.exr`
//! the variance of that mean, both made by `data/make_mitsuba_reference.py`.
//! Our path tracer, with the same settings and far fewer samples, must agree
//! with it tile by tile: any mismatch in the scene (a wall, a box's rotation,
//! the light's radiance or side), in the depth convention or in the estimator
//! shows up as a bias.

use std::path::Path;

use raytracer::film::Image;
use raytracer::integrator::PathTracer;
use raytracer::metrics::{mean, tile_variances, z_test, z_threshold};
use raytracer::render::{RenderOptions, render};
use raytracer::scene::Scene;

fn reference(name: &str) -> Image {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(name);
    Image::read_exr(&path)
        .unwrap_or_else(|e| panic!("cannot read the reference {}: {e}", path.display()))
}

/// 16×16-pixel tiles, three channels: 768 z-scores `(m_ours − m_ref)/√(v_ours + v_ref)`.
/// The threshold bounds the largest |z| of 768 standard normals with
/// probability 1 − 1e-4 (union bound), about 5.2, so a false failure has
/// probability below 1e-4. The whole-image means are compared too (5 standard
/// errors, false failure < 6e-7 per channel): their standard error at 32 spp
/// is about 0.08% of the mean, so a 1% error anywhere in the light transport
/// is a 13 σ discrepancy there, while the tiles catch local errors (a 1% change
/// of the whole image already shows as |z| ≈ 6 in the worst tile).
#[test]
fn cornell_box_matches_mitsuba_tile_by_tile() {
    let scene = Scene::builtin("cornell").unwrap();
    assert_eq!((scene.camera.width, scene.camera.height), (256, 256));
    let integrator = PathTracer {
        max_depth: Some(65),
        rr_depth: 5,
        ..PathTracer::default()
    };
    let options = RenderOptions {
        spp: 32,
        seed: 2024,
        threads: None,
        progress: false,
        ..RenderOptions::default()
    };
    let film = render(&scene, &integrator, &options).film;
    let (ours, ours_var) = (film.image(), film.variance_image());
    let (theirs, theirs_var) = (
        reference("cornell-mitsuba.exr"),
        reference("cornell-mitsuba-variance.exr"),
    );

    let z = z_test(&ours, &ours_var, &theirs, &theirs_var, 16);
    let threshold = z_threshold(z.z.len() * 3, 1e-4) as f32;
    assert!(
        z.max_abs_z < threshold,
        "tile {} differs from Mitsuba: |z| = {:.1} > {threshold:.1}",
        z.worst_tile,
        z.max_abs_z
    );

    // The whole image: means per channel within 5 standard errors.
    let (m_ours, m_theirs) = (mean(&ours), mean(&theirs));
    let whole = |img: &Image| tile_variances(img, 256)[0];
    let se = (whole(&ours_var) + whole(&theirs_var)).powf(0.5);
    for c in 0..3 {
        assert!(
            (m_ours[c] - m_theirs[c]).abs() < 5.0 * se[c],
            "channel {c}: mean {} vs Mitsuba {} (standard error {})",
            m_ours[c],
            m_theirs[c],
            se[c]
        );
    }
}
