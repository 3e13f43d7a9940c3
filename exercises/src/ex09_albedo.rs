//! Exercise 9 — a Monte Carlo estimate of the directional albedo.
//!
//! Slides: "Properties of BRDFs" ("Свойства на BRDF-ите"), "Solving with
//! Monte Carlo" ("Решаване чрез Monte Carlo метод").
//!
//! Energy conservation: a surface reflects at most the light it receives.
//! The slide writes it as `∫_Ω f_r(ω_i, ω_o) cos Θ_o dω_o ≤ 1`: the light
//! arriving from one direction ω_i, reflected into all directions ω_o. Here
//! we compute the directional albedo
//!
//! ```text
//! ρ(ω_o) = ∫_Ω f_r(ω_i, ω_o) cos θ_i dω_i,
//! ```
//!
//! the light arriving from all directions ω_i, reflected towards one ω_o.
//! By reciprocity (the slide's symmetry, `f_r(ω_i, ω_o) = f_r(ω_o, ω_i)`)
//! the two integrals are the same function of the one fixed direction, so
//! either form of the bound says the same.
//!
//! Task: estimate `ρ(ω_o)` of `brdf` for `wo` (local frame, normal `+z`) by
//! the Monte Carlo method with N = `samples` random directions. Draw them as
//! you like:
//! - with the BRDF's own sampling, `Brdf::sample` (it returns a
//!   `BrdfSample` with `wi`, `f` and `pdf_w`, or `None` when the direction
//!   it drew carries nothing, e.g. below the horizon: such a draw
//!   contributes 0 and is still one of the N);
//! - or uniformly or cosine-weighted over the hemisphere
//!   (`raytracer::sampling::warp`), with `Brdf::eval`.
//!
//! Take every random number from `sampler` (`Sampler::next_1d`,
//! `Sampler::next_2d`); use `uv = Vec2::ZERO` and `TransportMode::Radiance`.
//!
//! Receives: the BRDF, `wo`, the sampler, N. Returns: the estimate (RGB).
//! The grader calls it many times with independent samplers and compares
//! the mean of your estimates with the exact albedo, using the spread of
//! your own estimates. One case is a Phong lobe seen at 75° from the normal,
//! whose albedo is well below ρ_s (exercise 4).

use raytracer::brdf::Brdf;
use raytracer::math::{Color, Vec3A};
use raytracer::sampling::Sampler;

/// A Monte Carlo estimate of `∫ f_r cos θ_i dω_i` for `wo`.
pub fn estimate_albedo(brdf: &Brdf, wo: Vec3A, sampler: &mut Sampler, samples: u32) -> Color {
    // TODO: average the contributions of `samples` random directions.
    todo!()
}
