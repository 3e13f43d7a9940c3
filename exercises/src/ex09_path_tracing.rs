//! Exercise 9 — the path tracing loop: throughput and Russian roulette.
//!
//! Slides: "Basic scheme of path tracing" ("Принципна схема на Path
//! Tracing") and "Path tracing": many paths per pixel; at each hit choose one
//! random continuation, use the BRDF to say by how much to multiply the light
//! that comes from it; intersect again, continue again.
//!
//! Task: follow one path from the camera ray `ray` and return its radiance
//! estimate. Keep the throughput `β` (starts at 1) and the sum `L` (starts at 0):
//! 1. intersect; no hit: `L += β · scene.escaped_radiance(ray.d)`, stop;
//! 2. hit: `L += β · scene.emitted(&it)` (lights are found only by hitting
//!    them: no light sampling in this exercise);
//! 3. depth: after `max_depth − 1` bounces stop (`max_depth = Some(1)`: only
//!    emitters seen directly; `None`: no limit — roulette ends the path);
//! 4. sample the BRDF (as in exercise 8); `None` ends the path; otherwise
//!    `β *= f · |cos θ_i| / pdf_w`, and the next ray leaves the hit point;
//! 5. Russian roulette once `rr_depth` bounces have been made: continue with
//!    probability `q = min(max channel of β, 0.95)`, and then divide β by q
//!    (this keeps the estimate unbiased).
//!
//! Receives: the scene, the camera ray, `max_depth`, `rr_depth`, the sampler.
//! Returns: the path's radiance estimate. `exercises::plug::StudentPathTracer`
//! renders with it (`lesson11 render --student`).

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
    // TODO: a loop, not a recursion: throughput, emission, BRDF sample, roulette.
    todo!()
}
