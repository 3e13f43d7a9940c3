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
use super::record::{NoRecorder, PathRecord, PathRole, PathVertex, Pdf, Recorder};
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
        self.trace(scene, pixel, sampler, &mut NoRecorder)
    }

    fn sample_recorded(
        &self,
        scene: &Scene,
        pixel: UVec2,
        sampler: &mut Sampler,
        _splats: &mut Vec<Splat>,
        record: &mut PathRecord,
    ) -> Color {
        self.trace(scene, pixel, sampler, record)
    }
}

impl Direct {
    /// One sample, its hit, shadow ray and BRDF ray handed to `rec`.
    fn trace<R: Recorder>(
        &self,
        scene: &Scene,
        pixel: UVec2,
        sampler: &mut Sampler,
        rec: &mut R,
    ) -> Color {
        let ray = camera_ray(scene, pixel, sampler);
        let hit = scene.intersect(&ray);
        let at = rec.record().and_then(|r| {
            let lens = r.start_path(
                PathRole::Camera,
                None,
                PathVertex::camera(ray.o, Color::ONE),
            );
            let pdf = Pdf::direction(scene.camera.pdf_we(&ray).pdf_w, false);
            r.push_vertex(
                lens,
                PathVertex::hit(scene, &ray, hit.as_ref(), pdf, Color::ONE),
            )
        });
        let Some(it) = hit else {
            let le = scene.escaped_radiance(ray.d);
            if let Some(r) = rec.record() {
                r.contribute(at, le, None);
            }
            return le;
        };
        // L_e seen directly (depth 1).
        let mut l = scene.emitted(&it);
        if let Some(r) = rec.record() {
            r.contribute(at, l, None);
        }
        let brdf = scene.brdf(&it);

        // Light sampling.
        let at_beta = at.map(|v| (v, Color::ONE));
        l += nee::sample_light_recorded(scene, &it, brdf, sampler, true, rec, at_beta);

        // BRDF sampling: follow one direction and see whether it reaches a light.
        let Some(c) = sample_continuation(&it, brdf, TransportMode::Radiance, sampler) else {
            return l;
        };
        let next = scene.intersect(&c.ray);
        let next_at = rec.record().and_then(|r| {
            let pdf = Pdf::direction(c.sample.pdf_w, c.sample.is_delta);
            r.push_vertex(
                at,
                PathVertex::hit(scene, &c.ray, next.as_ref(), pdf, c.weight),
            )
        });
        if let Some(e) = scene.emitter_hit(&c.ray, next.as_ref()) {
            let w = if c.sample.is_delta {
                1.0
            } else {
                nee::brdf_sample_weight(scene, it.p, c.sample.pdf_w, &e, c.wi)
            };
            l += c.weight * e.le * w;
            if let Some(r) = rec.record() {
                r.contribute(next_at, c.weight * e.le * w, Some(w));
            }
        }
        l
    }
}
