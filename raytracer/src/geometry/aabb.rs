//! Axis-aligned bounding boxes: the bounding volumes of the BVH.
//!
//! Lecture topic: none of its own (acceleration structures); the slab test
//! below is what lets a ray skip whole groups of primitives.

use crate::math::Vec3A;

/// A ray's direction prepared for slab tests: its reciprocal `1/d`, and on
/// which side it enters each slab. The one place where the BVH traversals
/// (binary, four-wide, packets) compute them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InverseDirection {
    /// `1/d`, with components of `d` smaller than 1e-30 in magnitude first
    /// replaced by ±1e-30 of the same sign: the slab distances are then ±huge
    /// instead of `0 · ∞ = NaN` for a ray that starts on a slab's plane.
    pub inv_d: Vec3A,
    /// Per axis, 1 if the ray runs towards −∞ along it (it enters a slab at
    /// the slab's maximum plane), else 0. Taken from the sign of `inv_d`, so
    /// the two always agree: a component −0.0 counts as negative, as its
    /// reciprocal −1e30 does (`d.x < 0.0` would say positive and pick the
    /// planes the wrong way round).
    pub negative: [usize; 3],
}

impl InverseDirection {
    #[inline(always)]
    pub fn new(d: Vec3A) -> Self {
        let tiny = Vec3A::splat(1e-30);
        let inv_d = Vec3A::select(d.abs().cmplt(tiny), tiny.copysign(d), d).recip();
        InverseDirection {
            inv_d,
            negative: [
                (inv_d.x < 0.0) as usize,
                (inv_d.y < 0.0) as usize,
                (inv_d.z < 0.0) as usize,
            ],
        }
    }
}

/// The box `[min, max]` (component-wise). The empty box has `min = +∞`,
/// `max = -∞`, so that growing it by anything gives that thing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    pub min: Vec3A,
    pub max: Vec3A,
}

impl Default for Aabb {
    fn default() -> Self {
        Aabb::EMPTY
    }
}

impl Aabb {
    /// The empty box (identity of [`Aabb::union`]).
    pub const EMPTY: Aabb = Aabb {
        min: Vec3A::splat(f32::INFINITY),
        max: Vec3A::splat(f32::NEG_INFINITY),
    };

    /// The smallest box holding both points (in any order).
    #[inline]
    pub fn new(a: Vec3A, b: Vec3A) -> Aabb {
        Aabb {
            min: a.min(b),
            max: a.max(b),
        }
    }

    /// The box holding the single point `p`.
    #[inline]
    pub fn from_point(p: Vec3A) -> Aabb {
        Aabb { min: p, max: p }
    }

    /// True when the box holds no point.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.min.cmpgt(self.max).any()
    }

    /// Grows the box to hold `p`.
    #[inline]
    pub fn grow(&mut self, p: Vec3A) {
        self.min = self.min.min(p);
        self.max = self.max.max(p);
    }

    /// The smallest box holding both boxes.
    #[inline]
    pub fn union(self, other: Aabb) -> Aabb {
        Aabb {
            min: self.min.min(other.min),
            max: self.max.max(other.max),
        }
    }

    /// `max - min` (negative for the empty box).
    #[inline]
    pub fn diagonal(&self) -> Vec3A {
        self.max - self.min
    }

    /// Surface area `2(dx·dy + dy·dz + dz·dx)`; zero for the empty box. The
    /// SAH uses it as the probability (up to a common factor) that a random
    /// ray hitting the parent box also hits this one.
    #[inline]
    pub fn surface_area(&self) -> f32 {
        if self.is_empty() {
            return 0.0;
        }
        let d = self.diagonal();
        2.0 * (d.x * d.y + d.y * d.z + d.z * d.x)
    }

    /// The centre of the box.
    #[inline]
    pub fn centroid(&self) -> Vec3A {
        0.5 * (self.min + self.max)
    }

    /// The axis (0 = x, 1 = y, 2 = z) along which the box is longest.
    #[inline]
    pub fn largest_axis(&self) -> usize {
        let d = self.diagonal();
        if d.x >= d.y && d.x >= d.z {
            0
        } else if d.y >= d.z {
            1
        } else {
            2
        }
    }

    /// True when `p` lies in the (closed) box.
    #[inline]
    pub fn contains(&self, p: Vec3A) -> bool {
        p.cmpge(self.min).all() && p.cmple(self.max).all()
    }

    /// Slab test: the ray `o + t·d` (given by `inv_d = 1/d`, see
    /// [`InverseDirection`]) overlaps the box
    /// for `t ∈ [t_near, t_far]` with `t_near = max_k min(t0_k, t1_k)` and
    /// `t_far = min_k max(t0_k, t1_k)`, where `t{0,1}_k = (min_k|max_k − o_k)/d_k`
    /// are the distances to the two planes of slab `k`. Returns that interval
    /// clipped to `[t_min, t_max]`, or `None` when it is empty.
    #[inline]
    pub fn intersect_ray(
        &self,
        o: Vec3A,
        inv_d: Vec3A,
        t_min: f32,
        t_max: f32,
    ) -> Option<(f32, f32)> {
        let t0 = (self.min - o) * inv_d;
        let t1 = (self.max - o) * inv_d;
        let near = t0.min(t1).max_element().max(t_min);
        let far = t0.max(t1).min_element().min(t_max);
        (near <= far).then_some((near, far))
    }
}
