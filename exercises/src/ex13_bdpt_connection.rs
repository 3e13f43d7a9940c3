//! Exercise 13 — bidirectional path tracing: connecting two subpath vertices.
//!
//! Slide: "Bidirectional path tracing": a camera subpath and a light subpath
//! are joined by one edge between a camera vertex `x` and a light vertex
//! `y`. Every full path can be made by several strategies (how many vertices
//! come from each side); multiple importance sampling weighs them.
//!
//! Part 1: `geometry_term(x, nx, y, ny)`: `G(x ↔ y) = |cos θ_x| |cos θ_y| /
//! ‖x − y‖²`, with θ_x between `nx` and the edge at `x`, θ_y between `ny` and
//! the edge at `y` (visibility is the caller's job). It converts the
//! product of the two area densities into the measure of the edge:
//! `dω_x = |cos θ_y| dA_y / ‖x − y‖²`.
//!
//! Part 2: `bdpt_mis_weight(pdfs, s)`: the power-heuristic weight (β = 2) of
//! strategy `s` among all strategies that could have made the same path,
//! `pdfs[i]` being the density with which strategy `i` makes it (all in the
//! same measure): `w_s = p_s² / Σ_i p_i²`.
//!
//! Receives: two vertices with normals / the strategies' densities and the
//! index of the one used. Returns: `G` / the weight in `[0, 1]`.

use raytracer::math::Vec3A;

/// The geometry term `G(x ↔ y)`.
pub fn geometry_term(x: Vec3A, nx: Vec3A, y: Vec3A, ny: Vec3A) -> f32 {
    // TODO
    todo!()
}

/// The power-heuristic weight of strategy `s`.
pub fn bdpt_mis_weight(pdfs: &[f32], s: usize) -> f32 {
    // TODO
    todo!()
}
