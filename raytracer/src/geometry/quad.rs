//! Quad: a parallelogram `origin + a·e1 + b·e2`, `a, b ∈ [0, 1]`.
//!
//! Lecture topic: none of its own (ray-surface intersection); the Cornell
//! box's walls and its light are quads.

use crate::math::{Ray, Vec3A};

/// A parallelogram; its geometric normal is `normalize(e1 × e2)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Quad {
    /// One corner.
    pub origin: Vec3A,
    /// The edge from `origin` to the second corner.
    pub e1: Vec3A,
    /// The edge from `origin` to the fourth corner.
    pub e2: Vec3A,
}

impl Quad {
    /// The first intersection with `t ∈ (0, ray.t_max)`, as `(t, a, b)` with
    /// the hit point `origin + a·e1 + b·e2`.
    #[inline]
    pub fn intersect(&self, ray: &Ray) -> Option<(f32, f32, f32)> {
        intersect_quad(self.origin, self.e1, self.e2, ray.o, ray.d, ray.t_max)
    }

    /// Unit geometric normal `normalize(e1 × e2)`.
    #[inline]
    pub fn normal(&self) -> Vec3A {
        self.e1.cross(self.e2).normalize()
    }

    /// Area `|e1 × e2|`.
    #[inline]
    pub fn area(&self) -> f32 {
        self.e1.cross(self.e2).length()
    }

    /// The point with edge parameters `(a, b)`.
    #[inline]
    pub fn point(&self, a: f32, b: f32) -> Vec3A {
        self.origin + a * self.e1 + b * self.e2
    }
}

/// Slack on the edge parameters of a quad. Two walls meeting at an edge (the
/// corners of the Cornell box) must not let a ray slip between them through
/// rounding: the parameters of a point on the shared edge may come out as
/// `1 + ε` on one wall and `−ε` on the other. Widening each quad by a few
/// ulps of its own size closes the crack without visibly changing its shape.
const QUAD_EPS: f32 = 1e-6;

/// Ray–parallelogram intersection (Möller–Trumbore with the bounds of a
/// parallelogram): solving `o + t·d = p0 + a·e1 + b·e2` by Cramer's rule with
/// `P = d × e2`, `T = o − p0`, `Q = T × e1`, `det = e1·P` gives
/// `a = T·P / det`, `b = d·Q / det`, `t = e2·Q / det`.
#[inline]
pub fn intersect_quad(
    p0: Vec3A,
    e1: Vec3A,
    e2: Vec3A,
    o: Vec3A,
    d: Vec3A,
    t_max: f32,
) -> Option<(f32, f32, f32)> {
    let p = d.cross(e2);
    let det = e1.dot(p);
    if det == 0.0 {
        return None;
    }
    let inv = 1.0 / det;
    let tv = o - p0;
    let a = tv.dot(p) * inv;
    if !(-QUAD_EPS..=1.0 + QUAD_EPS).contains(&a) {
        return None;
    }
    let q = tv.cross(e1);
    let b = d.dot(q) * inv;
    if !(-QUAD_EPS..=1.0 + QUAD_EPS).contains(&b) {
        return None;
    }
    let t = e2.dot(q) * inv;
    (t > 0.0 && t < t_max).then_some((t, a.clamp(0.0, 1.0), b.clamp(0.0, 1.0)))
}
