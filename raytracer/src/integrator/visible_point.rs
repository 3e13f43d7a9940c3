//! The visible point of a camera sample: the first surface it sees that does
//! not reflect like a mirror.
//!
//! Lecture topic: the biased algorithms ("photon mapping, irradiance caching,
//! instant radiosity"). All four of them — photon mapping, its progressive
//! form (SPPM, where the term "visible point" comes from), instant radiosity
//! and irradiance caching — answer the question "how much light leaves this
//! diffuse or glossy point towards the camera?" with a cache built from the
//! light's side. Mirrors and glass cannot be cached (their `f_r` is a delta),
//! so the camera ray is followed through them by ordinary ray tracing first:
//!
//! ```text
//!   camera → (mirror | glass)* → x      β = Π f_r |cos θ_i| / p  over the delta bounces
//! ```
//!
//! On the way, light seen directly or through the delta bounces is added in
//! full (`L_e`): no light sample can find it (a BRDF sample from a delta lobe
//! has weight 1 in the path tracer too).
//!
//! All four then begin alike ([`lit_visible_point`], their one prologue):
//! below the maximum depth, the direct light at `x` comes from one light
//! sample, as in the path tracer, and what is left (light that bounced at
//! least once) is each algorithm's own estimate at the [`GatherPoint`].

use super::continuation::sample_continuation;
use super::{camera_ray, max_segments, nee, stop};
use crate::brdf::TransportMode;
use crate::geometry::Interaction;
use crate::math::{Color, Ray, UVec2};
use crate::sampling::Sampler;
use crate::scene::Scene;

/// At most this many delta bounces are followed (a ray trapped inside a
/// glass ball by total internal reflection would otherwise bounce for ever
/// when the depth is unlimited).
pub const MAX_DELTA_BOUNCES: u32 = 64;

/// Where a camera sample's ray first meets a non-delta surface.
#[derive(Clone, Copy, Debug)]
pub struct VisiblePoint {
    /// Emitted light seen directly or through the delta bounces, already
    /// weighted by their `β` (the emission of `x` itself included).
    pub le: Color,
    /// The point `x` with `ω_o` towards the camera, if the ray found one
    /// before leaving the scene or reaching the maximum depth.
    pub hit: Option<Interaction>,
    /// The throughput `β` of the delta bounces before `x` (1 without them).
    pub beta: Color,
    /// The number of segments from the lens to `x` (1: seen directly).
    pub depth: u32,
}

/// A visible point below the maximum depth, where a biased integrator
/// estimates the light that bounced at least once.
#[derive(Clone, Copy, Debug)]
pub struct GatherPoint {
    /// The point `x`, with `ω_o` towards the camera.
    pub it: Interaction,
    /// The throughput `β` of the delta bounces before `x`.
    pub beta: Color,
    /// Segments from the lens to `x`.
    pub depth: u32,
}

/// The prologue of the biased integrators: the [`visible_point`] of
/// `pixel`, then, if it lies below the maximum depth, the direct light at
/// `x` from one light sample ([`nee::sample_light`]). Returns the light
/// found so far (`L_e` through the delta bounces, plus `β` times the light
/// sample) and the point to go on from, `None` where no path may (no hit,
/// or `x` at the maximum depth). Draws the visible point's numbers, then a
/// light sample's.
pub fn lit_visible_point(
    scene: &Scene,
    pixel: UVec2,
    sampler: &mut Sampler,
    max_depth: Option<u32>,
) -> (Color, Option<GatherPoint>) {
    let vp = visible_point(scene, pixel, sampler, max_depth);
    let Some(it) = vp.hit else {
        return (vp.le, None);
    };
    if vp.depth >= max_segments(max_depth) {
        return (vp.le, None);
    }
    let direct = nee::sample_light(scene, &it, scene.brdf(&it), sampler, false);
    let point = GatherPoint {
        it,
        beta: vp.beta,
        depth: vp.depth,
    };
    (vp.le + vp.beta * direct, Some(point))
}

/// Follows the camera ray of `pixel` through mirrors and glass to the first
/// non-delta surface, up to `max_depth` segments (Mitsuba's D; `None`:
/// [`MAX_DELTA_BOUNCES`]). Draws the camera ray's numbers, then a
/// continuation per delta bounce.
pub fn visible_point(
    scene: &Scene,
    pixel: UVec2,
    sampler: &mut Sampler,
    max_depth: Option<u32>,
) -> VisiblePoint {
    let ray = camera_ray(scene, pixel, sampler);
    follow_delta_chain(scene, ray, Color::ONE, 1, sampler, max_depth, true)
}

/// Follows `ray` (its end would be segment number `depth`) through delta
/// bounces to the first non-delta surface. With `count_emission`, light
/// reached on the way is added to `le` (a camera ray); without, it is not
/// (a gather ray, whose emitters were found by a light sample already).
pub fn follow_delta_chain(
    scene: &Scene,
    mut ray: Ray,
    mut beta: Color,
    mut depth: u32,
    sampler: &mut Sampler,
    max_depth: Option<u32>,
    count_emission: bool,
) -> VisiblePoint {
    let max_depth = max_depth.unwrap_or(MAX_DELTA_BOUNCES + 1);
    let mut le = Color::ZERO;
    let mut bounces = 0;
    loop {
        let hit = scene.intersect(&ray);
        if count_emission {
            if let Some(e) = scene.emitter_hit(&ray, hit.as_ref()) {
                le += beta * e.le;
            }
        }
        let Some(it) = hit else {
            return VisiblePoint {
                le,
                hit: None,
                beta,
                depth,
            };
        };
        let brdf = scene.brdf(&it);
        if !brdf.is_delta() {
            return VisiblePoint {
                le,
                hit: Some(it),
                beta,
                depth,
            };
        }
        if depth >= max_depth || bounces >= MAX_DELTA_BOUNCES || stop::stop_requested() {
            return VisiblePoint {
                le,
                hit: None,
                beta,
                depth,
            };
        }
        let Some(c) = sample_continuation(&it, brdf, TransportMode::Radiance, sampler) else {
            return VisiblePoint {
                le,
                hit: None,
                beta,
                depth,
            };
        };
        beta *= c.weight;
        ray = c.ray;
        depth += 1;
        bounces += 1;
    }
}
