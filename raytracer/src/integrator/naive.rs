//! Naive recursive Monte Carlo: the rendering equation solved as written.
//!
//! Lecture topic: "Решаване чрез Monte Carlo метод" — at a hit point `x`,
//! shoot N random directions `ω_k`, find what each one sees (another instance
//! of the same equation, solved the same way) and average: the slide's
//! general estimator `(1/N) Σ_k g(ω_k)/p(ω_k)` applied to the integral of the
//! rendering equation (exercise 10 derives the line; `exercises/INSTRUCTOR.md`
//! has it).
//!
//! The recursion ends when a ray escapes, when the depth limit is reached,
//! optionally when the product of the BRDF weights along the recursion falls
//! below a threshold (the lecture's idea; it is *biased*: the light it
//! ignores is small but not zero), or by Russian roulette (unbiased), which
//! judges a branch by what it carries, not by its share `1/N` of the split
//! it belongs to. With N
//! branches per level a pixel sample costs about `N^D` rays — the
//! combinatorial explosion that path tracing (N = 1, many samples per pixel)
//! avoids. The lecture's variant "many rays at the top, few below" is a
//! branching factor per level. The integrator counts every ray it traces.

use std::sync::atomic::{AtomicU64, Ordering};

use super::continuation::sample_continuation;
use super::record::{NoRecorder, PathRecord, PathRole, PathVertex, Pdf, Recorder, VertexRef};
use super::roulette::russian_roulette;
use super::stop::stop_requested;
use super::{Integrator, camera_ray};
use crate::brdf::TransportMode;
use crate::film::Splat;
use crate::math::{Color, Ray, UVec2};
use crate::sampling::Sampler;
use crate::scene::Scene;

/// The naive recursive estimator.
#[derive(Debug)]
pub struct NaiveRecursive {
    /// Branching factor per recursion level: `branching[d]` rays leave a hit
    /// at depth `d`; the last entry repeats for deeper levels.
    branching: Vec<u32>,
    /// Maximum depth (Mitsuba's convention, as the path tracer); `None` =
    /// unlimited (then the roulette or the cutoff ends the recursion).
    max_depth: Option<u32>,
    /// Stop recursing once the largest channel of the product of BRDF weights
    /// `Π f_r |cos θ| / p` (each level divided by its N) is below this (biased).
    cutoff: Option<f32>,
    /// Russian roulette from this depth on (unbiased), if set.
    roulette_depth: Option<u32>,
    rays: AtomicU64,
}

impl NaiveRecursive {
    /// The recursion with `branching` factors, bounded by the max depth `D`.
    ///
    /// # Panics
    /// If a branching factor is 0 or there is none, or `max_depth` is `None`:
    /// an unlimited recursion needs an end, [`NaiveRecursive::try_new`].
    pub fn new(branching: Vec<u32>, max_depth: Option<u32>) -> Self {
        Self::try_new(branching, max_depth, None, None).unwrap_or_else(|e| panic!("{e}"))
    }

    /// The recursion with `branching` factors, max depth `max_depth`,
    /// Russian roulette from depth `roulette_depth` on and the lecture's
    /// `cutoff`, if set. Refuses a recursion that would not end: with
    /// unlimited depth, the last branching factor `N` repeats at every level
    /// below, and
    /// - without roulette or cutoff nothing ends it;
    /// - with roulette alone and `N ≥ 2`, a ray survives with `q` near the
    ///   albedo and has `N q > 1` children on average where `N > 1/q`: the
    ///   tree grows without end (roulette ends a path, `N = 1`, for sure);
    /// - with the cutoff alone and `N = 1`, a white surface keeps the product
    ///   of weights at 1 for ever (each level's `1/N ≤ 1/2` shrinks it for
    ///   `N ≥ 2`).
    ///
    /// Also refuses a factor of 0, no factor, and a cutoff that is not a
    /// number ≥ 0.
    pub fn try_new(
        branching: Vec<u32>,
        max_depth: Option<u32>,
        roulette_depth: Option<u32>,
        cutoff: Option<f32>,
    ) -> Result<Self, String> {
        if branching.is_empty() || branching.contains(&0) {
            return Err(format!("branching factors must be ≥ 1, got {branching:?}"));
        }
        if let Some(c) = cutoff
            && !(c.is_finite() && c >= 0.0)
        {
            return Err(format!("the cutoff must be a number ≥ 0, got {c}"));
        }
        if max_depth.is_none() {
            let last = *branching.last().unwrap();
            let ends = match (roulette_depth, cutoff) {
                (Some(_), _) if last == 1 => true,
                (_, Some(_)) if last >= 2 => true,
                _ => false,
            };
            if !ends {
                return Err(format!(
                    "naive recursion with unlimited depth and branching {branching:?} never ends: \
                     give a max depth, or end the branching with 1 and use Russian roulette \
                     (the last factor repeats at every deeper level; roulette ends a single \
                     path, not a tree whose rays have {last} children each), or use the cutoff \
                     with a last factor ≥ 2"
                ));
            }
        }
        Ok(NaiveRecursive {
            branching,
            max_depth,
            cutoff,
            roulette_depth,
            rays: AtomicU64::new(0),
        })
    }

    /// The branching factors (the last repeats).
    pub fn branching(&self) -> &[u32] {
        &self.branching
    }

    /// The max depth D (`None`: unlimited).
    pub fn max_depth(&self) -> Option<u32> {
        self.max_depth
    }

    /// The depth from which Russian roulette plays, if it does.
    pub fn roulette_depth(&self) -> Option<u32> {
        self.roulette_depth
    }

