//! Exercise 4 — the normalized Phong lobe.
//!
//! Slides: "Examples of BRDFs" ("Примери за BRDF"): the glossy BRDF
//! `f_r = S(n) · max(0, cos∠(reflect(ω_i), ω_o))^n`, where `S(n)` is a
//! normalizing constant meant to conserve energy; and "Properties of BRDFs"
//! ("Свойства на BRDF-ите"): `∫_Ω f_r cos θ dω ≤ 1`, which is why `1/π` and
//! `S(n)` exist.
//!
//! Task, part 1: `phong_normalization(n)` returns the `S(n)` that makes the
//! directional albedo `∫ f_r cos θ_i dω_i` of the lobe exactly 1 at normal
//! incidence (`ω_o = +z`, so that the mirror direction is the normal and
//! α = θ_i). Hint: `∫_{H²} cos^{n+1}θ dω = 2π ∫_0^1 t^{n+1} dt`.
//!
//! Part 2: `phong_eval(albedo, n, wo, wi)` returns
//! `albedo · S(n) · max(0, cos α)^n`, α the angle between `wi` and the mirror
//! direction of `wo` about the normal. Local frame (normal `+z`); both
//! directions are in the upper hemisphere (the renderer checks that).
//!
//! Receives: the exponent `n ≥ 0` (and the specular albedo ρ_s, `wo`, `wi`).
//! Returns: `S(n)`, and `f_r`.

use raytracer::math::{Color, Vec3A};

/// `S(n)`: the normalization of the Phong lobe `cos^n α`.
pub fn phong_normalization(n: f32) -> f32 {
    // TODO: work out ∫ cos^n θ · cos θ dω over the hemisphere, take 1 over it.
    todo!()
}

/// `f_r(ω_i → ω_o) = ρ_s · S(n) · max(0, cos α)^n`.
pub fn phong_eval(albedo: Color, n: f32, wo: Vec3A, wi: Vec3A) -> Color {
    // TODO: the mirror direction of wo about +z is (−wo.x, −wo.y, wo.z).
    todo!()
}
