//! The camera stage: one primary ray per path of the unit.
//!
//! Lecture topic: paths start at the camera. Each path draws its film and
//! lens numbers from its own sampler, as `path` does, so the two engines
//! trace the same primary rays.

use super::queue::PathQueue;
use crate::integrator::camera_ray;
use crate::math::UVec2;
use crate::scene::Scene;

/// Fills `queue.ray` with the camera ray of every path; the queue's slot
/// `i` is the unit's path `first + i`, which belongs to
/// `pixels[(first + i) / per_pixel]`.
pub fn generate(
    scene: &Scene,
    pixels: &[UVec2],
    per_pixel: usize,
    first: usize,
    queue: &mut PathQueue,
) {
    let q = queue;
    for (i, (ray, sampler)) in q.ray.iter_mut().zip(q.sampler.iter_mut()).enumerate() {
        *ray = camera_ray(scene, pixels[(first + i) / per_pixel], sampler);
    }
}
