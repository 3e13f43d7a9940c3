//! Which engine runs the path tracer: the lecture's `path`, one path at a
//! time, or `raytracer::wavefront`, all of a tile's paths in lockstep. Both
//! compute the same samples (the same image bit for bit for a seed); only
//! the speed differs.

use clap::ValueEnum;
use raytracer::integrator::PathTracer;
use raytracer::render::{RenderOptions, RenderResult, render};
use raytracer::scene::Scene;
use raytracer::wavefront::{Unsupported, WavefrontPathTracer};

/// The engine of `--integrator path`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, ValueEnum)]
pub enum Engine {
    /// The lecture's path tracer: one path from the camera to its end, then the next.
    #[default]
    Scalar,
    /// The wavefront engine: a tile's paths in lockstep, one stage at a time (same image, faster).
    Wavefront,
}

impl Engine {
    /// The engine that renders the tour's pictures where the chapter is not
    /// about the integrator's code (the same image either way): the
    /// wavefront engine, 0.96× the scalar engine's CPU time on the Cornell
    /// box (see the README's performance section).
    pub const FASTEST: Engine = Engine::Wavefront;

    /// Checks that this engine runs `path` as configured (before rendering).
    pub fn check(self, path: &PathTracer) -> Result<(), Unsupported> {
        match self {
            Engine::Scalar => Ok(()),
            Engine::Wavefront => WavefrontPathTracer::from_path(path).map(|_| ()),
        }
    }

    /// Renders `scene` with `path` on this engine.
    pub fn render(
        self,
        scene: &Scene,
        path: &PathTracer,
        options: &RenderOptions,
    ) -> Result<RenderResult, Unsupported> {
        Ok(match self {
            Engine::Scalar => render(scene, path, options),
            Engine::Wavefront => WavefrontPathTracer::from_path(path)?.render(scene, options),
        })
    }
}
