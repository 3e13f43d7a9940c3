//! Exact answers for direct light from polygonal lights, for the grader of
//! next event estimation (exercise 12).
//!
//! The irradiance at a point `x` with normal `n` from a Lambertian polygon of
//! radiance `L` lying wholly above x's tangent plane is Lambert's contour
//! formula (Arvo, "Irradiance Tensors", 1995):
//! `E = (L/2) |Σ_i Θ_i (n · Γ_i)|`, with `Θ_i` the angle between the
//! directions from x to vertices i and i+1 and `Γ_i` the unit normal of the
//! plane through x and that edge. It is linear in the region, so the light
//! that passes beside an occluder is `E(light) − E(shadow)`, where the shadow
//! is the occluder's outline projected from x onto the light's plane (when it
//! lies inside the light).
//!
//! The grader also needs what a *wrong* estimator converges to (a cosine
//! missing, `r` instead of `r²`, …), to name the mistake: those integrals have
//! no closed form here and are computed by [`integrate_over_quad`], a
//! midpoint rule on a fine grid of the light (a deterministic quadrature;
//! accurate to about 1e-5 relative for the smooth integrands used).

use glam::DVec3;
use raytracer::math::Vec3A;

pub fn d(v: Vec3A) -> DVec3 {
    DVec3::new(v.x as f64, v.y as f64, v.z as f64)
}

/// Irradiance at `x` (unit normal `n`) from a polygon of radiance `l`, by
/// Lambert's contour formula. The polygon must lie in front of x's tangent
/// plane (`(v − x)·n > 0` for every vertex v).
pub fn irradiance(x: Vec3A, n: Vec3A, polygon: &[Vec3A], l: f64) -> f64 {
    let (x, n) = (d(x), d(n).normalize());
    let mut sum = 0.0;
    for i in 0..polygon.len() {
        let a = (d(polygon[i]) - x).normalize();
        let b = (d(polygon[(i + 1) % polygon.len()]) - x).normalize();
        let theta = a.dot(b).clamp(-1.0, 1.0).acos();
        sum += theta * n.dot(a.cross(b).normalize());
    }
    0.5 * l * sum.abs()
}

/// The four corners of the parallelogram `origin + a·e1 + b·e2`, `a, b ∈ [0, 1]`.
pub fn corners(origin: Vec3A, e1: Vec3A, e2: Vec3A) -> [Vec3A; 4] {
    [origin, origin + e1, origin + e1 + e2, origin + e2]
}

/// The point where the ray from `x` through `p` meets the plane through
/// `q` with normal `m` (the projection of `p` from `x` onto that plane).
pub fn project_from(x: Vec3A, p: Vec3A, q: Vec3A, m: Vec3A) -> Vec3A {
    let dir = p - x;
    let t = (q - x).dot(m) / dir.dot(m);
    x + t * dir
}

/// `∫_quad g(y) dA_y` by the midpoint rule on an `n × n` grid of the
/// parallelogram `origin + a·e1 + b·e2`.
pub fn integrate_over_quad(
    origin: Vec3A,
    e1: Vec3A,
    e2: Vec3A,
    n: usize,
    g: impl Fn(DVec3) -> f64,
) -> f64 {
    let (o, e1, e2) = (d(origin), d(e1), d(e2));
    let area = e1.cross(e2).length();
    let mut sum = 0.0;
    for j in 0..n {
        for i in 0..n {
            let y = o + e1 * ((i as f64 + 0.5) / n as f64) + e2 * ((j as f64 + 0.5) / n as f64);
            sum += g(y);
        }
    }
    sum * area / (n * n) as f64
}
