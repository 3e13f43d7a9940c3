//! Ray streams: many rays traced through the four-wide BVH together, each
//! node fetched and tested once for all the rays that enter it.
//!
//! Lecture topic: none of its own (acceleration structures); the wavefront
//! engine (`crate::wavefront`) traces its rays this way.
//!
//! One ray at a time, each BVH node is loaded once per ray that visits it,
//! and the next node to load depends on the test just made, so the processor
//! waits on memory and on a hard-to-predict branch at every step. A stream
//! walks the tree once, depth first, carrying the list of rays still inside
//! (Barringer and Akenine-Möller, "Dynamic Ray Stream Traversal", 2014): at
//! an interior node every ray of the list is tested against the node's four
//! boxes at once (the SIMD slab test of [`super::bvh4`]), and each child gets
//! the list of the rays that enter it; at a leaf every ray of the list is
//! tested against the leaf's primitives. The node stays in cache while all
//! the rays use it, and the loops over a list are branch-light and
//! independent from ray to ray, so they overlap in the pipeline.
//!
//! Children are visited nearest first by the mean entry distance of their
//! rays; a ray keeps its closest hit so far as its `t_max`, so farther boxes
//! are culled for it as in single-ray traversal. Each ray gets the closest
//! hit [`Geometry::intersect`] gives it (the same primitive tests), except
//! that of two hits at exactly the same distance the one found first wins,
//! and the order differs.

use super::aabb::InverseDirection;
use super::bvh4::{LEAF, SlabRay, leaf_range};
use super::{Geometry, Hit};
use crate::math::{Ray, Vec3A};

/// A pending subtree: the node (or leaf reference) and the rays entering
/// it, `lists[start..end]`.
#[derive(Clone, Copy, Debug)]
struct Entry {
    node: u32,
    start: u32,
    end: u32,
}

/// The working memory of stream traversal, kept from stream to stream.
#[derive(Debug, Default)]
pub struct RayStream {
    o: Vec<Vec3A>,
    d: Vec<Vec3A>,
    inv: Vec<InverseDirection>,
    t_max: Vec<f32>,
    /// Whether a shadow ray was found blocked (it leaves the lists).
    done: Vec<bool>,
    /// The ray lists of pending subtrees, stacked.
    lists: Vec<u32>,
    /// Which children each ray of the current list enters (bit mask).
    masks: Vec<u8>,
    stack: Vec<Entry>,
}

impl RayStream {
    fn load(&mut self, rays: &[Ray]) {
        self.o.clear();
        self.d.clear();
        self.inv.clear();
        self.t_max.clear();
        self.done.clear();
        for r in rays {
            self.o.push(r.o);
            self.d.push(r.d);
            self.inv.push(InverseDirection::new(r.d));
            self.t_max.push(r.t_max);
            self.done.push(false);
        }
    }
}

impl Geometry {
    /// The closest hit of each ray of `rays` into `hits` (as
    /// [`Geometry::intersect`] for each, up to exact ties).
    pub fn intersect_stream(
        &self,
        rays: &[Ray],
        hits: &mut Vec<Option<Hit>>,
        stream: &mut RayStream,
    ) {
        hits.clear();
        hits.resize(rays.len(), None);
        let prims = &self.prims[..];
        self.traverse_stream(rays, stream, |first, count, r, o, d, t_max| {
            let leaf = &prims[first as usize..(first + count) as usize];
            for (k, prim) in leaf.iter().enumerate() {
                if let Some((t, uv)) = prim.intersect(o, d, *t_max) {
                    *t_max = t;
                    hits[r] = Some(Hit {
                        t,
                        prim: first + k as u32,
                        uv,
                    });
                }
            }
            false
        });
    }

    /// Whether each ray of `rays` is blocked before its `t_max`, into
    /// `blocked` (as [`Geometry::occluded`] for each).
    pub fn occluded_stream(&self, rays: &[Ray], blocked: &mut Vec<bool>, stream: &mut RayStream) {
        let prims = &self.prims[..];
        self.traverse_stream(rays, stream, |first, count, _, o, d, t_max| {
            prims[first as usize..(first + count) as usize]
                .iter()
                .any(|prim| prim.intersect(o, d, *t_max).is_some())
        });
        blocked.clear();
        blocked.extend_from_slice(&stream.done);
    }

    /// Walks the tree with the whole stream; `leaf(first, count, ray, o, d,
    /// &mut t_max)` tests one ray against one leaf and returns true if the
    /// ray is finished (a shadow ray found blocked).
    fn traverse_stream(
        &self,
        rays: &[Ray],
        s: &mut RayStream,
        mut leaf: impl FnMut(u32, u32, usize, Vec3A, Vec3A, &mut f32) -> bool,
    ) {
        s.load(rays);
        let nodes = &self.bvh.nodes[..];
        if nodes.is_empty() || rays.is_empty() {
            return;
        }
        s.lists.clear();
        s.lists.extend(0..rays.len() as u32);
        s.stack.clear();
        s.stack.push(Entry {
            node: 0,
            start: 0,
            end: rays.len() as u32,
        });
        while let Some(e) = s.stack.pop() {
            // Everything stacked above this entry's list is finished.
            s.lists.truncate(e.end as usize);
            let (start, end) = (e.start as usize, e.end as usize);
            if e.node & LEAF != 0 {
                let (first, count) = leaf_range(e.node);
                for i in start..end {
                    let r = s.lists[i] as usize;
                    if !s.done[r] && leaf(first, count, r, s.o[r], s.d[r], &mut s.t_max[r]) {
                        s.done[r] = true;
                    }
                }
                continue;
            }
            let node = &nodes[e.node as usize];
            // Which children each ray enters, and their rays' entry distances.
            let mut count = [0u32; 4];
            let mut t_sum = [0.0f32; 4];
            s.masks.clear();
            for i in start..end {
                let r = s.lists[i] as usize;
                let mut mask = 0;
                if !s.done[r] {
                    let slab = SlabRay::from_inverse(s.o[r], s.inv[r]);
                    let (t_near, m) = slab.enter(node, s.t_max[r]);
                    mask = m;
                    let t = t_near.to_array();
                    for c in 0..4 {
                        let hit = (m >> c) & 1;
                        count[c] += hit;
                        if hit != 0 {
                            t_sum[c] += t[c];
                        }
                    }
                }
                s.masks.push(mask as u8);
            }
            // Push the children far first, so the nearest is visited next.
            let mut order = [0usize, 1, 2, 3];
            let mean = |c: usize| t_sum[c] / count[c].max(1) as f32;
            order.sort_by(|&a, &b| mean(b).total_cmp(&mean(a)));
            for c in order {
                if count[c] == 0 {
                    continue;
                }
                let child_start = s.lists.len() as u32;
                for i in start..end {
                    if (s.masks[i - start] >> c) & 1 != 0 {
                        let r = s.lists[i];
                        s.lists.push(r);
                    }
                }
                s.stack.push(Entry {
                    node: node.child[c],
                    start: child_start,
                    end: s.lists.len() as u32,
                });
            }
        }
    }
}
