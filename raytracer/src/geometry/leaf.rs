//! What a leaf of the four-wide BVH holds, and the test of a ray against it.
//!
//! Lecture topic: none of its own (acceleration structures).
//!
//! A leaf is a range of [`PrimRecord`]s with its triangles first (the
//! geometry orders each leaf so). A leaf of [`MIN_BLOCK`] triangles or more
//! also packs them four to a [`LeafBlock`], structure-of-arrays, and tests
//! them a block at a time in SIMD lanes ([`Triangle4`]); its other
//! primitives (quads, spheres), and every primitive of a smaller leaf, are
//! tested one by one from their records. Lane `k` of block `j` of a leaf
//! is primitive `first + 4j + k`, so a hit names the same primitive, with
//! the same distance and barycentrics bit for bit, as testing the records
//! in order would.

use super::Hit;
use super::bvh::MIN_BLOCK;
use super::primitive::{KIND_TRIANGLE, PrimRecord};
use super::triangle4::{Ray4, Triangle4};
use crate::math::{Vec2, Vec3A};

/// Up to four triangles of a leaf, and where the leaf is (every block of a
/// leaf carries the same three numbers; the first one's are read).
#[derive(Clone, Copy, Debug)]
#[repr(C, align(16))]
pub struct LeafBlock {
    triangles: Triangle4,
    /// The leaf's first primitive.
    first: u32,
    /// Its number of triangles (in `⌈triangles / 4⌉` blocks).
    triangle_count: u16,
    /// Its number of primitives (the triangles, then the others).
    count: u16,
}

/// Set in a leaf's name when its triangles are in blocks: the rest of the
/// name is the index of its first block. Otherwise the name is
/// `first << COUNT_BITS | count`, the leaf's range of records.
const IN_BLOCKS: u32 = 1 << 30;
const COUNT_BITS: u32 = 4;

/// The blocks of the leaves with [`MIN_BLOCK`] triangles or more.
#[derive(Clone, Debug, Default)]
pub struct Leaves {
    blocks: Vec<LeafBlock>,
}

impl Leaves {
    /// Packs the leaf `prims[first..first + count]`, whose triangles come
    /// first; returns its name (below 2³¹).
    pub fn push(&mut self, prims: &[PrimRecord], first: u32, count: u32) -> u32 {
        let leaf = &prims[first as usize..(first + count) as usize];
        let triangles: Vec<[Vec3A; 3]> = leaf
            .iter()
            .take_while(|p| p.kind() == KIND_TRIANGLE)
            .map(|p| [p.a, p.b, p.c].map(Vec3A::from_vec4))
            .collect();
        debug_assert!(
            leaf[triangles.len()..]
                .iter()
                .all(|p| p.kind() != KIND_TRIANGLE)
        );
        if (triangles.len() as u32) < MIN_BLOCK {
            assert!(
                first < IN_BLOCKS >> COUNT_BITS && count < 1 << COUNT_BITS,
                "too many primitives for the BVH's leaves"
            );
            return first << COUNT_BITS | count;
        }
        let name = self.blocks.len() as u32;
        assert!(name < IN_BLOCKS, "too many leaf blocks");
        for chunk in triangles.chunks(4) {
            self.blocks.push(LeafBlock {
                triangles: Triangle4::new(chunk),
                first,
                triangle_count: triangles.len() as u16,
                count: count as u16,
            });
        }
        IN_BLOCKS | name
    }

    /// The leaf's first record, number of triangles in blocks (0 if it has
    /// no blocks) and number of records.
    #[inline(always)]
    fn layout(&self, leaf: u32) -> (u32, u32, u32) {
        if leaf & IN_BLOCKS == 0 {
            (leaf >> COUNT_BITS, 0, leaf & ((1 << COUNT_BITS) - 1))
        } else {
            let head = &self.blocks[(leaf & !IN_BLOCKS) as usize];
            (head.first, head.triangle_count as u32, head.count as u32)
        }
    }

    /// Whether leaf `leaf` tests its triangles in blocks.
    pub fn in_blocks(leaf: u32) -> bool {
        leaf & IN_BLOCKS != 0
    }

    /// Number of primitives in leaf `leaf`.
    pub fn primitive_count(&self, leaf: u32) -> u32 {
        self.layout(leaf).2
    }

    /// The closest hit in leaf `leaf` with `t ∈ (0, t_max)`, shrinking
    /// `t_max` to it.
    #[inline(always)]
    pub fn closest(
        &self,
        leaf: u32,
        prims: &[PrimRecord],
        o: Vec3A,
        d: Vec3A,
        t_max: &mut f32,
    ) -> Option<Hit> {
        let (first, in_blocks, count) = self.layout(leaf);
        let mut best = None;
        let block = leaf & !IN_BLOCKS;
        // (Splatting the ray here rather than once per ray keeps the leaves
        // without blocks, e.g. the Cornell box's quads, from paying for it.)
        let lanes = Ray4::new(o, d);
        for j in 0..in_blocks.div_ceil(4) {
            let h = self.blocks[(block + j) as usize]
                .triangles
                .intersect(&lanes, *t_max);
            if h.mask != 0 {
                let k = h.nearest();
                *t_max = h.t[k];
                best = Some(Hit {
                    t: h.t[k],
                    prim: first + 4 * j + k as u32,
                    uv: Vec2::new(h.b1[k], h.b2[k]),
                });
            }
        }
        for p in first + in_blocks..first + count {
            if let Some((t, uv)) = prims[p as usize].intersect(o, d, *t_max) {
                *t_max = t;
                best = Some(Hit { t, prim: p, uv });
            }
        }
        best
    }

    /// Whether anything in leaf `leaf` lies on the ray for `t ∈ (0, t_max)`.
    #[inline(always)]
    pub fn any(&self, leaf: u32, prims: &[PrimRecord], o: Vec3A, d: Vec3A, t_max: f32) -> bool {
        let (first, in_blocks, count) = self.layout(leaf);
        let block = leaf & !IN_BLOCKS;
        let lanes = Ray4::new(o, d);
        (0..in_blocks.div_ceil(4)).any(|j| {
            self.blocks[(block + j) as usize]
                .triangles
                .intersect(&lanes, t_max)
                .mask
                != 0
        }) || prims[(first + in_blocks) as usize..(first + count) as usize]
            .iter()
            .any(|p| p.intersect(o, d, t_max).is_some())
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn block_is_ten_vectors() {
        assert_eq!(std::mem::size_of::<super::LeafBlock>(), 160);
    }
}
