//! Four-wide BVH: the binary SAH tree collapsed so that each node holds four
//! children whose boxes are tested together with SIMD.
//!
//! Lecture topic: none of its own (acceleration structures).
//!
//! A binary tree spends most of a primary ray's time on node visits: about
//! 17 levels for 80k triangles, two slab tests per level, each a handful of
//! instructions plus a hard-to-predict branch. Collapsing pairs of levels
//! (each node adopts its grandchildren, preferring to open the child with the
//! largest surface area) halves the number of visits, and the four slab tests
//! of a node run side by side in the four lanes of a `Vec4` (SSE2 on x86_64,
//! plain scalar code elsewhere through glam's fallback). Boxes are stored
//! structure-of-arrays: `bounds[2k]` holds the four children's minima along
//! axis `k`, `bounds[2k + 1]` their maxima.
//!
//! Two walks share the four-box slab test: [`Bvh4::traverse`] visits the
//! children a ray enters nearest first and skips those that start beyond the
//! closest hit so far (closest hit); [`Bvh4::traverse_any`] visits them in
//! any order and stops at the first blocker (shadow rays).

use std::mem::MaybeUninit;

use super::aabb::InverseDirection;
use super::bvh::{Bvh, BvhNode};
use crate::math::{Vec3A, Vec4};

/// Set in a child reference that points to a leaf.
pub const LEAF: u32 = 1 << 31;
/// A leaf reference is `LEAF | first << COUNT_BITS | count`.
const COUNT_BITS: u32 = 4;
/// Traversal stack size (enough: pending subtrees are siblings of the nodes
/// on the binary path from the root, whose depth the build keeps below 64).
const STACK: usize = 64;
/// A reference to nothing (an unused child slot; its box is empty).
const NONE: u32 = u32::MAX;

/// One node: four children's boxes (structure of arrays) and references.
#[derive(Clone, Copy, Debug)]
#[repr(C, align(64))]
pub struct Bvh4Node {
    /// `[min_x, max_x, min_y, max_y, min_z, max_z]`, one lane per child;
    /// unused lanes hold the empty box (min = +∞, max = −∞), which no ray hits.
    bounds: [Vec4; 6],
    /// Node index, or a leaf reference (see `LEAF`), or `NONE`.
    pub(super) child: [u32; 4],
}

/// The four-wide tree. Node 0 is the root; primitives are in the order of
/// the binary [`Bvh`] it was collapsed from.
#[derive(Clone, Debug, Default)]
pub struct Bvh4 {
    pub nodes: Vec<Bvh4Node>,
}

fn leaf_ref(node: &BvhNode) -> u32 {
    LEAF | node.offset() << COUNT_BITS | node.count()
}

impl Bvh4 {
    /// Collapses a binary tree (which must have leaves of at most 15
    /// primitives and fewer than 2²⁷ primitives in all).
    pub fn from_binary(bvh: &Bvh) -> Bvh4 {
        let bin = &bvh.nodes[..];
        if bin.is_empty() {
            return Bvh4::default();
        }
        assert!(
            bvh.order.len() < 1 << (31 - COUNT_BITS),
            "too many primitives for Bvh4"
        );
        let mut nodes = Vec::with_capacity(bin.len() / 2);
        if bin[0].count() > 0 {
            // A single leaf: a root with one child.
            let mut root = empty_node();
            set_lane(&mut root, 0, &bin[0], leaf_ref(&bin[0]));
            nodes.push(root);
        } else {
            collapse(bin, 0, &mut nodes);
        }
        Bvh4 { nodes }
    }

