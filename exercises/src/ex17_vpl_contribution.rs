//! Exercise 17 — instant radiosity: one virtual point light's contribution, clamped.
//!
//! Slides: "Instant radiosity" ("Instant radiosity"),
//! "Clamping: smooth, but wrong" ("Отрязване: гладко, но грешно").
//!
//! A virtual point light (VPL) sits at a vertex y of a light path with
//! normal `ny`; a camera point x with normal `nx` gathers its light over the
//! edge x ↔ y. The caller has already multiplied the two BRDFs and the VPL's
//! power into `fff = f_r(x; ω_xy, ω_o) · f_r(y; ω_in, ω_yx) · Φ_y` and checks
//! visibility; what is left is the geometry term of the edge (exercise 15):
//!
//! ```text
//!   L = fff · min(G(x, y), g_max),   G(x, y) = |cos θ_x| |cos θ_y| / ‖x − y‖²
//! ```
//!
//! θ_x lies between `nx` and the edge, θ_y between `ny` and the edge; the
//! normals may face either way. G grows without bound as x nears y: bright
//! splotches near corners. Clamping G at `g_max = clamp` removes them (and
//! with them light that was really there: the picture comes out too dark
//! where surfaces meet). `clamp = 0` means no clamping at all; `x ≠ y`.
//!
//! Receives: the two points with their normals, the product of the BRDFs and
//! the power, the bound. Returns: the light the VPL sends from x towards the
//! viewer (RGB).

use raytracer::math::{Color, Vec3A};

/// The contribution of the VPL at `y` to `x`, with G clamped at `clamp` (0: not clamped).
pub fn vpl_contribution(x: Vec3A, nx: Vec3A, y: Vec3A, ny: Vec3A, fff: Color, clamp: f32) -> Color {
    // TODO: the geometry term of the edge, then the bound.
    todo!()
}
