//! Sphere: centre and radius, with a numerically robust ray intersection.
//!
//! Lecture topic: none of its own (ray-surface intersection).

use crate::math::{PI, Ray, Vec2, Vec3A};

/// A sphere; its geometric normal points outwards.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere {
    pub center: Vec3A,
    pub radius: f32,
}

impl Sphere {
    /// Distance to the first intersection with `t ∈ (0, ray.t_max)`.
    #[inline]
    pub fn intersect(&self, ray: &Ray) -> Option<f32> {
        intersect_sphere(self.center, self.radius, ray.o, ray.d, ray.t_max)
    }

    /// Surface area `4πr²`.
    #[inline]
    pub fn area(&self) -> f32 {
        4.0 * PI * self.radius * self.radius
    }

    /// Outward unit normal at the surface point `p`.
    #[inline]
    pub fn normal(&self, p: Vec3A) -> Vec3A {
        (p - self.center).normalize()
    }

    /// `p` moved radially onto the surface (removes the error of `o + t·d`).
    #[inline]
    pub fn reproject(&self, p: Vec3A) -> Vec3A {
        self.center + self.radius * self.normal(p)
    }

    /// Texture coordinates of the direction `n` from the centre:
    /// `u = φ / 2π` with the longitude `φ = atan2(n_z, n_x) ∈ [0, 2π)` about
    /// the y axis (y is up), `v = θ / π` with the polar angle θ measured
    /// from +y (v = 0 at the north pole, 1 at the south pole).
    #[inline]
    pub fn uv(n: Vec3A) -> Vec2 {
        let phi = n.z.atan2(n.x);
        let phi = if phi < 0.0 { phi + 2.0 * PI } else { phi };
        let theta = n.y.clamp(-1.0, 1.0).acos();
        Vec2::new((phi * (0.5 / PI)).min(1.0), (theta * (1.0 / PI)).min(1.0))
    }
}

/// Ray–sphere intersection for a unit direction `d`.
///
/// With `f = o − c`, the roots of `|f + t·d|² = r²` are `t = −b ± √Δ` with
/// `b = f·d` and `Δ = r² − |f|² + b²`. The last two terms cancel badly for a
/// far-away sphere, so `Δ` is computed as `r² − |f − b·d|²` (the squared
/// distance from the centre to the line; Haines et al., "Precision
/// Improvements for Ray/Sphere Intersection", Ray Tracing Gems ch. 7). The
/// root of larger magnitude `q = −b − sign(b)·√Δ` has no cancellation, the
/// other follows from the product of the roots, `c/q` with `c = |f|² − r²`.
#[inline]
pub fn intersect_sphere(center: Vec3A, radius: f32, o: Vec3A, d: Vec3A, t_max: f32) -> Option<f32> {
    let f = o - center;
    let b = f.dot(d);
    let l = f - b * d;
    let r2 = radius * radius;
    let disc = r2 - l.dot(l);
    if disc < 0.0 {
        return None;
    }
    let q = -b - disc.sqrt().copysign(b);
    if q == 0.0 {
        return None;
    }
    let c = f.dot(f) - r2;
    let (t0, t1) = {
        let (x, y) = (c / q, q);
        if x < y { (x, y) } else { (y, x) }
    };
    if t0 > 0.0 && t0 < t_max {
        Some(t0)
    } else if t1 > 0.0 && t1 < t_max {
        Some(t1)
    } else {
        None
    }
}
