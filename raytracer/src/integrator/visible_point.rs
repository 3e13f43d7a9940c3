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

use super::continuation::sample_continuation;
use super::{camera_ray, stop};
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
