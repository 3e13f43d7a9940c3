//! Exercise 6 — cosine-weighted hemisphere sampling and its pdf.
//!
//! Slides: "Solving by the Monte Carlo method" ("Решаване чрез Monte Carlo
//! метод") and "The Rendering Equation": the integral over the hemisphere Ω is
//! estimated with random directions; the `cos θ` factor of the equation is
//! best sampled, not multiplied: with pdf `cos θ / π` the cosine (and a
//! Lambertian `1/π`) cancel.
//!
//! Part 1: `sample_cosine_hemisphere(u)`: turn two uniform numbers
//! `u ∈ [0, 1)²` into a unit direction in the upper hemisphere (`z ≥ 0`,
//! local frame) whose density per unit solid angle is `cos θ / π`. Any
//! correct method is fine (e.g. a uniform point on the unit disk lifted up
//! to the hemisphere, "Malley's method").
//!
//! Part 2: `cosine_hemisphere_pdf(w)`: that density for the direction `w`
//! (0 below the horizon).
//!
//! Receives: the explicit random numbers `u` (never call a random generator
//! here: the grader feeds you its own numbers). Returns: the direction / its pdf.

use raytracer::math::{Vec2, Vec3A};

/// A direction with density `cos θ / π`.
pub fn sample_cosine_hemisphere(u: Vec2) -> Vec3A {
    // TODO: r = sqrt(u.x) and φ = 2π·u.y give a uniform point on the disk.
    todo!()
}

/// The density of [`sample_cosine_hemisphere`] per unit solid angle.
pub fn cosine_hemisphere_pdf(w: Vec3A) -> f32 {
    // TODO
    todo!()
}
