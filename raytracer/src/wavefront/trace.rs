//! The trace stages: closest hits of all live paths' rays, and the shadow
//! rays of a bounce, each traced as one stream.
//!
//! Lecture topic: none of its own (ray casting). A stream is traced as a
//! whole before any path is shaded, so no shading code runs between two
//! traversals to evict the tree from the cache; with `streams` the rays
//! walk the tree together ([`crate::geometry::stream`]), each node fetched
//! once for all the rays that enter it, else one after the other.

use super::queue::{PathQueue, ShadowQueue};
use crate::geometry::stream::RayStream;
use crate::geometry::{Hit, Interaction};
use crate::math::Ray;
use crate::scene::Scene;

/// The tracer's working memory, kept from bounce to bounce.
#[derive(Debug, Default)]
pub struct Tracer {
    stream: RayStream,
    rays: Vec<Ray>,
    hits: Vec<Option<Hit>>,
    blocked: Vec<bool>,
}

impl Tracer {
    /// The closest hit of every live path's ray, into `queue.hit`; `camera`:
    /// the rays are the camera rays, in slot order.
    pub fn closest_hits(
        &mut self,
        scene: &Scene,
        streams: bool,
        camera: bool,
        queue: &mut PathQueue,
    ) {
        self.rays.clear();
        self.rays
            .extend(queue.live.iter().map(|&s| queue.ray[s as usize]));
        let g = &scene.geometry;
        if streams {
            g.intersect_stream(&self.rays, &mut self.hits, &mut self.stream);
        } else if camera {
            // The samples of a pixel are neighbours in the queue: their camera
            // rays are nearly parallel, and go through the BVH as packets.
            self.hits.clear();
            for chunk in self.rays.chunks(16) {
                match <&[Ray; 16]>::try_from(chunk) {
                    Ok(packet) => self.hits.extend(g.intersect16(packet)),
                    Err(_) => self.hits.extend(chunk.iter().map(|r| g.intersect(r))),
                }
            }
        } else {
            self.hits.clear();
            self.hits.extend(self.rays.iter().map(|r| g.intersect(r)));
        }
        for ((&s, ray), hit) in queue.live.iter().zip(&self.rays).zip(&self.hits) {
            queue.hit[s as usize] = hit.map(|h| {
                let sp = g.surface_point(ray, &h);
                Interaction::new(sp, h.t, -ray.d)
            });
        }
    }

    /// Resolves the shadow rays of a bounce: each unblocked one adds its
    /// contribution to its path's radiance.
    pub fn shadow_rays(
        &mut self,
        scene: &Scene,
        streams: bool,
        shadows: &ShadowQueue,
        queue: &mut PathQueue,
    ) {
        let g = &scene.geometry;
        if streams {
            g.occluded_stream(&shadows.ray, &mut self.blocked, &mut self.stream);
        } else {
            self.blocked.clear();
            self.blocked
                .extend(shadows.ray.iter().map(|r| g.occluded(r)));
        }
        for (i, &blocked) in self.blocked.iter().enumerate() {
            if !blocked {
                queue.l[shadows.slot[i] as usize] += shadows.contribution[i];
            }
        }
    }
}
