//! Exercise 7 — a Monte Carlo estimate of the directional albedo.
//!
//! Slide: "Properties of BRDFs" ("Свойства на BRDF-ите"): energy
//! conservation, `ρ(ω_o) = ∫_Ω f_r(ω_i, ω_o) cos θ_i dω_i ≤ 1`.
//!
//! Task: estimate the directional albedo `ρ(ω_o)` of `brdf` for the
//! outgoing direction `wo` (local frame, normal `+z`) with `samples` random
//! directions: the Monte Carlo estimator `(1/N) Σ f_r(ω_k) cos θ_k / p(ω_k)`.
//! You may draw `ω_k` with the BRDF's own sampling (`brdf.sample(wo, uv,
//! u_lobe, u, TransportMode::Radiance)` returns `wi`, `f` and `pdf_w`; `None`
//! counts as a zero sample) or uniformly / cosine-weighted over the
//! hemisphere (`raytracer::sampling::warp`) with `brdf.eval`. Take every
//! random number from `sampler` (`next_1d`, `next_2d`); use `uv = Vec2::ZERO`.
//!
//! Receives: the BRDF, `wo`, the sampler, `N`. Returns: the estimate (RGB).
//! The grader calls it many times with independent samplers and checks the
//! mean against the exact albedo, using the spread of your own estimates.

use raytracer::brdf::Brdf;
use raytracer::math::{Color, Vec3A};
use raytracer::sampling::Sampler;

/// A Monte Carlo estimate of `∫ f_r cos θ_i dω_i` for `wo`.
pub fn estimate_albedo(brdf: &Brdf, wo: Vec3A, sampler: &mut Sampler, samples: u32) -> Color {
    // TODO: average f · cos θ_i / pdf over `samples` directions.
    todo!()
}
