//! Exercise 13 — multiple importance sampling: a path tracer that uses both strategies.
//!
//! Slides: "Multiple importance sampling" ("Multiple importance sampling"),
//! "Next event estimation" ("Next event estimation"), "Finding the light by
//! chance" ("Светлината, намерена случайно").
//!
//! At every vertex the direct light can be found two ways: by a light
//! sample (exercise 12) and by the BRDF sample that continues the path and
//! happens to hit an emitter (exercise 11). Exercise 12 kept only the first
//! (the second was counted only after a mirror); light sampling alone is
//! noisy where a large light meets a shiny surface, BRDF sampling alone where
//! a small light meets a rough one (Veach's plates, the slide). Here both
//! count, each weighted so that the two weights of one direction sum to
//! one: the power heuristic with exponent 2, as the slide writes it and the
//! renderer uses (the balance heuristic, exponent 1, is a valid weight too,
//! but it is not the one asked for, and the grader tells them apart).
//!
//! Task: `path_radiance_mis(scene, ray, max_depth, rr_depth, sampler)`:
//! your path tracer (exercises 11 and 12; copy your own loop) where at every
//! vertex x
//! - one light sample is added with its power-heuristic weight, and
//! - the emitter that the continuation ray hits (an area light, or the
//!   environment when it escapes) is added with its power-heuristic weight.
//!
//! Each weight compares the two densities with which the two strategies
//! would have produced the SAME direction ω_i at x, both per unit solid
//! angle at x, and each the density of the whole strategy: the light
//! strategy first chooses a light (with the probability `P(light)`), then a
//! direction towards it. Compute the weights yourself (a small helper
//! function of your own is welcome; not `raytracer::sampling`'s heuristics).
//! Where only one strategy could have made the sample it takes the whole
//! weight: the camera ray; a ray that left a delta lobe (mirror, glass: no
//! light sample finds light there, `Brdf::eval` and `Brdf::pdf` are zero);
//! a point light (`LightSample::is_delta`: no ray ever hits it).
//! Depth and Russian roulette as in exercise 12: with `max_depth` D a path
//! has at most D segments, a light sample adds one.
//!
//! Toolbox (besides exercise 11's):
//! - the light sample: `Scene::choose_light` (its `pmf`), then
//!   `Light::sample_li(x, u)`: the direction `wi`, the arriving radiance
//!   `li`, its density `pdf_w` per unit solid angle, the point `p` and
//!   normal `n` on the light for the shadow ray
//!   (`Interaction::spawn_ray_to(p, n)`, or `Interaction::spawn_ray(wi)` when
//!   `dist` is infinite: the environment), `Scene::unoccluded`;
//! - the BRDF's density of a direction it did not sample: `Brdf::pdf`
//!   (local frame);
//! - an emitter hit by a ray: `Scene::emitter_hit(&ray, hit)`, with the hit
//!   (`None` when the ray escaped): the light's index in `Scene::lights`, the
//!   radiance `le` it sends back, the point `p` and normal `n` where the ray
//!   met it;
//! - the light strategy's density of a direction that happened to hit the
//!   light: `Light::pdf_li_w(x, p, n, wi)` (per unit solid angle at x, for
//!   the same sampling `Light::sample_li` does), and `Scene::light_pmf`.
//!   Take the light sample from `Light::sample_li` too (not exercise 12's
//!   sampling by area): a weight must use the density of the sampling you
//!   actually do, and for a sphere seen from outside `Light::sample_li`
//!   samples the cone it subtends, not its area (Veach's lights are spheres).
//!
//! Receives: the scene, a camera ray, the depths, the sampler. Returns: the
//! path's radiance estimate. `exercises::plug::StudentPathTracer` renders it
//! with `StudentRender::PathMis` (`lesson11 render --student -i path`).

use raytracer::math::{Color, Ray};
use raytracer::sampling::Sampler;
use raytracer::scene::Scene;

/// The radiance estimate of one path starting with `ray`: light sampling and
/// BRDF sampling at every vertex, combined by the power heuristic.
pub fn path_radiance_mis(
    scene: &Scene,
    ray: Ray,
    max_depth: Option<u32>,
    rr_depth: u32,
    sampler: &mut Sampler,
) -> Color {
    // TODO: your loop of exercise 12, with both strategies counted at every vertex, each with its power-heuristic weight.
    todo!()
}
