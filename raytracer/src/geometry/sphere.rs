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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hits_front_then_back() {
        let s = Sphere {
            center: Vec3A::new(0.0, 0.0, -5.0),
            radius: 1.0,
        };
        let r = Ray::new(Vec3A::ZERO, -Vec3A::Z);
        assert!((s.intersect(&r).unwrap() - 4.0).abs() < 1e-6);
        // From inside: the far side.
        let r = Ray::new(Vec3A::new(0.0, 0.0, -5.0), -Vec3A::Z);
        assert!((s.intersect(&r).unwrap() - 1.0).abs() < 1e-6);
        // Too short, pointing away, passing beside.
        let r = Ray {
            t_max: 3.9,
            ..Ray::new(Vec3A::ZERO, -Vec3A::Z)
        };
        assert!(s.intersect(&r).is_none());
        assert!(s.intersect(&Ray::new(Vec3A::ZERO, Vec3A::Z)).is_none());
        assert!(
            s.intersect(&Ray::new(Vec3A::new(1.01, 0.0, 0.0), -Vec3A::Z))
                .is_none()
        );
        assert!((s.area() - 4.0 * PI).abs() < 1e-5);
    }

    #[test]
    fn far_small_sphere_is_precise() {
        // |f|² = 1e8 and r² = 1e-4: the naive discriminant loses every digit.
        let s = Sphere {
            center: Vec3A::new(0.0, 0.0, -1e4),
            radius: 0.01,
        };
        let t = s
            .intersect(&Ray::new(Vec3A::new(0.005, 0.0, 0.0), -Vec3A::Z))
            .unwrap();
        let expect = 1e4 - (0.01f64 * 0.01 - 0.005 * 0.005).sqrt();
        assert!((t as f64 - expect).abs() < 2e-3, "{t} vs {expect}");
    }

    #[test]
    fn uv_of_poles_and_equator() {
        assert!(Sphere::uv(Vec3A::Y).y < 1e-6);
        assert!((Sphere::uv(-Vec3A::Y).y - 1.0).abs() < 1e-6);
        let e = Sphere::uv(Vec3A::Z);
        assert!((e.x - 0.25).abs() < 1e-6 && (e.y - 0.5).abs() < 1e-6);
        let w = Sphere::uv(-Vec3A::X);
        assert!((w.x - 0.5).abs() < 1e-6);
    }
}
