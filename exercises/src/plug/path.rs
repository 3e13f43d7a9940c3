//! Exercises 11–13: the path tracer around the student's `path_radiance` (BRDF
//! sampling, next event estimation, MIS), and exercise 12's direct light.

use raytracer::film::Splat;
use raytracer::integrator::{Integrator, camera_ray};
use raytracer::math::{Color, Ray, UVec2};
use raytracer::sampling::Sampler;
use raytracer::scene::{Interaction, Scene};

use crate::{ex11_path_tracing, ex12_nee};

/// The signature of exercise 11's `path_radiance` (and of exercise 12's
/// `path_radiance_nee` and exercise 13's `path_radiance_mis`).
pub type PathRadianceFn = fn(&Scene, Ray, Option<u32>, u32, &mut Sampler) -> Color;

/// The signature of exercise 12's `estimate_direct`.
pub type EstimateDirectFn = fn(&Scene, &Interaction, &mut Sampler) -> Color;

/// The path tracer around a `path_radiance` (exercise 11): the student's with
/// [`StudentPathTracer::new`], or any other with the same signature (the
/// student's NEE and MIS path tracers of exercises 12 and 13, the grader's
/// fixtures).
#[derive(Clone, Copy, Debug)]
pub struct StudentPathTracer {
    pub path_radiance: PathRadianceFn,
    pub max_depth: Option<u32>,
    pub rr_depth: u32,
}

impl StudentPathTracer {
    /// The student's path tracer.
    pub fn new(max_depth: Option<u32>, rr_depth: u32) -> Self {
        StudentPathTracer {
            path_radiance: ex11_path_tracing::path_radiance,
            max_depth,
            rr_depth,
        }
    }
}

impl Integrator for StudentPathTracer {
    fn name(&self) -> &'static str {
        "student-path"
    }

    fn sample(
        &self,
        scene: &Scene,
        pixel: UVec2,
        sampler: &mut Sampler,
        _: &mut Vec<Splat>,
    ) -> Color {
        let ray = camera_ray(scene, pixel, sampler);
        (self.path_radiance)(scene, ray, self.max_depth, self.rr_depth, sampler)
    }
}

/// Direct light by next event estimation only, around an `estimate_direct`
/// (exercise 12; the student's by `Default`): emitters seen directly plus one
/// light sample at the first hit (the renderer's `PathTracer` with
/// `max_depth = 2` and `DirectStrategy::LightOnly` computes the same).
#[derive(Clone, Copy, Debug)]
pub struct StudentDirect(pub EstimateDirectFn);

impl Default for StudentDirect {
    fn default() -> Self {
        StudentDirect(ex12_nee::estimate_direct)
    }
}

impl Integrator for StudentDirect {
    fn name(&self) -> &'static str {
        "student-direct"
    }

    fn sample(
        &self,
        scene: &Scene,
        pixel: UVec2,
        sampler: &mut Sampler,
        _: &mut Vec<Splat>,
    ) -> Color {
        let ray = camera_ray(scene, pixel, sampler);
        let Some(it) = scene.intersect(&ray) else {
            return scene.escaped_radiance(ray.d);
        };
        scene.emitted(&it) + (self.0)(scene, &it, sampler)
    }
}
