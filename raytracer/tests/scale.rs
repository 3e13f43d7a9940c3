//! The same scene in metres, millimetres or kilometres: the same picture.
//!
//! Radiance does not depend on the unit of length, so `cornell` scaled by
//! 0.001 and by 1000 about the origin (camera included) must render the same
//! image as `cornell` itself, within noise. Every length the renderer uses
//! to keep rays off surfaces must therefore scale with the scene: the ray
//! offsets (once an absolute 1.5e-5 near the origin: 1.5 % of the box at
//! scale 0.001, more than the 1 cm gap between lamp and ceiling, so rays
//! from the ceiling started below the lamp), the end of shadow rays (once
//! shortened by 1e-4 of their length) and the shell within which a receiver
//! counts as on a sphere light (once 1e-3 r²). Cosine thresholds are
//! dimensionless and need no care.
//!
//! Two comparisons, each with both films' variances and independent seeds
//! (honest z-scores), each at a family-wise false-failure probability of
//! 1e-4: the whole image tile by tile (8×8 tiles of 48×48, path tracing and
//! bidirectional tracing), and the rows around the lamp at full resolution
//! in segments of one row by 16 pixels (path tracing), where the lamp's
//! gap to the ceiling is.

use crate::common;

use raytracer::film::Film;
use raytracer::integrator::{Bdpt, Integrator, PathTracer};
use raytracer::math::{Color, UVec2, Vec3A};
use raytracer::metrics::{z_test, z_threshold};
use raytracer::render::{RenderOptions, render, render_pixels};
use raytracer::scene::Scene;

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

fn scaled(scale: f32) -> Scene {
    let mut scene = common::builtin_moved("cornell", scale, Vec3A::ZERO);
    scene.set_resolution(48, 48);
    scene
}

#[test]
fn cornell_in_millimetres_and_kilometres_looks_the_same() {
    let pt = PathTracer::default();
    let bdpt = Bdpt {
        max_depth: Some(6),
        ..Bdpt::default()
    };
    let threshold = z_threshold(2 * 36 * 3 * 2, 1e-4) as f32;
    for (name, integrator, spp) in [("path", &pt as &dyn Integrator, 128), ("bdpt", &bdpt, 16)] {
        let base = film(&scaled(1.0), integrator, spp, 1);
        for (k, scale) in [1e-3f32, 1e3].into_iter().enumerate() {
            let other = film(&scaled(scale), integrator, spp, 2 + k as u64);
            let z = z_test(
                &base.image(),
                &base.variance_image(),
                &other.image(),
                &other.variance_image(),
                8,
            );
            eprintln!(
                "{name} at scale {scale}: max |z| = {:.2} (threshold {threshold:.2})",
                z.max_abs_z
            );
            assert!(
                z.max_abs_z < threshold,
                "{name}: cornell scaled by {scale} differs in tile {:?}: |z| = {:.1}",
                z.worst_tile,
                z.max_abs_z
            );
        }
    }
}

/// The rows around the lamp (x ∈ [64, 192), y ∈ [24, 48) of 256×256, the
/// band of `mitsuba_cornell.rs`) rendered by the path tracer at 64 spp.
fn lamp_band(scene: &Scene, seed: u64) -> Film {
    let pt = PathTracer::default();
    let options = RenderOptions {
        spp: 64,
        seed,
        threads: None,
        progress: false,
        ..RenderOptions::default()
    };
    render_pixels(128, 24, &options, |pixel, sampler, splats| {
        pt.sample(scene, pixel + UVec2::new(64, 24), sampler, splats)
    })
    .film
}

/// The largest |z| over segments of one row by 16 pixels of two bands.
fn worst_segment(a: &Film, b: &Film) -> (f32, u32, u32) {
    let (ia, va, ib, vb) = (a.image(), a.variance_image(), b.image(), b.variance_image());
    let mut worst = (0.0f32, 0, 0);
    for y in 0..ia.height {
        for k in 0..ia.width / 16 {
            let (mut d, mut v) = (Color::ZERO, Color::ZERO);
            for x in 16 * k..16 * k + 16 {
                d += ia.get(x, y) - ib.get(x, y);
                v += va.get(x, y) + vb.get(x, y);
            }
            let z = (d / v.powf(0.5)).abs().max_element();
            if z > worst.0 {
                worst = (z, 64 + 16 * k, 24 + y);
            }
        }
    }
    worst
}

/// The lamp hangs 1 cm below the ceiling: 1e-5 in millimetres. The old
/// absolute ray offset near the origin (1.5e-5) started rays from the
/// ceiling below the lamp there: row 31 over the lamp differed by |z| = 27.7
/// at 128 spp (the whole 48×48 image only by 3.8: a 16×16-pixel tile of the
/// full image holds two rows of the gap).
#[test]
fn the_lamp_gap_survives_scaling() {
    let base = lamp_band(&common::builtin_moved("cornell", 1.0, Vec3A::ZERO), 3);
    let threshold = z_threshold(2 * 8 * 24 * 3, 1e-4) as f32;
    for (k, scale) in [1e-3f32, 1e3].into_iter().enumerate() {
        let other = lamp_band(
            &common::builtin_moved("cornell", scale, Vec3A::ZERO),
            4 + k as u64,
        );
        let (z, x, y) = worst_segment(&base, &other);
        eprintln!(
            "lamp band at scale {scale}: max |z| = {z:.2} at row {y}, x from {x} (threshold {threshold:.2})"
        );
        assert!(
            z < threshold,
            "cornell scaled by {scale}: row {y}, x from {x}: |z| = {z:.1}"
        );
    }
}

/// The same box moved 100 m and 1000 m from the origin: its coordinates
/// grow, the 1 cm lamp gap does not. A ray offset of 2⁻¹⁵ of the largest
/// coordinate (3 cm at 1000 m) started rays from the ceiling below the lamp
/// beyond about 330 m (the band's |z| was about 3 at 100 m and 20 at
/// 1000 m); offsets from the hit points' error bounds (a few ulps: about
/// 0.5 mm at 1000 m) keep the gap open. Same band, segments and threshold
/// as [`the_lamp_gap_survives_scaling`]. Cost: about 3 s.
#[test]
fn the_lamp_gap_survives_translation() {
    let base = lamp_band(&common::builtin_moved("cornell", 1.0, Vec3A::ZERO), 3);
    let threshold = z_threshold(2 * 8 * 24 * 3, 1e-4) as f32;
    for (k, offset) in [100.0f32, 1000.0].into_iter().enumerate() {
        let moved = Vec3A::new(offset, -offset, offset);
        let other = lamp_band(&common::builtin_moved("cornell", 1.0, moved), 6 + k as u64);
        let (z, x, y) = worst_segment(&base, &other);
        eprintln!(
            "lamp band moved by {moved}: max |z| = {z:.2} at row {y}, x from {x} (threshold {threshold:.2})"
        );
        assert!(
            z < threshold,
            "cornell moved by {moved}: row {y}, x from {x}: |z| = {z:.1}"
        );
    }
}
