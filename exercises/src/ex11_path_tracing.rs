//! Exercise 11 — the path tracing loop: throughput and Russian roulette.
//!
//! Slides: "Path tracing in outline" ("Принципна схема на path tracing"),
//! "Russian roulette" ("Руска рулетка"), "Path tracing: samples per pixel"
//! ("Path tracing: проби на пиксел").
//!
//! Path tracing follows one random continuation at each hit instead of N:
//! the integral of the rendering equation is estimated with one sample per
//! bounce (the Monte Carlo estimate of the slide "Solving with Monte Carlo"
//! with N = 1), and the weights of all the bounces so far multiply into the
//! path's throughput β. Lights are
//! found only by hitting them: no light sampling here. Conventions as in
//! exercise 10: directions point away from the surface, `cos θ_i = ω_i·n`
//! with the normal on the side of `ω_o`, and D counts the segments of a path.
//!
//! Task: follow one path from the camera ray `ray` and return its radiance
//! estimate: the light emitted towards the camera at every vertex of the
//! path, each weighted by the path's throughput there, plus the
//! environment's radiance if the path escapes.
//! - `max_depth`: `Some(D)`, at most D segments as in exercise 10; `None`:
//!   no limit.
//! - Russian roulette once the path has made `rr_depth` bounces: continue
//!   with a survival probability q of your choice (from β, say) and end the
//!   path otherwise, keeping the estimate unbiased. Every path must end.
//!
//! Toolbox: as in exercise 10. Returns: the path's radiance estimate.
//! `exercises::plug::StudentPathTracer` renders with it
//! (`lesson11 render --student`).

use raytracer::math::{Color, Ray};
use raytracer::sampling::Sampler;
use raytracer::scene::Scene;

/// The radiance estimate of one path starting with `ray`.
pub fn path_radiance(
    scene: &Scene,
    ray: Ray,
    max_depth: Option<u32>,
    rr_depth: u32,
    sampler: &mut Sampler,
) -> Color {
    // TODO: a loop, not a recursion: throughput, emission, one BRDF sample, roulette.
    todo!()
}
