//! Bounding volume hierarchy: binned-SAH build and ordered traversal over
//! flattened 32-byte nodes.
//!
//! Lecture topic: none of its own (acceleration structures). Every ray of
//! every algorithm of Lecture 11 ends up here.
//!
//! # Build
//!
//! Top-down, in the manner of Wald, "On fast Construction of SAH-based
//! Bounding Volume Hierarchies" (2007): the centroids of a node's primitives
//! are sorted into [`BINS`] bins along each axis, and the split between bins
//! that minimises the surface area heuristic
//!
//! `C = C_trav + (A_L·N_L + A_R·N_R) / A`
//!
//! (`A` the surface area of a box, `N` a primitive count) is compared with the
//! cost `N` of a leaf. Binning is one pass over the primitives, so a level of
//! the tree costs O(N); the two halves of a node are built in parallel (rayon)
//! once they are large enough to pay for it.
//!
//! # Layout
//!
//! The tree is flattened depth first with siblings side by side: the children
//! of an interior node are `offset` and `offset + 1`, so that the pair fills
//! one 64-byte cache line and both boxes are tested together. A leaf holds
//! `count` consecutive primitives starting at `offset` in [`Bvh::order`]
//! (the caller stores its primitive data in that order, so a leaf's data is
//! contiguous in memory).
//!
//! # Traversal
//!
//! [`Bvh::traverse`] tests both children of a node, visits the one the ray
//! enters first and keeps the other on a stack with its entry distance; a
//! subtree popped after `t_max` has shrunk below that distance is skipped.
//! So the closest hit is usually found early and most far subtrees are never
//! opened. The stack is a fixed array of 64 entries (the build keeps the tree
//! depth below 64). The split axis is stored too (for front-to-back orders
//! that need no distances, e.g. in lessons).

use rayon::prelude::*;

use super::aabb::{Aabb, InverseDirection};
use crate::math::{Vec3A, Vec4};

/// Number of bins per axis for the SAH sweep.
pub const BINS: usize = 16;
/// Cost of visiting a node, relative to one primitive test.
const TRAVERSAL_COST: f32 = 1.0;
/// Largest leaf; larger groups are always split.
pub const MAX_LEAF: usize = 8;
/// Beyond this depth the build splits at the median, which bounds the depth
/// by `DEPTH_SAH + log2(N) < STACK` for any `N < 2³²`.
const DEPTH_SAH: u32 = 30;
/// Traversal stack size.
pub const STACK: usize = 64;
/// Subtrees larger than this are built in parallel.
const PARALLEL_BUILD: usize = 4096;
/// Nodes larger than this are binned in parallel.
const PARALLEL_BIN: usize = 1 << 16;

/// One node of the flattened tree (32 bytes, half a cache line).
///
/// `lo.xyz`/`hi.xyz` are the bounds; the `w` lanes hold integers as bit
/// patterns: `lo.w` = `offset` (second child, or first primitive of a leaf),
/// `hi.w` = `count | axis << 16` (`count = 0` for an interior node).
#[derive(Clone, Copy, Debug)]
#[repr(C, align(32))]
pub struct BvhNode {
    lo: Vec4,
    hi: Vec4,
}

impl BvhNode {
    fn new(bounds: Aabb, offset: u32, count: u32, axis: u32) -> Self {
        debug_assert!(count < 1 << 16 && axis < 3);
        BvhNode {
            lo: bounds.min.extend(f32::from_bits(offset)),
            hi: bounds.max.extend(f32::from_bits(count | axis << 16)),
        }
    }

    /// The node's bounding box.
    #[inline]
    pub fn bounds(&self) -> Aabb {
        Aabb {
            min: Vec3A::from_vec4(self.lo),
            max: Vec3A::from_vec4(self.hi),
        }
    }

    /// Second child (interior) or first primitive (leaf).
    #[inline]
    pub fn offset(&self) -> u32 {
        self.lo.w.to_bits()
    }

    /// Number of primitives; 0 for an interior node.
    #[inline]
    pub fn count(&self) -> u32 {
        self.hi.w.to_bits() & 0xffff
    }

    /// Split axis of an interior node.
    #[inline]
    pub fn axis(&self) -> usize {
        (self.hi.w.to_bits() >> 16) as usize
    }
}