    /// As [`Bvh::traverse`]: calls `leaf(first, count, &mut t_max)` for the
    /// leaves the ray `o + t·d`, `t ∈ (0, t_max)`, enters, nearest first.
    #[inline(always)]
    pub fn traverse(
        &self,
        o: Vec3A,
        d: Vec3A,
        mut t_max: f32,
        mut leaf: impl FnMut(u32, u32, &mut f32) -> bool,
    ) {
        let nodes = &self.nodes[..];
        if nodes.is_empty() {
            return;
        }
        let ray = SlabRay::new(o, d);
        let mut stack = Stack::<(u32, f32)>::new();
        let mut current = 0u32;
        loop {
            if current & LEAF != 0 {
                let (first, count) = leaf_range(current);
                if leaf(first, count, &mut t_max) {
                    return;
                }
            } else {
                let node = &nodes[current as usize];
                let (t_near, mut mask) = ray.enter(node, t_max);
                if mask != 0 {
                    let t = t_near.to_array();
                    let i = mask.trailing_zeros() as usize;
                    mask &= mask - 1;
                    if mask == 0 {
                        // One child hit: no stack traffic.
                        current = node.child[i];
                        continue;
                    }
                    let j = mask.trailing_zeros() as usize;
                    if mask & (mask - 1) == 0 {
                        // Two children hit (the common case): nearer first.
                        let (a, b) = if t[i] <= t[j] { (i, j) } else { (j, i) };
                        stack.push((node.child[b], t[b]));
                        current = node.child[a];
                        continue;
                    }
                    // More: sort by entry distance (at most four, by
                    // insertion), visit the nearest, push the others far first.
                    let mut hits = [(node.child[i], t[i]); 4];
                    let mut n = 1;
                    while mask != 0 {
                        let j = mask.trailing_zeros() as usize;
                        mask &= mask - 1;
                        let mut k = n;
                        while k > 0 && hits[k - 1].1 > t[j] {
                            hits[k] = hits[k - 1];
                            k -= 1;
                        }
                        hits[k] = (node.child[j], t[j]);
                        n += 1;
                    }
                    for h in hits[1..n].iter().rev() {
                        stack.push(*h);
                    }
                    current = hits[0].0;
                    continue;
                }
            }
            // Next pending subtree that still starts before t_max.
            loop {
                let Some((c, t)) = stack.pop() else {
                    return;
                };
                if t < t_max {
                    current = c;
                    break;
                }
            }
        }
    }

    /// Any-hit traversal for shadow rays: calls `leaf(first, count)` for the
    /// leaves the ray `o + t·d`, `t ∈ (0, t_max)`, enters, in no particular
    /// order, until it returns `true` (something blocks the ray); returns
    /// whether it did. Since any blocker ends the walk, the children a ray
    /// enters are neither sorted nor stored with their entry distances, and
    /// `t_max` never shrinks, so no pending subtree is ever skipped.
    #[inline(always)]
    pub fn traverse_any(
        &self,
        o: Vec3A,
        d: Vec3A,
        t_max: f32,
        mut leaf: impl FnMut(u32, u32) -> bool,
    ) -> bool {
        let nodes = &self.nodes[..];
        if nodes.is_empty() {
            return false;
        }
        let ray = SlabRay::new(o, d);
        let mut stack = Stack::<u32>::new();
        let mut current = 0u32;
        loop {
            if current & LEAF != 0 {
                let (first, count) = leaf_range(current);
                if leaf(first, count) {
                    return true;
                }
            } else {
                let node = &nodes[current as usize];
                let (_, mut mask) = ray.enter(node, t_max);
                if mask != 0 {
                    // Visit the first child entered, keep the others.
                    current = node.child[mask.trailing_zeros() as usize];
                    mask &= mask - 1;
                    while mask != 0 {
                        stack.push(node.child[mask.trailing_zeros() as usize]);
                        mask &= mask - 1;
                    }
                    continue;
                }
            }
            let Some(c) = stack.pop() else {
                return false;
            };
            current = c;
        }
    }
}

/// First primitive and count of a leaf reference.
#[inline(always)]
pub fn leaf_range(reference: u32) -> (u32, u32) {
    (
        (reference & !LEAF) >> COUNT_BITS,
        reference & ((1 << COUNT_BITS) - 1),
    )
}

/// A ray prepared for the slab tests of four boxes at once.
///
/// Moving in +k the ray enters slab k at its minimum plane, in −k at its
/// maximum: picking the planes once per ray saves the min/max of the two
/// plane distances per box. The side comes from the sign of 1/d, so a −0.0
/// component picks the planes its −1e30 needs.
pub struct SlabRay {
    o: [Vec4; 3],
    inv_d: [Vec4; 3],
    negative: [usize; 3],
}

impl SlabRay {
    #[inline(always)]
    pub(super) fn new(o: Vec3A, d: Vec3A) -> Self {
        Self::from_inverse(o, InverseDirection::new(d))
    }

