//! Exercise 10 — next event estimation on an area light.
//!
//! Slides: "The Rendering Equation" (`L_i` may come straight from a lamp)
//! and "Path tracing (II)": instead of waiting for a path to hit a light, aim
//! at the light. A point `y` chosen on the light's surface with density
//! `p_A(y)` per unit *area* must be turned into a density per unit *solid
//! angle* at the receiver `x`, because the rendering equation integrates over
//! directions: `dω = |cos θ_y| dA / ‖x − y‖²`.
//!
//! Part 1: `area_pdf_to_solid_angle(pdf_area, x, y, n_y)`: the density per
//! solid angle at `x` of the direction towards `y` (normal `n_y`), given the
//! area density `pdf_area` of `y`.
//!
//! Part 2: `estimate_direct(scene, it, sampler)`: one light sample of the
//! direct light reflected at the hit `it` towards `it.wo`:
//! choose a light with `scene.choose_light(sampler.next_1d())` (it returns the
//! light and the probability `pmf` of choosing it); for `Light::Area(a)` take
//! a point uniform by area, `(y, n_y) = a.shape.sample_area(sampler.next_2d())`
//! (density `1 / a.shape.area()`); the light sends `a.le(n_y, -wi)` towards
//! `x`; if `scene.unoccluded(&it.spawn_ray_to(y, n_y))`, return
//! `f_r · L_e · |cos θ_i| / (pmf · p_ω)`, else black. `f_r` is
//! `scene.brdf(it).eval(wo, wi, it.uv)` in the local frame. Other lights
//! (point, environment) can use `light.sample_li`, which converts for you.
//!
//! Receives: densities and points / the scene, a hit, the sampler.
//! Returns: the solid-angle density / the direct light estimate.

use raytracer::math::{Color, Vec3A};
use raytracer::sampling::Sampler;
use raytracer::scene::{Interaction, Scene};

/// `p_ω = p_A · ‖x − y‖² / |cos θ_y|`.
pub fn area_pdf_to_solid_angle(pdf_area: f32, x: Vec3A, y: Vec3A, n_y: Vec3A) -> f32 {
    // TODO: θ_y is the angle between n_y and the direction from y to x.
    todo!()
}

/// One next-event estimate of the direct light at `it`.
pub fn estimate_direct(scene: &Scene, it: &Interaction, sampler: &mut Sampler) -> Color {
    // TODO: choose a light, a point on it, convert the pdf, test visibility.
    todo!()
}
