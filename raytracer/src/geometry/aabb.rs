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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn union_grow_area_centroid() {
        let mut b = Aabb::EMPTY;
        assert!(b.is_empty());
        assert_eq!(b.surface_area(), 0.0);
        b.grow(Vec3A::new(0.0, 0.0, 0.0));
        b.grow(Vec3A::new(1.0, 2.0, 3.0));
        assert_eq!(b.surface_area(), 2.0 * (2.0 + 6.0 + 3.0));
        assert_eq!(b.centroid(), Vec3A::new(0.5, 1.0, 1.5));
        assert_eq!(b.largest_axis(), 2);
        let u = b.union(Aabb::from_point(Vec3A::new(-1.0, 5.0, 0.0)));
        assert_eq!(u.min, Vec3A::new(-1.0, 0.0, 0.0));
        assert_eq!(u.max, Vec3A::new(1.0, 5.0, 3.0));
        assert_eq!(Aabb::EMPTY.union(b), b);
        assert!(u.contains(Vec3A::new(0.0, 4.0, 1.0)));
        assert!(!u.contains(Vec3A::new(0.0, 6.0, 1.0)));
    }

    #[test]
    fn slab_test() {
        let b = Aabb::new(Vec3A::splat(-1.0), Vec3A::splat(1.0));
        let o = Vec3A::new(0.0, 0.0, 5.0);
        let d = Vec3A::new(0.0, 0.0, -1.0);
        let (near, far) = b.intersect_ray(o, d.recip(), 0.0, f32::INFINITY).unwrap();
        assert!((near - 4.0).abs() < 1e-6 && (far - 6.0).abs() < 1e-6);
        // Too short a ray, a ray pointing away and a ray passing beside miss.
        assert!(b.intersect_ray(o, d.recip(), 0.0, 3.9).is_none());
        assert!(
            b.intersect_ray(o, (-d).recip(), 0.0, f32::INFINITY)
                .is_none()
        );
        let beside = Vec3A::new(1.5, 0.0, 5.0);
        assert!(
            b.intersect_ray(beside, d.recip(), 0.0, f32::INFINITY)
                .is_none()
        );
        // From inside, the interval starts at t_min.
        let (near, _) = b
            .intersect_ray(Vec3A::ZERO, d.recip(), 0.0, f32::INFINITY)
            .unwrap();
        assert_eq!(near, 0.0);
    }

    /// Zero components give ±1e30 with the sign of the zero, and the entry
    /// side follows that sign; a ray along an axis, starting inside the
    /// other slabs, enters the box.
    #[test]
    fn inverse_direction_keeps_the_sign_of_zero() {
        let down = InverseDirection::new(-Vec3A::Y);
        assert_eq!(down.inv_d, Vec3A::new(-1e30, -1.0, -1e30));
        assert_eq!(down.negative, [1, 1, 1]);
        let up = InverseDirection::new(Vec3A::Y);
        assert_eq!(up.inv_d, Vec3A::new(1e30, 1.0, 1e30));
        assert_eq!(up.negative, [0, 0, 0]);
        let b = Aabb::new(Vec3A::splat(-1.0), Vec3A::splat(1.0));
        let o = Vec3A::new(0.3, 5.0, 0.2);
        let (near, far) = b.intersect_ray(o, down.inv_d, 0.0, f32::INFINITY).unwrap();
        assert_eq!((near, far), (4.0, 6.0));
    }
}
