//! Exercise 10: naive recursive Monte Carlo around the student's
//! `naive_radiance`.

use raytracer::film::Splat;
use raytracer::integrator::{Integrator, camera_ray};
use raytracer::math::{Color, UVec2};
use raytracer::sampling::Sampler;
use raytracer::scene::Scene;

use crate::ex10_naive_recursive;

/// Naive recursive Monte Carlo with the student's `naive_radiance` (exercise 10).
#[derive(Clone, Copy, Debug)]
pub struct StudentNaive {
    pub max_depth: u32,
    pub branching: u32,
}

impl Integrator for StudentNaive {
    fn name(&self) -> &'static str {
        "student-naive"
    }

    fn sample(
        &self,
        scene: &Scene,
        pixel: UVec2,
        sampler: &mut Sampler,
        _: &mut Vec<Splat>,
    ) -> Color {
        let ray = camera_ray(scene, pixel, sampler);
        ex10_naive_recursive::naive_radiance(
            scene,
            &ray,
            0,
            self.max_depth,
            self.branching,
            sampler,
        )
    }
}
