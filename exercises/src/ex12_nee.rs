//! Exercise 12 — next event estimation: a path tracer that aims at the lights.
//!
//! Slides: "Directions at a point" ("Посоките в една точка"), "Next event
//! estimation" ("Next event estimation"), "Finding the light by chance"
//! ("Светлината, намерена случайно"), "The rendering equation: the
//! integral" ("Транспортното уравнение: интегралът"), "Path tracing in
//! outline" ("Принципна схема на path tracing").
//!
//! Instead of waiting for a path to hit a light, aim at it: choose a point
//! y on a light and connect x to it with a shadow ray. The point is drawn
//! with a density per unit *area* of the light, `p_A(y)`; the rendering
//! equation integrates over *directions* at x, so the estimate needs the
//! density per unit solid angle.
//!
//! Part 1: `area_pdf_to_solid_angle(pdf_area, x, y, n_y)`: the density per
//! unit solid angle at x of the direction towards y (normal `n_y`), when y
//! is drawn with density `pdf_area` per unit area; `x ≠ y`. If the light is
//! seen exactly edge-on from x (`n_y ⟂ y − x`) no solid angle corresponds
//! to the area: return 0 (the caller drops a sample of density 0; its
//! `L_e cos θ_y` would be 0 anyway).
//!
//! Part 2: `estimate_direct(scene, it, sampler)`: a one-sample estimate of
//! the direct light reflected at the hit `it` towards `it.wo`, the part of
//! `∫ f_r L_i cos θ_i dω_i` that comes straight from the lights (directions
//! as in exercise 10: `ω_i` from x towards y, `cos θ_i = ω_i·n` with the
//! normal on the side of `ω_o`):
//! - choose a light with `Scene::choose_light` (one random number); it
//!   returns a `LightChoice`: the light and the probability of having chosen
//!   it (`choice.light`, `choice.pmf`);
//! - for a `Light::Area` take a point uniform by area, `AreaShape::sample_area`
//!   (density `1 / AreaShape::area`); the radiance leaving y towards x is
//!   `AreaLight::le` (zero behind a one-sided light);
//! - other lights (point, environment): `Light::sample_li` gives the
//!   direction, the arriving radiance and its density per solid angle;
//! - the BRDF: `Brdf::eval` in the local frame; visibility:
//!   `Scene::unoccluded` with the shadow ray `Interaction::spawn_ray_to`
//!   (towards the environment: `Interaction::spawn_ray`).
//!
//!
//! Part 3: `path_radiance_nee(scene, ray, max_depth, rr_depth, sampler)`:
//! your path tracer of exercise 11 (copy your own loop) with next event
//! estimation. At every vertex the path reaches, before it continues, add
//! one light sample (part 2), weighted by the throughput β there. Now the
//! direct light of a vertex is found by the light sample — so the emission
//! that the *next* ray happens to hit must not be counted again: the path
//! counts `L_e` (and the environment when it escapes) only where no light
//! sample could have found it — the camera ray, and a ray that left a
//! delta (mirror, glass) lobe, at whose vertex `Brdf::eval` is zero so the
//! light sample found nothing (`BrdfSample::is_delta`; `Brdf::is_delta`
//! says it of the whole model). Depth as in exercise 11: with `max_depth`
//! D a path has at most D segments, and a light sample at a vertex is one
//! more segment (D = 2: emitters seen directly plus the light sample at the
//! first hit, the direct light of part 2). Russian roulette as in exercise
//! 11. `exercises::plug::StudentPathTracer` renders it with
//! `StudentRender::PathNee` (`lesson11 render --student -i path-nee`).
//!
//! Receives: densities and points / the scene, a hit, the sampler / the
//! scene, a camera ray, the depths, the sampler.
//! Returns: the solid-angle density / the direct light estimate / the
//! path's radiance estimate.

use raytracer::math::{Color, Ray, Vec3A};
use raytracer::sampling::Sampler;
use raytracer::scene::{Interaction, Scene};

/// The density per unit solid angle at `x` of the direction towards `y`.
pub fn area_pdf_to_solid_angle(pdf_area: f32, x: Vec3A, y: Vec3A, n_y: Vec3A) -> f32 {
    // TODO: how large a solid angle does a small patch dA at y cover, seen from x?
    todo!()
}

/// One next-event estimate of the direct light at `it`.
pub fn estimate_direct(scene: &Scene, it: &Interaction, sampler: &mut Sampler) -> Color {
    // TODO: choose a light, a point on it, convert the density, test visibility.
    todo!()
}

/// The radiance estimate of one path starting with `ray`, with next event
/// estimation at every vertex.
pub fn path_radiance_nee(
    scene: &Scene,
    ray: Ray,
    max_depth: Option<u32>,
    rr_depth: u32,
    sampler: &mut Sampler,
) -> Color {
    // TODO: your loop of exercise 11, a light sample at each vertex, and emission counted only where no light sample could have found it.
    todo!()
}
