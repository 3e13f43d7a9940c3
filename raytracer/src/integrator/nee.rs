//! Next event estimation: sampling a light from a surface point, weighted by
//! multiple importance sampling against BRDF sampling.
//!
//! Lecture topic: the direct-light part of the rendering equation. Of the
//! integral `∫ f_r L_i cos θ_i dω_i`, the part that comes straight from the
//! lights is estimated by choosing a point on a light:
//! `f_r · L_e · |cos θ_i| / p_light(ω_i)`, where `p_light` is the pdf per unit
//! solid angle (the area pdf converted with `dist² / cos θ_light`). Shared by
//! every integrator that connects a surface point to a light.

use super::dimensions::{LIGHT_CHOICE, LIGHT_POINT};
use super::record::{NoRecorder, Recorder, Segment, SegmentEnd, SegmentKind, VertexRef};
use crate::brdf::Brdf;
use crate::geometry::Interaction;
use crate::light::LightSample;
use crate::math::{Color, Vec3A};
use crate::sampling::{Sampler, power_heuristic};
use crate::scene::{EmitterHit, LightChoice, Scene};

/// A light chosen, and a point on it sampled as seen from a receiver.
#[derive(Clone, Copy, Debug)]
pub struct LightPoint<'a> {
    /// Which light, with the probability `P(light)` of choosing it.
    pub choice: LightChoice<'a>,
    /// The point: direction `ω_i`, `L_i`, its density `p_ω` per unit solid
    /// angle at the receiver, distance, normal.
    pub sample: LightSample,
}

/// The sampling half of next event estimation, shared by every integrator
/// that aims at a light (this file's [`sample_light`], and the `s = 1`
/// strategy of bidirectional tracing): chooses a light with `P(light)` and
/// samples a point on it as seen from `p`. Draws [`LIGHT_CHOICE`], then
/// [`LIGHT_POINT`]. `None` if the scene has no light or the sample carries
/// nothing (zero density or radiance).
#[inline]
pub fn sample_light_point<'a>(
    scene: &'a Scene,
    p: Vec3A,
    sampler: &mut Sampler,
) -> Option<LightPoint<'a>> {
    let u_choice = LIGHT_CHOICE.draw(sampler);
    let u = LIGHT_POINT.draw(sampler);
    let choice = scene.choose_light(u_choice)?;
    let sample = choice.light.sample_li(p, u)?;
    if sample.pdf_w <= 0.0 || sample.li == Color::ZERO {
        return None;
    }
    Some(LightPoint { choice, sample })
}

/// One light sample for the point `it` with BRDF `brdf`: the one-sample
/// estimate of the direct light (exercise 12 builds it), weighted by the
/// power heuristic against BRDF sampling if `mis`.
///
/// Draws as [`sample_light_point`].
#[inline]
pub fn sample_light(
    scene: &Scene,
    it: &Interaction,
    brdf: &Brdf,
    sampler: &mut Sampler,
    mis: bool,
) -> Color {
    sample_light_recorded(scene, it, brdf, sampler, mis, &mut NoRecorder, None)
}

/// [`sample_light`], with its shadow ray (blocked or not) recorded as
/// leaving the recorded vertex of `at`, its contribution scaled by the
/// throughput `β` of `at` by which the caller scales the result.
#[inline]
pub fn sample_light_recorded<R: Recorder>(
    scene: &Scene,
    it: &Interaction,
    brdf: &Brdf,
    sampler: &mut Sampler,
    mis: bool,
    rec: &mut R,
    at: Option<(VertexRef, Color)>,
) -> Color {
    let Some(LightPoint { choice, sample: ls }) = sample_light_point(scene, it.p, sampler) else {
        return Color::ZERO;
    };
    let wo = it.frame.to_local(it.wo);
    let wi = it.frame.to_local(ls.wi);
    let f = brdf.eval(wo, wi, it.uv);
    if f == Color::ZERO {
        return Color::ZERO;
    }
    let shadow = if ls.dist.is_finite() {
        it.spawn_ray_to(ls.p, ls.n)
    } else {
        it.spawn_ray(ls.wi)
    };
    let occluded = !scene.unoccluded(&shadow);
    let record = |rec: &mut R, weight: Option<f32>, c: Color| {
        if let Some(r) = rec.record() {
            if let Some((from, beta)) = at {
                r.push_segment(Some(from), |from| {
                    shadow_ray(from, ls.p, occluded, weight, beta * c)
                });
            }
        }
    };
    if occluded {
        record(rec, None, Color::ZERO);
        return Color::ZERO;
    }
    let pdf_light_w = choice.pmf * ls.pdf_w;
    // A point light cannot be hit by a BRDF sample: its sample takes all the weight.
    let weight = if ls.is_delta || !mis {
        1.0
    } else {
        power_heuristic(1.0, pdf_light_w, 1.0, brdf.pdf(wo, wi, it.uv))
    };
    let c = f * ls.li * (wi.z.abs() * weight / pdf_light_w);
    record(rec, Some(weight), c);
    c
}

/// The recorded shadow ray from `from` to the light point `p`.
fn shadow_ray(from: VertexRef, p: Vec3A, occluded: bool, w: Option<f32>, c: Color) -> Segment {
    Segment {
        kind: SegmentKind::ShadowRay,
        from,
        to: SegmentEnd::point(p),
        occluded,
        strategy: None,
        mis_weight: w,
        strategy_weights: None,
        contribution: c.to_array(),
        splat: None,
    }
}

/// The MIS weight of a (non-delta) BRDF sample that left the point `from` in
/// world direction `wi` with density `pdf_brdf_w` per unit solid angle and
/// found the emitter `e`: the counterpart of [`sample_light`]'s weight, with
/// the density light sampling would have had for the same direction,
/// `P(light) · p_ω`. A sample from a delta lobe has weight 1 (no light sample
/// could have produced it); callers handle that case.
#[inline]
pub fn brdf_sample_weight(
    scene: &Scene,
    from: Vec3A,
    pdf_brdf_w: f32,
    e: &EmitterHit,
    wi: Vec3A,
) -> f32 {
    let light = &scene.lights[e.light as usize];
    let pdf_light_w = scene.light_pmf(e.light) * light.pdf_li_w(from, e.p, e.n, wi);
    power_heuristic(1.0, pdf_brdf_w, 1.0, pdf_light_w)
}