    /// The ray from `o` with its direction's inverse already computed.
    #[inline(always)]
    pub(super) fn from_inverse(o: Vec3A, inv: InverseDirection) -> Self {
        let InverseDirection { inv_d, negative } = inv;
        SlabRay {
            o: [Vec4::splat(o.x), Vec4::splat(o.y), Vec4::splat(o.z)],
            inv_d: [
                Vec4::splat(inv_d.x),
                Vec4::splat(inv_d.y),
                Vec4::splat(inv_d.z),
            ],
            negative,
        }
    }

    /// Slab test of the four children of `node` against `(0, t_max)`: the
    /// entry distances `max_k (plane_near_k − o_k)/d_k` (clamped at 0) and a
    /// bit mask of the children entered (`t_near ≤ t_far`).
    #[inline(always)]
    pub(super) fn enter(&self, node: &Bvh4Node, t_max: f32) -> (Vec4, u32) {
        let b = &node.bounds;
        let [sx, sy, sz] = self.negative;
        let [ox, oy, oz] = self.o;
        let [ix, iy, iz] = self.inv_d;
        let t_near = ((b[sx] - ox) * ix)
            .max((b[2 + sy] - oy) * iy)
            .max(((b[4 + sz] - oz) * iz).max(Vec4::ZERO));
        let t_far = ((b[1 - sx] - ox) * ix)
            .min((b[3 - sy] - oy) * iy)
            .min(((b[5 - sz] - oz) * iz).min(Vec4::splat(t_max)));
        (t_near, t_near.cmple(t_far).bitmask())
    }
}

/// The traversal stack: a fixed array, left uninitialized (zeroing its
/// 512 bytes for every ray showed up in profiles as a `memset` costing a
/// few per cent of a path tracer's time).
struct Stack<T: Copy> {
    items: [MaybeUninit<T>; STACK],
    len: usize,
}

impl<T: Copy> Stack<T> {
    #[inline(always)]
    fn new() -> Self {
        Stack {
            items: [const { MaybeUninit::uninit() }; STACK],
            len: 0,
        }
    }

    #[inline(always)]
    fn push(&mut self, item: T) {
        // Indexing panics (rather than writing out of bounds) should the
        // depth bound of the build ever be broken.
        self.items[self.len] = MaybeUninit::new(item);
        self.len += 1;
    }

    #[inline(always)]
    fn pop(&mut self) -> Option<T> {
        self.len = self.len.checked_sub(1)?;
        // SAFETY: every slot below the former `len` was written by `push`.
        Some(unsafe { self.items[self.len].assume_init() })
    }
}

fn empty_node() -> Bvh4Node {
    let (inf, ninf) = (Vec4::splat(f32::INFINITY), Vec4::splat(f32::NEG_INFINITY));
    Bvh4Node {
        bounds: [inf, ninf, inf, ninf, inf, ninf],
        child: [NONE; 4],
    }
}

fn set_lane(node: &mut Bvh4Node, lane: usize, from: &BvhNode, child: u32) {
    let b = from.bounds();
    for k in 0..3 {
        node.bounds[2 * k][lane] = b.min[k];
        node.bounds[2 * k + 1][lane] = b.max[k];
    }
    node.child[lane] = child;
}

/// Writes the four-wide node for the binary interior node `at` and its
/// subtree; returns its index.
fn collapse(bin: &[BvhNode], at: usize, out: &mut Vec<Bvh4Node>) -> u32 {
    // Start from the two children; open the interior child with the largest
    // surface area (the one most rays enter) until there are four.
    let c = bin[at].offset() as usize;
    let mut kids = [c, c + 1, 0, 0];
    let mut n = 2;
    while n < 4 {
        let open = kids[..n]
            .iter()
            .enumerate()
            .filter(|&(_, &k)| bin[k].count() == 0)
            .max_by(|a, b| {
                let (sa, sb) = (
                    bin[*a.1].bounds().surface_area(),
                    bin[*b.1].bounds().surface_area(),
                );
                sa.total_cmp(&sb)
            })
            .map(|(i, _)| i);
        let Some(i) = open else { break };
        let g = bin[kids[i]].offset() as usize;
        kids[i] = g;
        kids[n] = g + 1;
        n += 1;
    }
    let me = out.len();
    out.push(empty_node());
    let mut node = empty_node();
    for (lane, &k) in kids[..n].iter().enumerate() {
        let child = if bin[k].count() > 0 {
            leaf_ref(&bin[k])
        } else {
            collapse(bin, k, out)
        };
        set_lane(&mut node, lane, &bin[k], child);
    }
    out[me] = node;
    me as u32
}
