//! Path tracing: one random walk per sample, from the camera towards the lights.
//!
//! Lecture topic: "Path tracing". Instead of the naive recursion's N rays at
//! every hit (N^D rays per pixel), a path continues with exactly one
//! direction per bounce; many paths per pixel average out the noise (and
//! anti-alias the image for free). At every vertex the light arriving
//! directly from the emitters is estimated twice — by sampling a light (next
//! event estimation) and by the continuation ray happening to hit one — and
//! the two are combined by multiple importance sampling (power heuristic).
//!
//! The estimator of one path `x_0 … x_k`, with throughput
//! `β_k = Π f_r · |cos θ_i| / p(ω_i)`, adds `β_k · L_e` at each vertex; Russian
//! roulette ends the path with probability `1 − q` after `rr_depth` bounces and
//! divides the survivors' throughput by `q`, which keeps the estimate unbiased.
//!
//! Depth follows Mitsuba: with `max_depth = D`, a path has at most `D − 1`
//! scattering vertices (D = 1: only emitters seen directly).

use super::continuation::sample_continuation;
use super::record::{NoRecorder, PathRecord, PathRole, PathVertex, Pdf, Recorder};
use super::roulette::russian_roulette;
use super::{Integrator, camera_ray, nee};
use crate::brdf::TransportMode;
use crate::film::Splat;
use crate::math::{Color, UVec2, Vec3A};
use crate::sampling::Sampler;
use crate::scene::Scene;

/// Which estimators of direct light the path tracer uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum DirectStrategy {
    /// Light sampling and BRDF sampling combined by MIS (the default).
    #[default]
    Mis,
    /// BRDF sampling only: light is found only when a path happens to hit it
    /// (hopeless for small lights, impossible for point lights).
    BrdfOnly,
    /// Light sampling only, without MIS: the BRDF-sampled path counts emitters
    /// only after a delta bounce (noisy on glossy surfaces under large lights).
    LightOnly,
}

/// The BRDF sample that sent the path's current ray: what the MIS weight of
/// an emitter the ray hits needs.
#[derive(Clone, Copy, Debug)]
struct PreviousBounce {
    /// Where the ray left.
    p: Vec3A,
    /// Density of its direction per unit solid angle.
    pdf_w: f32,
    /// Whether it came from a delta lobe (no light sample could have found
    /// the same light: weight 1).
    is_delta: bool,
}

/// The path tracer.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PathTracer {
    /// Maximum depth (Mitsuba's convention); `None` = unlimited.
    pub max_depth: Option<u32>,
    /// Russian roulette starts once this many bounces have been made.
    pub rr_depth: u32,
    pub strategy: DirectStrategy,
}

impl Default for PathTracer {
    fn default() -> Self {
        PathTracer {
            max_depth: None,
            rr_depth: 5,
            strategy: DirectStrategy::Mis,
        }
    }
}

impl Integrator for PathTracer {
    fn name(&self) -> &'static str {
        match self.strategy {
            DirectStrategy::Mis => "path",
            DirectStrategy::BrdfOnly => "path-brdf",
            DirectStrategy::LightOnly => "path-nee",
        }
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

impl PathTracer {
    /// One path, its vertices, emitter hits and shadow rays handed to `rec`.
    fn trace<R: Recorder>(
        &self,
        scene: &Scene,
        pixel: UVec2,
        sampler: &mut Sampler,
        rec: &mut R,
    ) -> Color {
        let max_depth = super::max_segments(self.max_depth);
        let use_nee = self.strategy != DirectStrategy::BrdfOnly;
        let mut ray = camera_ray(scene, pixel, sampler);
        // The recorded vertex the path is at (always `None` when not recording).
        let mut at = rec.record().and_then(|r| {
            r.start_path(
                PathRole::Camera,
                None,
                PathVertex::camera(ray.o, Color::ONE),
            )
        });
        let mut l = Color::ZERO;
        let mut beta = Color::ONE;
        // Relative IOR accumulated along the path (radiance is scaled by 1/η²
        // through glass; roulette undoes that to judge the path fairly).
        let mut eta_scale = 1.0f32;
        // The BRDF sample that produced `ray` (none for the camera ray).
        let mut prev: Option<PreviousBounce> = None;
        let mut depth = 0u32;
        if max_depth == 0 {
            return l;
        }
        loop {
            // Without a depth limit or roulette a path may bounce for ever
            // (a closed white furnace): a stop request ends it.
            if depth % 64 == 63 && super::stop::stop_requested() {
                break;
            }
            let hit = scene.intersect(&ray);
            if let Some(r) = rec.record() {
                let pdf = match prev {
                    Some(b) => Pdf::direction(b.pdf_w, b.is_delta),
                    None => Pdf::direction(scene.camera.pdf_we(&ray).pdf_w, false),
                };
                at = r.push_vertex(at, PathVertex::hit(scene, &ray, hit.as_ref(), pdf, beta));
            }
            // Emitted light reached by the ray (counted while depth < max_depth).
            if let Some(e) = scene.emitter_hit(&ray, hit.as_ref()) {
                let weight = match (&prev, self.strategy) {
                    (None, _)
                    | (Some(PreviousBounce { is_delta: true, .. }), _)
                    | (Some(_), DirectStrategy::BrdfOnly) => 1.0,
                    (Some(_), DirectStrategy::LightOnly) => 0.0,
                    (Some(b), DirectStrategy::Mis) => {
                        nee::brdf_sample_weight(scene, b.p, b.pdf_w, &e, ray.d)
                    }
                };
                l += beta * e.le * weight;
                if let Some(r) = rec.record() {
                    r.contribute(at, beta * e.le * weight, Some(weight));
                }
            }
            let Some(it) = hit else { break };
            if depth + 1 >= max_depth {
                break;
            }
            let brdf = scene.brdf(&it);
            if use_nee {
                let mis = self.strategy == DirectStrategy::Mis;
                l += beta
                    * nee::sample_light_recorded(
                        scene,
                        &it,
                        brdf,
                        sampler,
                        mis,
                        rec,
                        at.map(|v| (v, beta)),
                    );
            }
            // Continue the path in one direction sampled from the BRDF.
            let Some(c) = sample_continuation(&it, brdf, TransportMode::Radiance, sampler) else {
                break;
            };
            beta *= c.weight;
            eta_scale *= c.sample.eta * c.sample.eta;
            ray = c.ray;
            prev = Some(PreviousBounce {
                p: it.p,
                pdf_w: c.sample.pdf_w,
                is_delta: c.sample.is_delta,
            });
            depth += 1;
            // Russian roulette (unbiased: survivors are divided by q).
            if depth >= self.rr_depth {
                let Some(q) = russian_roulette(beta, eta_scale, sampler) else {
                    break;
                };
                beta /= q;
            }
        }
        l
    }
}