/// A flattened binary BVH over primitives known only by their boxes.
#[derive(Clone, Debug, Default)]
pub struct Bvh {
    /// Node 0 is the root (the vector is empty when there are no primitives).
    pub nodes: Vec<BvhNode>,
    /// `order[k]` = index (in the input of [`Bvh::build`]) of the primitive in
    /// leaf slot `k`.
    pub order: Vec<u32>,
}

/// A primitive during the build: its box, with its index in `lo.w`.
#[derive(Clone, Copy)]
#[repr(C)]
struct PrimRef {
    lo: Vec4,
    hi: Vec4,
}

impl PrimRef {
    #[inline]
    fn min(&self) -> Vec3A {
        Vec3A::from_vec4(self.lo)
    }
    #[inline]
    fn max(&self) -> Vec3A {
        Vec3A::from_vec4(self.hi)
    }
    /// Twice the centroid (the factor ½ cancels in every comparison).
    #[inline]
    fn centroid2(&self) -> Vec3A {
        self.min() + self.max()
    }
}

enum BuildNode {
    Leaf {
        bounds: Aabb,
        first: u32,
        count: u32,
    },
    Interior {
        bounds: Aabb,
        axis: u32,
        /// Nodes in this subtree.
        size: u32,
        children: Box<[BuildNode; 2]>,
    },
}

impl BuildNode {
    fn size(&self) -> u32 {
        match self {
            BuildNode::Leaf { .. } => 1,
            BuildNode::Interior { size, .. } => *size,
        }
    }
}

/// Bounds and centroid bounds of a group of primitives, and the bins.
#[derive(Clone, Copy)]
struct Bins {
    bounds: [[Aabb; BINS]; 3],
    counts: [[u32; BINS]; 3],
}

impl Bins {
    fn empty() -> Self {
        Bins {
            bounds: [[Aabb::EMPTY; BINS]; 3],
            counts: [[0; BINS]; 3],
        }
    }

    fn merge(mut self, other: &Bins) -> Bins {
        for a in 0..3 {
            for b in 0..BINS {
                self.bounds[a][b] = self.bounds[a][b].union(other.bounds[a][b]);
                self.counts[a][b] += other.counts[a][b];
            }
        }
        self
    }
}

/// Maps a (doubled) centroid to its bin along each axis.
#[derive(Clone, Copy)]
struct Binner {
    origin: Vec3A,
    scale: Vec3A,
}

impl Binner {
    fn new(centroids: Aabb) -> Self {
        let extent = centroids.diagonal();
        // k = ⌊(c − c_min) · BINS / extent⌋, the factor just below 1 keeps the
        // largest centroid in the last bin.
        let scale = Vec3A::select(
            extent.cmpgt(Vec3A::ZERO),
            Vec3A::splat(BINS as f32 * (1.0 - 1e-5)) / extent,
            Vec3A::ZERO,
        );
        Binner {
            origin: centroids.min,
            scale,
        }
    }

    #[inline]
    fn bin(&self, c2: Vec3A) -> [usize; 3] {
        let k = ((c2 - self.origin) * self.scale).max(Vec3A::ZERO);
        [
            (k.x as usize).min(BINS - 1),
            (k.y as usize).min(BINS - 1),
            (k.z as usize).min(BINS - 1),
        ]
    }

    fn fill(&self, refs: &[PrimRef]) -> Bins {
        let mut bins = Bins::empty();
        for r in refs {
            let k = self.bin(r.centroid2());
            let b = Aabb {
                min: r.min(),
                max: r.max(),
            };
            for (a, &ka) in k.iter().enumerate() {
                bins.bounds[a][ka] = bins.bounds[a][ka].union(b);
                bins.counts[a][ka] += 1;
            }
        }
        bins
    }
}

/// Bounds of the boxes and of the (doubled) centroids of `refs`.
fn group_bounds(refs: &[PrimRef]) -> (Aabb, Aabb) {
    let seq = |refs: &[PrimRef]| {
        let (mut b, mut c) = (Aabb::EMPTY, Aabb::EMPTY);
        for r in refs {
            b.min = b.min.min(r.min());
            b.max = b.max.max(r.max());
            c.grow(r.centroid2());
        }
        (b, c)
    };
    if refs.len() > PARALLEL_BIN {
        refs.par_chunks(PARALLEL_BIN / 4).map(seq).reduce(
            || (Aabb::EMPTY, Aabb::EMPTY),
            |x, y| (x.0.union(y.0), x.1.union(y.1)),
        )
    } else {
        seq(refs)
    }
}

