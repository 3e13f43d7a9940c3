//! Ambient occlusion: how open the hemisphere above each point is.
//!
//! Lecture topic: global illumination effects, as a teaching contrast. AO is
//! not physically based — it ignores the lights and the BRDFs — but it shows
//! the contact shadows and the darkening of corners that indirect light also
//! produces. The estimate of `(1/π) ∫ V(x, ω) cos θ dω` with cosine-weighted
//! directions is simply the fraction of rays that escape within `distance`.

use super::dimensions::AO_DIRECTION;
use super::{Integrator, camera_ray};
use crate::film::Splat;
use crate::math::{Color, UVec2};
use crate::sampling::{Sampler, warp};
use crate::scene::Scene;

/// Ambient occlusion with occlusion rays of length `distance` (metres).
#[derive(Clone, Copy, Debug)]
pub struct AmbientOcclusion {
    pub distance: f32,
}

impl Default for AmbientOcclusion {
    fn default() -> Self {
        AmbientOcclusion { distance: 1.0 }
    }
}

impl Integrator for AmbientOcclusion {
    fn name(&self) -> &'static str {
        "ao"
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
            return Color::ONE;
        };
        // The hemisphere on the side the camera sees.
        let frame = if it.frame.n.dot(it.wo) < 0.0 {
            it.frame.flipped()
        } else {
            it.frame
        };
        let d = frame.to_world(warp::cosine_hemisphere(AO_DIRECTION.draw(sampler)));
        let mut occlusion_ray = it.spawn_ray(d);
        occlusion_ray.t_max = self.distance;
        if scene.unoccluded(&occlusion_ray) {
            Color::ONE
        } else {
            Color::ZERO
        }
    }
}
