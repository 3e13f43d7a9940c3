//! The shading stage: at every live path's hit, the emitted light (weighted
//! by MIS), a light sample (its shadow ray queued), the BRDF sample that
//! continues the path, and Russian roulette.
//!
//! Lecture topic: path tracing with next event estimation. The arithmetic is
//! `path`'s step for step, and each path draws the same random numbers in the
//! same order (light choice, light point, BRDF lobe, BRDF direction,
//! roulette): only *when* the shadow ray is traced changes, and it draws no
//! number. So both engines compute the same estimate, sample for sample.

use super::queue::{PathQueue, PreviousBounce, ShadowQueue};
use crate::brdf::{Brdf, TransportMode};
use crate::geometry::Interaction;
use crate::integrator::continuation::sample_continuation;
use crate::integrator::nee::{self, LightPoint};
use crate::integrator::roulette::russian_roulette;
use crate::math::{Color, Ray};
use crate::sampling::{Sampler, power_heuristic};
use crate::scene::Scene;

/// The depth settings of the path tracer (Mitsuba's convention, as `path`).
#[derive(Clone, Copy, Debug)]
pub struct Depths {
    /// At most `max_depth − 1` scattering vertices.
    pub max_depth: u32,
    /// Roulette from this many bounces on.
    pub rr_depth: u32,
}

/// Shades every live path; queues the light samples' shadow rays in
/// `shadows` and marks the paths that end.
pub fn shade(scene: &Scene, depths: Depths, queue: &mut PathQueue, shadows: &mut ShadowQueue) {
    shadows.clear();
    for &slot in &queue.live {
        let s = slot as usize;
        let hit = queue.hit[s].take();
        let ray = queue.ray[s];
        // Emitted light reached by the ray, weighted against light sampling.
        if let Some(e) = scene.emitter_hit(&ray, hit.as_ref()) {
            let weight = match queue.prev[s] {
                None | Some(PreviousBounce { is_delta: true, .. }) => 1.0,
                Some(b) => nee::brdf_sample_weight(scene, b.p, b.pdf_w, &e, ray.d),
            };
            queue.l[s] += queue.beta[s] * e.le * weight;
        }
        let Some(it) = hit else {
            queue.alive[s] = false;
            continue;
        };
        if queue.depth[s] + 1 >= depths.max_depth {
            queue.alive[s] = false;
            continue;
        }
        let brdf = scene.brdf(&it);
        let sampler = &mut queue.sampler[s];
        if let Some((shadow, c)) = light_sample(scene, &it, brdf, sampler) {
            shadows.push(slot, shadow, queue.beta[s] * c);
        }
        // Continue in one direction sampled from the BRDF.
        let Some(c) = sample_continuation(&it, brdf, TransportMode::Radiance, sampler) else {
            queue.alive[s] = false;
            continue;
        };
        queue.beta[s] *= c.weight;
        queue.eta_scale[s] *= c.sample.eta * c.sample.eta;
        queue.ray[s] = c.ray;
        queue.prev[s] = Some(PreviousBounce {
            p: it.p,
            pdf_w: c.sample.pdf_w,
            is_delta: c.sample.is_delta,
        });
        queue.depth[s] += 1;
        if queue.depth[s] >= depths.rr_depth {
            match russian_roulette(queue.beta[s], queue.eta_scale[s], sampler) {
                Some(q) => queue.beta[s] /= q,
                None => queue.alive[s] = false,
            }
        }
    }
}

/// Next event estimation without its shadow test: the shadow ray and what
/// the light sample brings if the ray is unblocked,
/// `f_r L_e |cos θ_i| w / (P(light) p_ω)` with the power heuristic's `w`
/// (as [`nee::sample_light`], which traces the ray at once). `None` if the
/// sample brings nothing whatever the ray meets.
#[inline]
fn light_sample(
    scene: &Scene,
    it: &Interaction,
    brdf: &Brdf,
    sampler: &mut Sampler,
) -> Option<(Ray, Color)> {
    let LightPoint { choice, sample: ls } = nee::sample_light_point(scene, it.p, sampler)?;
    let wo = it.frame.to_local(it.wo);
    let wi = it.frame.to_local(ls.wi);
    let f = brdf.eval(wo, wi, it.uv);
    if f == Color::ZERO {
        return None;
    }
    let shadow = if ls.dist.is_finite() {
        it.spawn_ray_to(ls.p, ls.n)
    } else {
        it.spawn_ray(ls.wi)
    };
    let pdf_light_w = choice.pmf * ls.pdf_w;
    // A point light cannot be hit by a BRDF sample: its sample takes all the weight.
    let weight = if ls.is_delta {
        1.0
    } else {
        power_heuristic(1.0, pdf_light_w, 1.0, brdf.pdf(wo, wi, it.uv))
    };
    Some((shadow, f * ls.li * (wi.z.abs() * weight / pdf_light_w)))
}