/// Moves the elements satisfying `left` to the front; returns their number.
fn partition(refs: &mut [PrimRef], left: impl Fn(&PrimRef) -> bool) -> usize {
    let (mut i, mut j) = (0, refs.len());
    loop {
        while i < j && left(&refs[i]) {
            i += 1;
        }
        while i < j && !left(&refs[j - 1]) {
            j -= 1;
        }
        if i >= j {
            return i;
        }
        refs.swap(i, j - 1);
        i += 1;
        j -= 1;
    }
}

fn build_node(refs: &mut [PrimRef], first: u32, depth: u32) -> BuildNode {
    let n = refs.len();
    let (bounds, centroids) = group_bounds(refs);
    let leaf = || BuildNode::Leaf {
        bounds,
        first,
        count: n as u32,
    };
    if n == 1 {
        return leaf();
    }

    let mut split = None; // (axis, number of primitives on the left)
    let axis_long = centroids.largest_axis();
    if centroids.diagonal()[axis_long] > 0.0 && depth < DEPTH_SAH {
        let binner = Binner::new(centroids);
        let bins = if n > PARALLEL_BIN {
            refs.par_chunks(PARALLEL_BIN / 4)
                .map(|c| binner.fill(c))
                .reduce(Bins::empty, |a, b| a.merge(&b))
        } else {
            binner.fill(refs)
        };
        // Sweep: right[i] = A·N of bins i.. ; left accumulated on the way back.
        let mut best = (f32::INFINITY, 0, 0);
        for a in 0..3 {
            let mut right_cost = [0.0f32; BINS];
            let (mut acc, mut cnt) = (Aabb::EMPTY, 0u32);
            for i in (1..BINS).rev() {
                acc = acc.union(bins.bounds[a][i]);
                cnt += bins.counts[a][i];
                right_cost[i] = acc.surface_area() * cnt as f32;
            }
            let (mut acc, mut cnt) = (Aabb::EMPTY, 0u32);
            for (i, &right) in right_cost.iter().enumerate().skip(1) {
                acc = acc.union(bins.bounds[a][i - 1]);
                cnt += bins.counts[a][i - 1];
                let cost = acc.surface_area() * cnt as f32 + right;
                if cnt > 0 && (cnt as usize) < n && cost < best.0 {
                    best = (cost, a, i);
                }
            }
        }
        let (cost, axis, bin) = best;
        if cost.is_finite() {
            let split_cost = TRAVERSAL_COST + cost / bounds.surface_area().max(f32::MIN_POSITIVE);
            if n > MAX_LEAF || split_cost < n as f32 {
                let mid = partition(refs, |r| binner.bin(r.centroid2())[axis] < bin);
                split = Some((axis, mid));
            }
        }
    } else if n > MAX_LEAF {
        // Equal centroids (or too deep for the SAH): median split.
        let a = axis_long;
        let mid = n / 2;
        refs.select_nth_unstable_by(mid, |x, y| x.centroid2()[a].total_cmp(&y.centroid2()[a]));
        split = Some((a, mid));
    }

    let Some((axis, mid)) = split else {
        return leaf();
    };
    let (l, r) = refs.split_at_mut(mid);
    let first_r = first + mid as u32;
    let (left, right) = if n > PARALLEL_BUILD {
        rayon::join(
            || build_node(l, first, depth + 1),
            || build_node(r, first_r, depth + 1),
        )
    } else {
        (
            build_node(l, first, depth + 1),
            build_node(r, first_r, depth + 1),
        )
    };
    BuildNode::Interior {
        bounds,
        axis: axis as u32,
        size: 1 + left.size() + right.size(),
        children: Box::new([left, right]),
    }
}

/// Writes the children of `node` (already written at `at`) as pairs of
/// adjacent nodes, allocated from `next`, depth first.
fn flatten(node: &BuildNode, nodes: &mut [BvhNode], at: usize, next: &mut usize) {
    match node {
        BuildNode::Leaf {
            bounds,
            first,
            count,
        } => nodes[at] = BvhNode::new(*bounds, *first, *count, 0),
        BuildNode::Interior {
            bounds,
            axis,
            children,
            ..
        } => {
            let pair = *next;
            *next += 2;
            nodes[at] = BvhNode::new(*bounds, pair as u32, 0, *axis);
            flatten(&children[0], nodes, pair, next);
            flatten(&children[1], nodes, pair + 1, next);
        }
    }
}

