//! Exercise 15 — bidirectional path tracing: the connection and its weight.
//!
//! Slides: "Bidirectional path tracing" ("Bidirectional path tracing"),
//! "Combining the strategies" ("Съчетаване на стратегиите").
//!
//! A camera subpath and a light subpath are joined by one edge between a
//! camera vertex x and a light vertex y. The densities of subpath vertices
//! are per unit area; the connecting edge brings them into the measure of
//! the whole path through the geometry term. Every full path can be made by
//! several strategies (how many vertices come from each side); multiple
//! importance sampling weighs them.
//!
//! Part 1: `geometry_term(x, nx, y, ny)`: `G(x ↔ y)`, defined by
//! `|cos θ_x| dω_x = G(x ↔ y) dA_y`: it turns an integral over directions at
//! x (with the cosine at x) into one over the area at y. θ_x lies between
//! `nx` and the edge at x, θ_y between `ny` and the edge at y; the normals
//! may face either way and `G ≥ 0`. Visibility is the caller's job; `x ≠ y`.
//!
//! Part 2: `bdpt_mis_weight(pdfs, s)`: the power-heuristic weight
//! (exponent 2, as in exercise 13 and on the slide "Combining the
//! strategies") of strategy `s` among all strategies that could have made
//! the same path, `pdfs[i]` being the density with which strategy i makes it
//! (all in the same measure). A strategy of density 0 gets weight 0; if all
//! are 0, return 0.
//!
//! Receives: two vertices with normals / the strategies' densities and the
//! index of the one used. Returns: `G` / the weight in [0, 1].

use raytracer::math::Vec3A;

/// The geometry term `G(x ↔ y)`.
pub fn geometry_term(x: Vec3A, nx: Vec3A, y: Vec3A, ny: Vec3A) -> f32 {
    // TODO: start from exercise 12's change of measure.
    todo!()
}

/// The power-heuristic weight of strategy `s`.
pub fn bdpt_mis_weight(pdfs: &[f32], s: usize) -> f32 {
    // TODO: as exercise 13, over all the strategies.
    todo!()
}
