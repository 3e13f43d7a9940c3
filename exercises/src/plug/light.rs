//! Exercise 14: light tracing around the student's `trace_light_path`, and the
//! lens point it joins vertices to.

use raytracer::camera::Camera;
use raytracer::film::Splat;
use raytracer::integrator::Integrator;
use raytracer::math::{Color, UVec2, Vec2, Vec3A};
use raytracer::sampling::Sampler;
use raytracer::scene::Scene;

use crate::ex14_light_tracing;

/// A point on the camera's lens, where light tracing joins a light-path
/// vertex to the camera (exercise 14).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LensPoint {
    /// The point, in world space.
    pub p: Vec3A,
    /// Its density per unit area of the lens. A pinhole is a single point,
    /// taken as a lens of area 1 (density 1), as [`Camera::we`] counts it.
    pub pdf_a: f32,
}

/// A lens point chosen by `u_lens`, uniformly on the lens disk of a thin-lens
/// camera (the centre of a pinhole). The lens faces along `Camera::forward`.
pub fn sample_lens(camera: &Camera, u_lens: Vec2) -> LensPoint {
    // The lens point of any primary ray drawn with u_lens: the one through
    // the film's centre.
    let centre = Vec2::new(camera.width as f32, camera.height as f32) * 0.5;
    let ray = camera.generate_ray(centre, u_lens);
    LensPoint {
        p: ray.o,
        pdf_a: camera.pdf_we(&ray).pdf_a,
    }
}

/// The signature of exercise 14's `trace_light_path`.
pub type LightPathFn = fn(&Scene, &mut Sampler, Option<u32>, u32, &mut Vec<Splat>);

/// The light tracer around a `trace_light_path` (exercise 14; the student's
/// with [`StudentLightTracer::new`]): every pixel sample traces one light
/// path and returns 0 — everything it finds, the lights seen directly
/// included, reaches the film as splats, which the film scales by `W·H/M`
/// (M pixel samples in all), as for the renderer's `LightTracer`.
#[derive(Clone, Copy, Debug)]
pub struct StudentLightTracer {
    pub trace_light_path: LightPathFn,
    pub max_depth: Option<u32>,
    pub rr_depth: u32,
}

impl StudentLightTracer {
    /// The student's light tracer.
    pub fn new(max_depth: Option<u32>, rr_depth: u32) -> Self {
        StudentLightTracer {
            trace_light_path: ex14_light_tracing::trace_light_path,
            max_depth,
            rr_depth,
        }
    }
}

impl Integrator for StudentLightTracer {
    fn name(&self) -> &'static str {
        "student-light"
    }

    fn sample(
        &self,
        scene: &Scene,
        _: UVec2,
        sampler: &mut Sampler,
        splats: &mut Vec<Splat>,
    ) -> Color {
        (self.trace_light_path)(scene, sampler, self.max_depth, self.rr_depth, splats);
        Color::ZERO
    }
}
