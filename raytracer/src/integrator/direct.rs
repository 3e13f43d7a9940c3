//! Direct lighting: light that reaches the camera after exactly one bounce.
//!
//! Lecture topic: what local illumination computes, and the first term of the
//! rendering equation's recursion. With Mitsuba's depth convention this is
//! `max_depth = 2`: emitters seen directly, plus light that travels
//! light → surface → camera. Both ways of finding that light are used and
//! combined with MIS (power heuristic): a sample on a light (next event
//! estimation, best for small lights and rough surfaces) and a sample of the
//! BRDF (best for large lights and glossy or mirror surfaces).

use super::continuation::sample_continuation;
use super::{Integrator, camera_ray, nee};
use crate::brdf::TransportMode;
use crate::film::Splat;
use crate::math::{Color, UVec2};
use crate::sampling::Sampler;
use crate::scene::Scene;

/// Direct lighting with next event estimation and BRDF sampling under MIS.
#[derive(Clone, Copy, Debug, Default)]
pub struct Direct;

impl Integrator for Direct {
    fn name(&self) -> &'static str {
        "direct"
    }

    fn sample(
        &self,
        scene: &Scene,
        pixel: UVec2,
        sampler: &mut Sampler,
        _splats: &mut Vec<Splat>,
    ) -> Color {
        let ray = camera_ray(scene, pixel, sampler);
        let Some(it) = scene.intersect(&ray) else {
            return scene.escaped_radiance(ray.d);
        };
        // L_e seen directly (depth 1).
        let mut l = scene.emitted(&it);
        let brdf = scene.brdf(&it);

        // Light sampling.
        l += nee::sample_light(scene, &it, brdf, sampler, true);

        // BRDF sampling: follow one direction and see whether it reaches a light.
        let Some(c) = sample_continuation(&it, brdf, TransportMode::Radiance, sampler) else {
            return l;
        };
        let next = scene.intersect(&c.ray);
        if let Some(e) = scene.emitter_hit(&c.ray, next.as_ref()) {
            let w = if c.sample.is_delta {
                1.0
            } else {
                nee::brdf_sample_weight(scene, it.p, c.sample.pdf_w, &e, c.wi)
            };
            l += c.weight * e.le * w;
        }
        l
    }
}
