//! Ray–triangle intersection, watertight.
//!
//! Lecture topic: none of its own (ray-surface intersection).

use crate::math::Vec3A;

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
