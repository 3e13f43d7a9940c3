//! Exercise 18 — instant radiosity (Keller): virtual point lights from light
//! paths, and their light gathered at a camera hit.
//!
//! Slides: "Instant radiosity" ("Instant radiosity"),
//! "Clamping: smooth, but wrong" ("Ограничаване (clamping): гладко, но грешно").
//!
//! Instant radiosity traces N light paths once and turns their vertices into
//! virtual point lights (VPLs); a point the camera sees is then lit by every
//! VPL over one connection, with a shadow ray each:
//!
//! ```text
//!   L(x, ω_o) = Σ_y f_r(x; ω_xy, ω_o) · G(x, y) · f_y(ω_yx) · Φ_y · V(x, y)
//! ```
//!
//! with `G(x, y)` the geometry term of the connection (exercise 15: a cosine
//! at each end, the squared distance). Averaged over the choice of the light
//! paths this is the rendering equation's answer: no bias, unless G is
//! clamped. Conventions as in exercises 10–14: directions point away from
//! the surface point, D counts the segments of a path.
//!
//! # Step 1: `generate_vpls`
//!
//! Trace `paths` (N) light paths with the numbers of `sampler` and return
//! their VPLs (`Vpl`, in `exercises::plug`):
//! - a path starts on a light: choose one (`Scene::choose_light`, with its
//!   probability `LightChoice::pmf`) and emit a ray from it
//!   (`Light::sample_le`: an `Emission` with its point, normal, `L_e`, the
//!   density of the point per unit area and of the direction per unit solid
//!   angle). Its first vertex `y_0` is already a VPL, `Vpl::Light`: it
//!   sends the light's own `L_e(y_0, ω)`; its `weight` is the throughput of
//!   the path at `y_0`, shared out among the N paths. Without it there is no
//!   direct light at all;
//! - every later vertex `y_k` (`k ≥ 1`) on a surface whose BRDF is not a
//!   delta (`Brdf::is_delta`: a mirror or glass can light nothing over a
//!   connection) becomes a `Vpl::Surface` whose `power` Φ is the flux the
//!   path carries there: its throughput so far (emission, then a factor per
//!   bounce), again shared by the N paths. A delta surface keeps no VPL but
//!   the path goes on through it;
//! - the path continues by sampling the BRDF (`Brdf::sample` in
//!   `TransportMode::Importance`: light flows along a light path) and plays
//!   Russian roulette once it has made `rr_depth` bounces (a survival
//!   probability of your choice; the flux must stay unbiased);
//! - depth: the gather happens at the camera's first hit, so a VPL of k
//!   segments makes a path of k + 2 segments; keep only those within
//!   `max_depth` (`Some(D)`; `None`: no limit). `D < 2`: no VPL at all.
//!
//! Lights are area lights (quads, spheres; two-sided ones emit on both
//! sides, and `Scene::emitted_by` says how much in each direction).
//!
//! # Step 2: `gather`
//!
//! The light all `vpls` send to the camera's hit `x` and that `x` reflects
//! towards `x.wo` (the sum above, RGB):
//! - at `x`: the BRDF (`Scene::brdf`, `Brdf::eval` in the local frame of
//!   `x.frame`) from the direction towards the VPL to `x.wo`;
//! - at the VPL: what it sends back towards `x` — for `Vpl::Light` the
//!   light's emission in that direction times its `weight`; for
//!   `Vpl::Surface` its BRDF from its incoming direction (`it.wo`) to the
//!   direction towards `x`, times its `power`;
//! - the geometry term with both cosines, each taken where it belongs, and
//!   normals that may face either way;
//! - visibility: one shadow ray (`Scene::unoccluded`, with
//!   `Ray::spawn_to` from `x` to the VPL's point with both geometric
//!   normals);
//! - `clamp`: `Some(g_max)` bounds the geometry term at `g_max` (the
//!   lecture's clamping: no splotches where x nears a VPL, and too dark
//!   where surfaces meet); `None`: not clamped at all. A VPL at `x` itself
//!   (zero distance) adds nothing.
//!
//! `exercises::plug::StudentVpl` puts the two together: at the first camera
//! hit, its emission plus `gather` over the VPLs of `generate_vpls`
//! (`lesson11 render --student -i vpl`, beside the renderer's `vpl`).

use raytracer::math::Color;
use raytracer::sampling::Sampler;
use raytracer::scene::{Interaction, Scene};

use crate::plug::Vpl;

/// The VPLs of `paths` light paths: one on the light where each path starts,
/// one at every later vertex on a surface that is not a mirror or glass.
pub fn generate_vpls(
    scene: &Scene,
    paths: u32,
    max_depth: Option<u32>,
    rr_depth: u32,
    sampler: &mut Sampler,
) -> Vec<Vpl> {
    // TODO: N light paths: a VPL on the light, one per non-delta hit, BRDF sampling, roulette.
    todo!()
}

/// The light of every VPL reflected at `x` towards `x.wo`, G clamped at
/// `clamp` (`None`: not clamped).
pub fn gather(scene: &Scene, x: &Interaction, vpls: &[Vpl], clamp: Option<f32>) -> Color {
    // TODO: for each VPL: the BRDF at x, what the VPL sends towards x, G, a shadow ray.
    todo!()
}
