//! Exercise 15 — bidirectional path tracing: the connections and their weights.
//!
//! Slides: "Bidirectional path tracing" ("Bidirectional path tracing"),
//! "Strategies" ("Стратегии"), "Combining the strategies" ("Съчетаване на
//! стратегиите").
//!
//! The library grows, for every pixel sample, a camera subpath
//! `camera = [z_0, z_1, …]` (`z_0` on the lens) and a light subpath
//! `light = [y_0, y_1, …]` (`y_0` on a light) by random walks
//! (`raytracer::integrator::subpath`). You write what bidirectional path
//! tracing does with them: every strategy `(s, t)` — the first `s` light
//! vertices and the first `t` camera vertices joined by one edge
//! `y_{s−1} — z_{t−1}` into the path `x̄ = z_0 … z_{t−1} y_{s−1} … y_0` of
//! `s + t` vertices — gives an estimate of the light carried by such paths,
//! and multiple importance sampling weighs the estimates of all strategies
//! that could have made the same path. `exercises::plug::StudentBdpt` calls
//! your `connect` and `mis_weight` for every `(s, t)` with `t ≥ 1`,
//! `s + t ≥ 2` and `s + t ≤ D + 1` and renders with them
//! (`lesson11 render --student -i bdpt`).
//!
//! **The vertices** (`raytracer::integrator::vertex::Vertex`). Each has its
//! position `.p()`, its kind (`VertexKind::Camera`, `Light`, `Surface`), its
//! throughput `.beta` (the subpath's weight up to this vertex, everything
//! before the vertex's own scattering: the camera side's is a radiance
//! weight, the light side's a power estimate), and two densities per unit
//! AREA at this vertex: `.pdf_fwd_a`, with which its own subpath generated
//! it, and `.pdf_rev_a`, with which the other subpath would have generated
//! it (the same walk run backwards). `.pdf_rev_a` is valid for all but the
//! last two vertices of each prefix: for those it depends on the vertex
//! across the edge. `.delta` marks a vertex where the walk scattered off a
//! delta BRDF (a mirror): its sampling densities are stored as 0.
//! Toolbox on a vertex: `Vertex::f` (the BRDF from `ω_o` — the direction to
//! its predecessor in its own subpath — to a given direction; at a light
//! vertex the emitted radiance `L_e` in that direction), `Vertex::f_importance`
//! (the same for a light-subpath vertex, which carries importance),
//! `Vertex::abs_cos` (the cosine a vertex uses: shading normal on a surface,
//! the light's normal, none at a point light), `Vertex::le_towards`,
//! `Vertex::is_connectible`, `Vertex::is_delta_light`, `Vertex::pdf_a` (the
//! area density at a target vertex of sampling it from this one, having
//! arrived from a given predecessor), `Vertex::pdf_light_a` and
//! `Vertex::pdf_light_origin_a` (the densities of a light path that starts at
//! this emitter point), `vertex::visible`, `Camera::sample_wi`.
//!
//! **Part 1: `geometry_term(x, nx, y, ny)`**, `G(x ↔ y)`, defined by
//! `|cos θ_x| dω_x = G(x ↔ y) dA_y`: it turns an integral over directions at
//! x (with the cosine at x) into one over the area at y. θ_x lies between
//! `nx` and the edge at x, θ_y between `ny` and the edge at y; the normals
//! may face either way and `G ≥ 0`. Visibility is the caller's job; `x ≠ y`.
//!
//! **Part 2: `connect(scene, light, camera, s, t, sampler)`**, the
//! UNWEIGHTED contribution `C_{s,t}` of one strategy: the path's
//! measurement contribution (the lecture's `f_j(x̄)`: emission, the BRDFs,
//! the geometry terms, the camera's importance) divided by the density with
//! which the strategy made the path, both in the area measure. The
//! throughputs hold everything on each side of the edge; the edge brings
//! what depends on both ends. Cases:
//! - `s = 0`: the camera subpath reached an emitter by itself at `z_{t−1}`;
//! - `t = 1`: `y_{s−1}` is joined to a point on the lens, drawn with
//!   `Camera::sample_wi` from `sampler.next_2d()` (exercise 14's
//!   connection): the result lands at `CameraSample::raster` (return it in
//!   `raster`, and the lens point as `Vertex::camera(p_lens, Color::ZERO)` in
//!   `lens`);
//! - otherwise `y_{s−1}` and `z_{t−1}` are joined directly (`s = 1` too:
//!   `y_0`, the light point of the light subpath, is a vertex like the
//!   others, its `f` is `L_e`). Each end scatters from its own predecessor
//!   towards the other end; mind which side carries importance.
//!
//! `None` where the contribution is zero: nothing emitted, an end that cannot
//! be connected (a delta BRDF), the two ends not visible to each other, the
//! lens point not seeing `y_{s−1}`.
//!
//! **Part 3: `mis_weight(scene, light, camera, s, t, lens)`**, the weight of
//! strategy `(s, t)` by the power heuristic with exponent 2 over every
//! strategy `(s', t')`, `s' + t' = s + t`, `t' ≥ 1`, that could have made
//! the same path. Derive each strategy's density from the vertices: a
//! strategy's density is the product over the path's vertices (all but the
//! lens point `z_0`, common to all) of each vertex's area density from the
//! side that made it in that strategy — the camera side for the first `t'`
//! vertices, the light side for the rest. Use the stored `.pdf_fwd_a` /
//! `.pdf_rev_a`; but a vertex's density from the other side depends on the
//! vertex the path now comes from, so the connection changes some of them
//! next to the edge: work out which, and compute those anew for this path
//! (`Vertex::pdf_a`, `Vertex::pdf_light_a`, `Vertex::pdf_light_origin_a`).
//! `lens`, if any, takes the place of `camera[0]` (for `t = 1` without a
//! `lens`, `camera[0]` is the lens point). The slices are shared: copy what
//! you change. Count every strategy of this renderer, the shortest paths
//! too: a path of two vertices has the strategies (0, 2) and (1, 1).
//!
//! Impossible strategies have density 0 and count for nothing: one whose
//! edge would end at a vertex with a delta BRDF (mirror), or `s' = 0` ending
//! on a point light (no ray hits it). If the edge of `(s, t)` itself ends
//! at a vertex with a delta BRDF, return 0. A delta's own density is the same delta in every strategy that
//! can make the path, so it does not change the weights (it is stored as 0).
//! The weights of the possible strategies of one path sum to 1.
//!
//! Receives: the scene, both subpaths (at least `s` and `t` vertices), the
//! strategy; `connect` a sampler for `t = 1`. Returns: `C_{s,t}` (RGB) / the
//! weight in [0, 1].

use raytracer::integrator::vertex::Vertex;
use raytracer::math::Vec3A;
use raytracer::sampling::Sampler;
use raytracer::scene::Scene;

use crate::plug::BdptConnection;

/// The geometry term `G(x ↔ y)`.
pub fn geometry_term(x: Vec3A, nx: Vec3A, y: Vec3A, ny: Vec3A) -> f32 {
    // TODO: start from exercise 12's change of measure.
    todo!()
}

/// The unweighted contribution of strategy `(s, t)`.
pub fn connect(
    scene: &Scene,
    light: &[Vertex],
    camera: &[Vertex],
    s: usize,
    t: usize,
    sampler: &mut Sampler,
) -> Option<BdptConnection> {
    // TODO: s = 0, t = 1, and the edge between y_{s−1} and z_{t−1}.
    todo!()
}

/// The MIS weight (power heuristic) of strategy `(s, t)`.
pub fn mis_weight(
    scene: &Scene,
    light: &[Vertex],
    camera: &[Vertex],
    s: usize,
    t: usize,
    lens: Option<Vertex>,
) -> f32 {
    // TODO: every strategy's density relative to this one's, from the vertices.
    todo!()
}
