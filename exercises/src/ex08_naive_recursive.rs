//! Exercise 8 — naive recursive Monte Carlo with a branching factor.
//!
//! Slides: "Recursion" ("Рекурсивност": when does the recursion end?) and
//! "Solving by the Monte Carlo method" ("Решаване чрез Monte Carlo метод"):
//! at the hit point shoot many random rays, compute the light each brings,
//! multiply by the BRDF, average — and suffer the combinatorial explosion.
//!
//! Task: return the radiance arriving along `ray` (towards its origin),
//! `L_o(x, ω_o) ≈ L_e(x, ω_o) + (1/N) Σ_k f_r L_i(x, ω_k) |cos θ_k| / p(ω_k)`:
//! - no hit: the environment, `scene.escaped_radiance(ray.d)`;
//! - hit `it = scene.intersect(ray)`: start with `scene.emitted(&it)`;
//! - depth: the camera ray has `depth = 0`; if `depth + 1 >= max_depth`,
//!   stop there (so `max_depth = 1` shows only emitters seen directly);
//! - otherwise shoot `branching` directions from the BRDF
//!   (`scene.brdf(&it).sample(wo, it.uv, u_lobe, u, TransportMode::Radiance)`
//!   in the local frame: `wo = it.frame.to_local(it.wo)`, the world direction is
//!   `it.frame.to_world(bs.wi)`, the new ray `it.spawn_ray(..)`), recurse with
//!   `depth + 1`, weight each by `f · |cos θ_i| / pdf_w`, and divide the sum
//!   by `branching` (a refused sample, `None`, counts as zero).
//!
//! Receives: the scene, the ray, its depth, `max_depth`, `branching` (N), the
//! sampler (all random numbers come from it). Returns: the radiance estimate.
//! `exercises::plug::StudentNaive` renders a picture with it.

use raytracer::math::{Color, Ray};
use raytracer::sampling::Sampler;
use raytracer::scene::Scene;

/// The naive recursive estimate of the radiance along `ray`.
pub fn naive_radiance(
    scene: &Scene,
    ray: &Ray,
    depth: u32,
    max_depth: u32,
    branching: u32,
    sampler: &mut Sampler,
) -> Color {
    // TODO: intersect, add emission, recurse `branching` times.
    todo!()
}
