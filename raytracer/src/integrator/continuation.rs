//! The path's continuation: one direction sampled from the BRDF.
//!
//! Lecture topic: "Path tracing in outline" — at a hit, pick one random
//! continuation; the BRDF tells how much to weight the light it brings:
//!
//! ```text
//!   β ← β · f_r(x, ω_i, ω_o) |cos θ_i| / p(ω_i)
//! ```
//!
//! Every estimator that follows a BRDF sample takes this one step: the BRDF
//! half of direct lighting, each branch of naive recursion, each bounce of
//! path tracing, and the random walks of light and bidirectional tracing.

use super::dimensions::{BRDF_DIRECTION, BRDF_LOBE};
use crate::brdf::{Brdf, BrdfSample, TransportMode};
use crate::geometry::Interaction;
use crate::math::{Color, Ray, Vec3A};
use crate::sampling::Sampler;

/// A continuation sampled at a surface point.
#[derive(Clone, Copy, Debug)]
pub struct Continuation {
    /// The BRDF's sample: `ω_i` in the local frame, `f_r`, its density per
    /// unit solid angle, whether the lobe is a delta, the η crossed.
    pub sample: BrdfSample,
    /// `ω_o` in the local frame (the reverse density of a random walk needs it).
    pub wo: Vec3A,
    /// `ω_i` in world space.
    pub wi: Vec3A,
    /// The throughput factor `f_r |cos θ_i| / p(ω_i)`.
    pub weight: Color,
    /// The ray that leaves the surface along `ω_i`.
    pub ray: Ray,
}

/// Samples the BRDF `brdf` at `it` in transport mode `mode`. Draws
/// [`BRDF_LOBE`], then [`BRDF_DIRECTION`]. `None` if the sample carries
/// nothing (see [`Brdf::sample`]).
#[inline]
pub fn sample_continuation(
    it: &Interaction,
    brdf: &Brdf,
    mode: TransportMode,
    sampler: &mut Sampler,
) -> Option<Continuation> {
    let wo = it.frame.to_local(it.wo);
    let (u_lobe, u) = (BRDF_LOBE.draw(sampler), BRDF_DIRECTION.draw(sampler));
    let sample = brdf.sample(wo, it.uv, u_lobe, u, mode)?;
    let wi = it.frame.to_world(sample.wi);
    Some(Continuation {
        sample,
        wo,
        wi,
        weight: sample.f * (sample.wi.z.abs() / sample.pdf_w),
        ray: it.spawn_ray(wi),
    })
}
