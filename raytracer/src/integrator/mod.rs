//! Integrators: the algorithms that solve the rendering equation.
//!
//! Lecture topic: global illumination algorithms. Each integrator estimates
//! the radiance of one camera sample; the render loop ([`crate::render`])
//! averages many of them per pixel.

use crate::film::Splat;
use crate::math::{Color, UVec2};
use crate::sampling::Sampler;
use crate::scene::Scene;

/// An algorithm that estimates pixel values.
pub trait Integrator: Sync {
    /// A short name for file names and tables ("direct", "path", ...).
    fn name(&self) -> &'static str;

    /// One sample of pixel `pixel`: returns its radiance estimate and may add
    /// contributions to other pixels to `splats` (light tracing). All random
    /// numbers come from `sampler`.
    fn sample(
        &self,
        scene: &Scene,
        pixel: UVec2,
        sampler: &mut Sampler,
        splats: &mut Vec<Splat>,
    ) -> Color;
}
