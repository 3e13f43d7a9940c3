//! Exercise 3 — the Lambertian BRDF with a texture.
//!
//! Slides: "BRDF examples" ("Примери за BRDF"), "BRDFs: a little more complex" ("BRDF-и: малко по-сложно"),
//! "Properties of BRDFs" ("Свойства на BRDF-ите").
//!
//! A diffuse (Lambertian) surface reflects the same radiance in every
//! direction: its BRDF is a constant for every pair of directions. How large
//! a constant is fixed by energy conservation, and with a diffuse texture it
//! depends on the point, through the texture's colour there.
//!
//! A BRDF is a density per unit solid angle (sr⁻¹), not a probability: its
//! values may exceed 1 (a narrow glossy lobe's do). What is bounded is the
//! directional albedo `∫_Ω f_r cos θ_i dω_i ≤ 1`, the fraction of the light
//! arriving from all directions that leaves towards `ω_o`. (The slide writes
//! the bound over ω_o, `∫ f_r cos Θ_o dω_o ≤ 1`; by reciprocity,
//! `f_r(ω_i, ω_o) = f_r(ω_o, ω_i)`, it is the same integral.)
//!
//! Task: evaluate the Lambertian BRDF whose albedo is the texture `albedo`
//! at the texture coordinates `uv`, with the constant chosen so that a white
//! texture (albedo 1) reflects exactly all the light: `∫_Ω f_r cos θ_i dω_i
//! = 1` over the hemisphere. Directions are in the local shading frame: the
//! normal is `+z`, so `cos θ` of a direction is its `z`; `wo` points towards
//! the viewer, `wi` towards where the light comes from (both away from the
//! surface). Light from below, or leaving below (`wi.z ≤ 0` or `wo.z ≤ 0`),
//! is not reflected: return black.
//!
//! Receives: the albedo texture (its colour at `uv` is `Texture::eval`),
//! `uv`, `wo`, `wi`. Returns: `f_r` alone — the cosine of the rendering
//! equation belongs to the integrator, not here.

use raytracer::brdf::Texture;
use raytracer::math::{Color, Vec2, Vec3A};

/// `f_r(ω_i, ω_o)` of a textured Lambertian surface.
pub fn lambert_eval(albedo: &Texture, uv: Vec2, wo: Vec3A, wi: Vec3A) -> Color {
    // TODO: the texture's colour at uv times the constant you derived.
    todo!()
}
