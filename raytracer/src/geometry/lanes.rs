//! Three-vectors in four SIMD lanes (structure of arrays): `[x, y, z]`, each
//! a `Vec4` holding one component of four vectors.
//!
//! Lecture topic: none of its own (ray-surface intersection).
//!
//! Two tests use them: four rays against one triangle ([`super::packet`]) and
//! one ray against four triangles ([`super::triangle4`]). Each operation
//! does per lane exactly what glam's `Vec3A` does for one vector, in the same
//! order (`dot` is `(x·x' + y·y') + z·z'`), so a lane's result equals the
//! scalar test's bit for bit.

use crate::math::{Vec3A, Vec4};

/// Four three-vectors, one per lane.
pub type Lanes3 = [Vec4; 3];

/// The same vector in all four lanes.
#[inline(always)]
pub fn splat(v: Vec3A) -> Lanes3 {
    [Vec4::splat(v.x), Vec4::splat(v.y), Vec4::splat(v.z)]
}

/// `(x·x' + y·y') + z·z'`, the order of glam's `Vec3A::dot`, lane by lane.
#[inline(always)]
pub fn dot(a: &Lanes3, b: &Lanes3) -> Vec4 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

#[inline(always)]
pub fn cross(a: &Lanes3, b: &Lanes3) -> Lanes3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

#[inline(always)]
pub fn sub(a: &Lanes3, b: &Lanes3) -> Lanes3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

#[inline(always)]
pub fn add(a: &Lanes3, b: &Lanes3) -> Lanes3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
