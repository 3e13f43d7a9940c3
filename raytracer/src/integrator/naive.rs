//! Naive recursive Monte Carlo: the rendering equation solved as written.
//!
//! Lecture topic: "Решаване чрез Monte Carlo метод" — at a hit point `x`,
//! shoot N random directions `ω_k`, find what each one sees (another instance
//! of the same equation, solved the same way) and average:
//!
//! `L_o(x, ω_o) ≈ L_e(x, ω_o) + (1/N) Σ_k f_r(x, ω_k, ω_o) · L_i(x, ω_k) · |cos θ_k| / p(ω_k)`
//!
//! The recursion ends when a ray escapes, when the depth limit is reached,
//! optionally when the product of the BRDF weights along the recursion falls
//! below a threshold (the lecture's idea; it is *biased*: the light it
//! ignores is small but not zero), or by Russian roulette (unbiased). With N
//! branches per level a pixel sample costs about `N^D` rays — the
//! combinatorial explosion that path tracing (N = 1, many samples per pixel)
//! avoids. The lecture's variant "many rays at the top, few below" is a
//! branching factor per level. The integrator counts every ray it traces.

use std::sync::atomic::{AtomicU64, Ordering};

use super::continuation::sample_continuation;
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
    pub branching: Vec<u32>,
    /// Maximum depth (Mitsuba's convention, as the path tracer); `None` = unlimited
    /// (then `roulette` must end the recursion).
    pub max_depth: Option<u32>,
    /// Stop recursing once the largest channel of the product of BRDF weights
    /// `Π f_r |cos θ| / p` (each level divided by its N) is below this (biased).
    pub cutoff: Option<f32>,
    /// Russian roulette from this depth on (unbiased), if set.
    pub roulette_depth: Option<u32>,
    rays: AtomicU64,
}

impl NaiveRecursive {
    pub fn new(branching: Vec<u32>, max_depth: Option<u32>) -> Self {
        assert!(
            !branching.is_empty() && branching.iter().all(|&n| n > 0),
            "branching factors must be ≥ 1"
        );
        NaiveRecursive {
            branching,
            max_depth,
            cutoff: None,
            roulette_depth: None,
            rays: AtomicU64::new(0),
        }
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

    fn radiance(
        &self,
        scene: &Scene,
        ray: &Ray,
        depth: u32,
        product: Color,
        sampler: &mut Sampler,
        rays: &mut u64,
    ) -> Color {
        // N^D rays can take minutes: a stop request ends the sample at once.
        if stop_requested() {
            return Color::ZERO;
        }
        *rays += 1;
        let Some(it) = scene.intersect(ray) else {
            return scene.escaped_radiance(ray.d);
        };
        let mut l = scene.emitted(&it);
        if depth + 1 >= self.max_depth.unwrap_or(u32::MAX) {
            return l;
        }
        if self.cutoff.is_some_and(|c| product.max_element() < c) {
            return l;
        }
        let brdf = scene.brdf(&it);
        let n = self.branching_at(depth);
        let mut sum = Color::ZERO;
        for _ in 0..n {
            let Some(c) = sample_continuation(&it, brdf, TransportMode::Radiance, sampler) else {
                continue;
            };
            let mut weight = c.weight;
            if self.roulette_depth.is_some_and(|d| depth + 1 >= d) {
                // Judged by the product of the weights down to here (each
                // level's 1/N included), with no η correction.
                let Some(q) = russian_roulette(product * weight, 1.0, sampler) else {
                    continue;
                };
                weight /= q;
            }
            sum += weight
                * self.radiance(
                    scene,
                    &c.ray,
                    depth + 1,
                    product * weight / n as f32,
                    sampler,
                    rays,
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
        let ray = camera_ray(scene, pixel, sampler);
        let mut rays = 0u64;
        let l = self.radiance(scene, &ray, 0, Color::ONE, sampler, &mut rays);
        self.rays.fetch_add(rays, Ordering::Relaxed);
        l
    }
}