impl Bvh {
    /// Builds the tree over primitives given by their boxes.
    pub fn build(bounds: &[Aabb]) -> Bvh {
        assert!(bounds.len() < u32::MAX as usize, "too many primitives");
        if bounds.is_empty() {
            return Bvh::default();
        }
        let mut refs: Vec<PrimRef> = bounds
            .par_iter()
            .enumerate()
            .map(|(i, b)| PrimRef {
                lo: b.min.extend(f32::from_bits(i as u32)),
                hi: b.max.extend(0.0),
            })
            .collect();
        let root = build_node(&mut refs, 0, 0);
        // Slot 1 is padding, so that every pair of siblings starts at an
        // even index: one 64-byte cache line.
        let mut nodes = vec![BvhNode::new(Aabb::EMPTY, 0, 0, 0); root.size() as usize + 1];
        let mut next = 2;
        flatten(&root, &mut nodes, 0, &mut next);
        drop_tree(root);
        let order = refs.par_iter().map(|r| r.lo.w.to_bits()).collect();
        Bvh { nodes, order }
    }

    /// Bounds of everything (empty without primitives).
    pub fn bounds(&self) -> Aabb {
        self.nodes.first().map_or(Aabb::EMPTY, |n| n.bounds())
    }

    /// Walks the tree along the ray `o + t·d`, `t ∈ (0, t_max)`, calling
    /// `leaf(first, count, &mut t_max)` for every leaf whose box the ray
    /// enters before `t_max`. The callback may shrink `t_max` (closest hit);
    /// returning `true` stops the walk (any hit).
    #[inline(always)]
    pub fn traverse(
        &self,
        o: Vec3A,
        d: Vec3A,
        mut t_max: f32,
        mut leaf: impl FnMut(u32, u32, &mut f32) -> bool,
    ) {
        let nodes = &self.nodes[..];
        let Some(root) = nodes.first() else {
            return;
        };
        let inv_d = InverseDirection::new(d).inv_d;
        // Slab test of a node: the entry distance, or +∞ for a miss.
        let enter = |n: &BvhNode, t_max: f32| -> f32 {
            let t0 = (Vec3A::from_vec4(n.lo) - o) * inv_d;
            let t1 = (Vec3A::from_vec4(n.hi) - o) * inv_d;
            let near = t0.min(t1).max_element().max(0.0);
            let far = t0.max(t1).min_element().min(t_max);
            if near <= far { near } else { f32::INFINITY }
        };
        if enter(root, t_max) == f32::INFINITY {
            return;
        }
        // Pending subtrees and the distance at which the ray enters them.
        let mut stack = [(0u32, 0f32); STACK];
        let mut sp = 0usize;
        let mut index = 0usize;
        loop {
            let node = &nodes[index];
            let count = node.count();
            if count > 0 {
                if leaf(node.offset(), count, &mut t_max) {
                    return;
                }
            } else {
                // Both children are tested here, with one cache line.
                let c = node.offset() as usize;
                let (ta, tb) = (enter(&nodes[c], t_max), enter(&nodes[c + 1], t_max));
                if ta != f32::INFINITY {
                    if tb != f32::INFINITY {
                        // Nearer child first, the other waits on the stack.
                        let (near, far, t_far) = if ta <= tb {
                            (c, c + 1, tb)
                        } else {
                            (c + 1, c, ta)
                        };
                        stack[sp] = (far as u32, t_far);
                        sp += 1;
                        index = near;
                    } else {
                        index = c;
                    }
                    continue;
                } else if tb != f32::INFINITY {
                    index = c + 1;
                    continue;
                }
            }
            // Pop the next subtree that still starts before t_max.
            loop {
                if sp == 0 {
                    return;
                }
                sp -= 1;
                let (i, t) = stack[sp];
                if t < t_max {
                    index = i as usize;
                    break;
                }
            }
        }
    }
}

/// Drops a big build tree in parallel (freeing a million boxes one by one on
/// a single thread takes a noticeable part of the build).
fn drop_tree(node: BuildNode) {
    if let BuildNode::Interior { children, size, .. } = node {
        let [a, b] = *children;
        if size as usize > PARALLEL_BUILD {
            rayon::join(|| drop_tree(a), || drop_tree(b));
        }
    }
}
