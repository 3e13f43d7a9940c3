//! Ray–triangle intersection and the primitive records the BVH leaves point to.
//!
//! Lecture topic: none of its own (ray-surface intersection).
//!
//! Every primitive of a [`super::Geometry`] (a triangle, a quad or a sphere)
//! is stored as one 48-byte [`PrimRecord`] in BVH leaf order, holding exactly
//! what its intersection test needs (a triangle's vertices rather than
//! their indices), so that a leaf's primitives are read from consecutive
//! memory with no indirection.

use super::quad::intersect_quad;
use super::sphere::intersect_sphere;
use crate::math::{Vec2, Vec3A, Vec4};

/// Watertight ray–triangle intersection for the triangle `v0, v1, v2`
/// (both sides are hit). Returns `(t, b1, b2)` for `t ∈ (0, t_max)`, with
/// the hit point `(1 − b1 − b2)·v0 + b1·v1 + b2·v2`.
///
/// With the vertices relative to the ray origin, `a = v0 − o`, `b = v1 − o`,
/// `c = v2 − o`, the line `o + t·d` passes through the triangle when the
/// three signed volumes `d·(b × c)`, `d·(c × a)`, `d·(a × b)` (each the
/// Plücker product of the ray with one edge) have the same sign; normalized
/// by their sum they are the barycentric coordinates of the hit. Each is
/// computed from its edge as `d·((q − p) × (q + p)) = 2 d·(p × q)`, which is
/// more accurate (short edge times the sum), and *exactly* negated when a
/// neighbouring triangle computes it for the same edge in the other
/// direction: `p − q = −(q − p)` and `p + q = q + p` hold in floating point.
/// So a ray crossing a shared edge meets one of the two triangles (or both),
/// never neither: meshes do not leak (Möller–Trumbore gives no such
/// guarantee). The distance is `t = (a·n)/(d·n)` with the normal
/// `n = (b − a) × (c − a)`.
#[inline(always)]
pub fn intersect_triangle(
    v0: Vec3A,
    v1: Vec3A,
    v2: Vec3A,
    o: Vec3A,
    d: Vec3A,
    t_max: f32,
) -> Option<(f32, f32, f32)> {
    let (a, b, c) = (v0 - o, v1 - o, v2 - o);
    let (e_ca, e_ab, e_bc) = (c - a, a - b, b - c);
    let w1 = d.dot(e_ca.cross(c + a)); // ∝ b1 (edge v2 v0)
    let w2 = d.dot(e_ab.cross(a + b)); // ∝ b2 (edge v0 v1)
    let w0 = d.dot(e_bc.cross(b + c)); // ∝ b0 (edge v1 v2)
    let lo = w0.min(w1).min(w2);
    let hi = w0.max(w1).max(w2);
    if lo < 0.0 && hi > 0.0 {
        return None;
    }
    let den = w0 + w1 + w2;
    if den == 0.0 {
        return None;
    }
    let n = e_ca.cross(e_ab); // = (b − a) × (c − a)
    let t = a.dot(n) / d.dot(n);
    if !(t > 0.0 && t < t_max) {
        return None;
    }
    let inv = 1.0 / den;
    Some((t, w1 * inv, w2 * inv))
}

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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn triangle_hit_and_barycentrics() {
        let (v0, v1, v2) = (Vec3A::ZERO, Vec3A::X, Vec3A::Y);
        let o = Vec3A::new(0.25, 0.5, 1.0);
        let (t, b1, b2) = intersect_triangle(v0, v1, v2, o, -Vec3A::Z, 10.0).unwrap();
        assert!((t - 1.0).abs() < 1e-6 && (b1 - 0.25).abs() < 1e-6 && (b2 - 0.5).abs() < 1e-6);
        // Outside the hypotenuse, too far, parallel.
        let o2 = Vec3A::new(0.6, 0.6, 1.0);
        assert!(intersect_triangle(v0, v1, v2, o2, -Vec3A::Z, 10.0).is_none());
        assert!(intersect_triangle(v0, v1, v2, o, -Vec3A::Z, 0.5).is_none());
        assert!(intersect_triangle(v0, v1, v2, o, Vec3A::X, 10.0).is_none());
        let rec = PrimRecord::triangle(v0, v1, v2);
        assert_eq!(rec.kind(), KIND_TRIANGLE);
        let (t2, uv) = rec.intersect(o, -Vec3A::Z, 10.0).unwrap();
        assert_eq!((t2, uv), (t, Vec2::new(b1, b2)));
    }

    /// A ray through the shared edge of two triangles hits at least one.
    #[test]
    fn shared_edges_are_watertight() {
        let (p, q) = (Vec3A::new(0.1, 0.2, 0.3), Vec3A::new(0.9, 0.7, 0.35));
        let (l, r) = (Vec3A::new(0.0, 1.0, 0.3), Vec3A::new(1.0, -0.2, 0.31));
        let mut s = crate::sampling::Sampler::new(1, 2, 3);
        for _ in 0..20_000 {
            let e = p + s.next_1d() * (q - p);
            let o = Vec3A::new(s.next_1d(), s.next_1d(), 2.0 + s.next_1d());
            let d = (e - o).normalize();
            let left = intersect_triangle(p, q, l, o, d, f32::INFINITY);
            let right = intersect_triangle(q, p, r, o, d, f32::INFINITY);
            assert!(
                left.is_some() || right.is_some(),
                "ray to {e} slipped through"
            );
        }
    }
}
