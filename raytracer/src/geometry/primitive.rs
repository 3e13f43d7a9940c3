//! The primitive records the BVH leaves point to.
//!
//! Lecture topic: none of its own (ray-surface intersection).
//!
//! Every primitive of a [`super::Geometry`] (a triangle, a quad or a sphere)
//! is stored as one 48-byte [`PrimRecord`] in BVH leaf order, holding exactly
//! what its intersection test needs (a triangle's vertices rather than
//! their indices), so that a leaf's primitives are read from consecutive
//! memory with no indirection. The tests themselves live with their shapes:
//! [`super::triangle`], [`super::quad`], [`super::sphere`].

use super::quad::intersect_quad;
use super::sphere::intersect_sphere;
use super::triangle::intersect_triangle;
use crate::math::{Vec2, Vec3A, Vec4};

/// Kind tags stored in the `w` lane of [`PrimRecord::a`].
pub const KIND_TRIANGLE: u32 = 0;
pub const KIND_QUAD: u32 = 1;
pub const KIND_SPHERE: u32 = 2;

/// One primitive, ready for intersection. `a.w` holds the kind (as bits).
/// - triangle: `a, b, c = v0, v1, v2` (the watertight test needs the
///   vertices themselves, bit for bit as the neighbours see them);
/// - quad: `a = origin`, `b = e1`, `c = e2`;
/// - sphere: `a = centre`, `b.x = radius`.
#[derive(Clone, Copy, Debug)]
#[repr(C, align(16))]
pub struct PrimRecord {
    pub a: Vec4,
    pub b: Vec4,
    pub c: Vec4,
}

impl PrimRecord {
    pub fn triangle(v0: Vec3A, v1: Vec3A, v2: Vec3A) -> Self {
        Self::new(KIND_TRIANGLE, v0, v1, v2)
    }

    pub fn quad(origin: Vec3A, e1: Vec3A, e2: Vec3A) -> Self {
        Self::new(KIND_QUAD, origin, e1, e2)
    }

    pub fn sphere(center: Vec3A, radius: f32) -> Self {
        Self::new(
            KIND_SPHERE,
            center,
            Vec3A::new(radius, 0.0, 0.0),
            Vec3A::ZERO,
        )
    }

    fn new(kind: u32, a: Vec3A, b: Vec3A, c: Vec3A) -> Self {
        PrimRecord {
            a: a.extend(f32::from_bits(kind)),
            b: b.extend(0.0),
            c: c.extend(0.0),
        }
    }

    #[inline(always)]
    pub fn kind(&self) -> u32 {
        self.a.w.to_bits()
    }

    /// The intersection with `t ∈ (0, t_max)` as `(t, surface parameters)`
    /// (see [`super::Hit::uv`]).
    #[inline(always)]
    pub fn intersect(&self, o: Vec3A, d: Vec3A, t_max: f32) -> Option<(f32, Vec2)> {
        let a = Vec3A::from_vec4(self.a);
        let b = Vec3A::from_vec4(self.b);
        let c = Vec3A::from_vec4(self.c);
        match self.kind() {
            KIND_TRIANGLE => {
                intersect_triangle(a, b, c, o, d, t_max).map(|(t, u, v)| (t, Vec2::new(u, v)))
            }
            KIND_QUAD => intersect_quad(a, b, c, o, d, t_max).map(|(t, u, v)| (t, Vec2::new(u, v))),
            _ => intersect_sphere(a, self.b.x, o, d, t_max).map(|t| (t, Vec2::ZERO)),
        }
    }
}