    /// The lecture's cutoff, if set.
    pub fn cutoff(&self) -> Option<f32> {
        self.cutoff
    }

    /// Rays traced so far (camera rays included).
    pub fn rays_traced(&self) -> u64 {
        self.rays.load(Ordering::Relaxed)
    }

    /// The number of rays one pixel sample traces when every ray hits a
    /// surface and nothing ends the recursion early: `Σ_{d=0}^{D−1} Π_{k<d} N_k`
    /// (1 camera ray, N_0 rays from its hit, N_0 N_1 from theirs, ...).
    pub fn rays_per_sample_bound(&self) -> Option<u64> {
        let d = self.max_depth?;
        let mut total = 0u64;
        let mut level = 1u64;
        for depth in 0..d {
            total = total.saturating_add(level);
            level = level.saturating_mul(self.branching_at(depth) as u64);
        }
        Some(total)
    }

    #[inline]
    fn branching_at(&self, depth: u32) -> u32 {
        self.branching[(depth as usize).min(self.branching.len() - 1)]
    }

    /// `L_o` along `ray` at recursion depth `depth`. `throughput` is the
    /// product of the BRDF weights `Π f_r |cos θ| / p` down to here, without
    /// the levels' `1/N`, and `product` the same with them (each branch's
    /// share of the pixel's estimate).
    /// `rec` receives the ray's hit (a new path of the tree hanging from
    /// `from.parent`, or the camera path's next vertex at depth 0) and
    /// what it adds to the estimate, `product · L_e`.
    #[allow(clippy::too_many_arguments)]
    fn radiance<R: Recorder>(
        &self,
        scene: &Scene,
        ray: &Ray,
        depth: u32,
        throughput: Color,
        product: Color,
        sampler: &mut Sampler,
        rays: &mut u64,
        (rec, from): (&mut R, RecordedRay),
    ) -> Color {
        // N^D rays can take minutes: a stop request ends the sample at once.
        if stop_requested() {
            return Color::ZERO;
        }
        *rays += 1;
        let hit = scene.intersect(ray);
        let at = rec.record().and_then(|r| {
            let v = PathVertex::hit(scene, ray, hit.as_ref(), from.pdf, product);
            match depth {
                0 => r.push_vertex(from.parent, v),
                _ => r.start_path(PathRole::Branch, from.parent, v),
            }
        });
        let Some(it) = hit else {
            let le = scene.escaped_radiance(ray.d);
            if let Some(r) = rec.record() {
                r.contribute(at, product * le, None);
            }
            return le;
        };
        let mut l = scene.emitted(&it);
        if let Some(r) = rec.record() {
            r.contribute(at, product * l, None);
        }
        if depth + 1 >= super::max_segments(self.max_depth) {
            return l;
        }
        if self.cutoff.is_some_and(|c| product.max_element() < c) {
            return l;
        }
        let brdf = scene.brdf(&it);
        let n = self.branching_at(depth);
        let mut sum = Color::ZERO;
        for _ in 0..n {
            // A branch that finds the stop request returns at once, but
            // N = 2³² siblings would still be sampled one by one.
            if stop_requested() {
                return Color::ZERO;
            }
            let Some(c) = sample_continuation(&it, brdf, TransportMode::Radiance, sampler) else {
                continue;
            };
            let mut weight = c.weight;
            if self.roulette_depth.is_some_and(|d| depth + 1 >= d) {
                // Judged by what the branch carries, without the 1/N of
                // the levels above: the N siblings of a split share the
                // light between them, and a survival probability that
                // counted the 1/N (as once) killed most of them right
                // after the split, undoing it. No η correction.
                let Some(q) = russian_roulette(throughput * weight, 1.0, sampler) else {
                    continue;
                };
                weight /= q;
            }
            let child = RecordedRay {
                parent: at,
                pdf: Pdf::direction(c.sample.pdf_w, c.sample.is_delta),
            };
            sum += weight
                * self.radiance(
                    scene,
                    &c.ray,
                    depth + 1,
                    throughput * weight,
                    product * weight / n as f32,
                    sampler,
                    rays,
                    (&mut *rec, child),
                );
        }
        l += sum / n as f32;
        l
    }
}

impl Integrator for NaiveRecursive {
    fn name(&self) -> &'static str {
        "naive"
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

/// Where a ray of the recursion is recorded: the recorded vertex it leaves
/// and the density of its direction.
#[derive(Clone, Copy, Debug)]
struct RecordedRay {
    parent: Option<VertexRef>,
    pdf: Pdf,
}

impl NaiveRecursive {
    /// One pixel sample's recursion, its tree handed to `rec`.
    fn trace<R: Recorder>(
        &self,
        scene: &Scene,
        pixel: UVec2,
        sampler: &mut Sampler,
        rec: &mut R,
    ) -> Color {
        let ray = camera_ray(scene, pixel, sampler);
        let mut rays = 0u64;
        let from = match rec.record() {
            Some(r) => RecordedRay {
                parent: r.start_path(
                    PathRole::Camera,
                    None,
                    PathVertex::camera(ray.o, Color::ONE),
                ),
                pdf: Pdf::direction(scene.camera.pdf_we(&ray).pdf_w, false),
            },
            None => RecordedRay {
                parent: None,
                pdf: Pdf::direction(0.0, false),
            },
        };
        let (one, rec) = (Color::ONE, (rec, from));
        let l = self.radiance(scene, &ray, 0, one, one, sampler, &mut rays, rec);
        self.rays.fetch_add(rays, Ordering::Relaxed);
        l
    }
}
