//! The trace stages: closest hits of all live paths' rays, and the shadow
//! rays of a bounce, each as one stream.
//!
//! Lecture topic: none of its own (ray casting). A stream is traced as a
//! whole before any path is shaded, so the BVH's nodes and the primitives
//! stay in cache from one ray to the next, and no shading code sits between
//! two traversals to evict them.

use super::queue::{PathQueue, ShadowQueue};
use crate::scene::Scene;

/// The closest hit of every live path's ray, into `queue.hit`.
pub fn closest_hits(scene: &Scene, queue: &mut PathQueue) {
    for &s in &queue.live {
        let s = s as usize;
        queue.hit[s] = scene.intersect(&queue.ray[s]);
    }
}

/// Resolves the shadow rays of a bounce: each unblocked one adds its
/// contribution to its path's radiance.
pub fn shadow_rays(scene: &Scene, shadows: &ShadowQueue, queue: &mut PathQueue) {
    for i in 0..shadows.len() {
        if scene.unoccluded(&shadows.ray[i]) {
            queue.l[shadows.slot[i] as usize] += shadows.contribution[i];
        }
    }
}
