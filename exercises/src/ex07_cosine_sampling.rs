//! Exercise 7 — cosine-weighted hemisphere sampling and its pdf.
//!
//! Slides: "Solving with Monte Carlo" ("Решаване чрез Monte Carlo метод").
//!
//! The Monte Carlo estimate of an integral over the hemisphere divides each
//! random direction's contribution by its density `p(ω)`. Directions drawn
//! with a density proportional to `cos θ` cancel the cosine of the
//! rendering equation (and, for Lambert, the whole BRDF but its albedo).
//!
//! Part 1: `sample_cosine_hemisphere(u)`: turn two uniform numbers
//! `u ∈ [0, 1)²` into a unit direction in the upper hemisphere (`z ≥ 0`,
//! local frame) whose density per unit solid angle is proportional to
//! `cos θ`. Any correct method is fine.
//!
//! Part 2: `cosine_hemisphere_pdf(w)`: that density for the direction `w`,
//! normalized (it integrates to 1 over the hemisphere); 0 below the horizon
//! (`w.z ≤ 0`).
//!
//! Receives: the explicit random numbers `u` (never call a random generator
//! here: the grader feeds you its own numbers). Returns: the direction / its
//! density.

use raytracer::math::{Vec2, Vec3A};

/// A direction with density proportional to `cos θ`.
pub fn sample_cosine_hemisphere(u: Vec2) -> Vec3A {
    // TODO: find a shape whose uniform points map to such directions.
    todo!()
}

/// The density of [`sample_cosine_hemisphere`] per unit solid angle.
pub fn cosine_hemisphere_pdf(w: Vec3A) -> f32 {
    // TODO: proportional to cos θ, integrating to 1.
    todo!()
}
