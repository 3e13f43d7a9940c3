//! Exercise 3 — the Lambertian BRDF with a texture.
//!
//! Slides: "Examples of BRDFs" ("Примери за BRDF": the diffuse BRDF of a
//! white surface is `1/π`) and "BRDFs: a bit more complicated" ("BRDFs: малко
//! по-сложно"): with a diffuse texture the BRDF depends on the point,
//! `f_r(x, ω_i, ω_o) = texture.sample(x) / π`.
//!
//! Task: evaluate the Lambertian BRDF whose albedo is the texture `albedo`
//! at the texture coordinates `uv`. Directions are in the local shading frame
//! (the normal is `+z`, so `cos θ` of a direction is its `z`); `wo` points to
//! the viewer, `wi` to the light. Light that comes from below the surface, or
//! leaves below it (`wi.z ≤ 0` or `wo.z ≤ 0`), is not reflected: return black.
//!
//! Receives: the albedo texture, `uv`, `wo`, `wi`. Returns: `f_r` alone —
//! the cosine of the rendering equation belongs to the integrator, not here.

use raytracer::brdf::Texture;
use raytracer::math::{Color, Vec2, Vec3A};

/// `f_r(ω_i → ω_o)` of a textured Lambertian surface.
pub fn lambert_eval(albedo: &Texture, uv: Vec2, wo: Vec3A, wi: Vec3A) -> Color {
    // TODO: the texture's colour at uv, divided by π (why π? see the slide
    // "Properties of BRDFs": energy conservation).
    todo!()
}
