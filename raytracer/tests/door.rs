//! The door scene: a room lit only through a door ajar, where bidirectional
//! path tracing beats path tracing by far.
//!
//! Speed is not measured in tests, so "at equal time" becomes "at a generous
//! equal cost": bidirectional tracing gets one sample for every 8 of the path
//! tracer's (`lesson11 bench` measures it at 4–6 times the cost of a path
//! sample on this scene), and must still reach a far lower variance. Both
//! estimators are unbiased, so their mean squared error is their variance;
//! the film's per-pixel variance of the mean measures it without a reference.

use raytracer::integrator::{Bdpt, Integrator, PathTracer};
use raytracer::render::{RenderOptions, render};
use raytracer::scene::Scene;

/// Sum over pixels and channels of the variance of each pixel's mean.
fn total_variance(scene: &Scene, integrator: &dyn Integrator, spp: u32) -> f64 {
    let options = RenderOptions {
        spp,
        seed: 77,
        threads: None,
        progress: false,
        ..RenderOptions::default()
    };
    let v = render(scene, integrator, &options).film.variance_image();
    v.pixels.iter().map(|c| (c.x + c.y + c.z) as f64).sum()
}

/// Measured: BDPT's total variance is about 1/15 of the path tracer's at
/// 8 times fewer samples (seed 77); the assertion asks for 1/3, so the
/// sampling error of the variance estimates themselves (a few percent over
/// 3072 pixels) cannot make it fail. It fails if BDPT loses its light
/// subpaths (then it is a slower path tracer) or its MIS weights go wrong.
#[test]
fn bidirectional_tracing_beats_path_tracing_through_the_door() {
    let mut scene = Scene::builtin("door").unwrap();
    scene.set_resolution(64, 48);
    let max_depth = Some(6);
    let path = total_variance(
        &scene,
        &PathTracer {
            max_depth,
            ..PathTracer::default()
        },
        64,
    );
    let bdpt = total_variance(
        &scene,
        &Bdpt {
            max_depth,
            ..Bdpt::default()
        },
        8,
    );
    assert!(
        bdpt * 3.0 < path,
        "BDPT total variance {bdpt:.3e} at 8 spp vs path tracing {path:.3e} at 64 spp"
    );
}
