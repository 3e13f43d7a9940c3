//! Warps: functions that turn uniform numbers `u ∈ [0,1)²` into points or
//! directions with a known density, each with its pdf and, where cheap, its
//! inverse (which makes round-trip tests easy).
//!
//! Directions are in the local shading frame (`z` is the normal, see
//! [`crate::frame`]); pdfs of directions are per unit solid angle (`pdf_w`),
//! pdfs of points per unit area (`pdf_a`).

use super::sincos::{sincos_small, sincos_turn};
use crate::math::{INV_2PI, INV_4PI, INV_PI, PI, Vec2, Vec3A};

/// Uniform point on the unit disk, by Shirley and Chiu's concentric map
/// (it keeps strata compact and has low distortion).
#[inline]
pub fn concentric_disk(u: Vec2) -> Vec2 {
    let a = 2.0 * u - Vec2::ONE;
    if a.x == 0.0 && a.y == 0.0 {
        return Vec2::ZERO;
    }
    // θ = (π/4)(a_y/a_x) on the left and right wedges; on the top and bottom
    // θ = π/2 − x with x = (π/4)(a_x/a_y), so cos θ = sin x, sin θ = cos x.
    // Both angles x lie in [−π/4, π/4].
    if a.x.abs() > a.y.abs() {
        let (s, c) = sincos_small((PI / 4.0) * (a.y / a.x));
        a.x * Vec2::new(c, s)
    } else {
        let (s, c) = sincos_small((PI / 4.0) * (a.x / a.y));
        a.y * Vec2::new(s, c)
    }
}

/// Density of [`concentric_disk`] per unit area: `1/π`.
#[inline]
pub fn concentric_disk_pdf() -> f32 {
    INV_PI
}

/// Inverse of [`concentric_disk`].
pub fn concentric_disk_inverse(p: Vec2) -> Vec2 {
    let r = p.length();
    if r == 0.0 {
        return Vec2::splat(0.5);
    }
    let mut phi = p.y.atan2(p.x);
    if phi < -PI / 4.0 {
        phi += 2.0 * PI;
    }
    let (a, b) = if phi < PI / 4.0 {
        (r, r * phi / (PI / 4.0))
    } else if phi < 3.0 * PI / 4.0 {
        (-r * (phi - PI / 2.0) / (PI / 4.0), r)
    } else if phi < 5.0 * PI / 4.0 {
        (-r, -r * (phi - PI) / (PI / 4.0))
    } else {
        (r * (phi - 3.0 * PI / 2.0) / (PI / 4.0), -r)
    };
    (Vec2::new(a, b) + Vec2::ONE) * 0.5
}

/// Uniform direction on the upper hemisphere (`z ≥ 0`).
#[inline]
pub fn uniform_hemisphere(u: Vec2) -> Vec3A {
    let z = u.x;
    let r = (1.0 - z * z).max(0.0).sqrt();
    let (sin_phi, cos_phi) = sincos_turn(u.y);
    Vec3A::new(r * cos_phi, r * sin_phi, z)
}

/// Density of [`uniform_hemisphere`]: `1/(2π)` per steradian.
#[inline]
pub fn uniform_hemisphere_pdf() -> f32 {
    INV_2PI
}

/// Inverse of [`uniform_hemisphere`].
#[inline]
pub fn uniform_hemisphere_inverse(w: Vec3A) -> Vec2 {
    Vec2::new(w.z, phi_fraction(w))
}

/// Cosine-weighted direction on the upper hemisphere: its density per unit
/// solid angle is proportional to `cos θ` ([`cosine_hemisphere_pdf`]), which
/// cancels the cosine of the rendering equation.
#[inline]
pub fn cosine_hemisphere(u: Vec2) -> Vec3A {
    let d = concentric_disk(u);
    let z = (1.0 - d.length_squared()).max(0.0).sqrt();
    Vec3A::new(d.x, d.y, z)
}

/// Density of [`cosine_hemisphere`] per steradian, given `cos θ` (0 below
/// the surface).
#[inline]
pub fn cosine_hemisphere_pdf(cos_theta: f32) -> f32 {
    cos_theta.max(0.0) * INV_PI
}

/// Inverse of [`cosine_hemisphere`].
#[inline]
pub fn cosine_hemisphere_inverse(w: Vec3A) -> Vec2 {
    concentric_disk_inverse(Vec2::new(w.x, w.y))
}

/// Uniform direction on the unit sphere.
#[inline]
pub fn uniform_sphere(u: Vec2) -> Vec3A {
    let z = 1.0 - 2.0 * u.x;
    let r = (1.0 - z * z).max(0.0).sqrt();
    let (sin_phi, cos_phi) = sincos_turn(u.y);
    Vec3A::new(r * cos_phi, r * sin_phi, z)
}

/// Density of [`uniform_sphere`]: `1/(4π)` per steradian.
#[inline]
pub fn uniform_sphere_pdf() -> f32 {
    INV_4PI
}

/// Inverse of [`uniform_sphere`].
#[inline]
pub fn uniform_sphere_inverse(w: Vec3A) -> Vec2 {
    Vec2::new((1.0 - w.z) * 0.5, phi_fraction(w))
}

/// Uniform direction inside the cone of half-angle θ_max around `+z`
/// (`cos_theta_max` = cos θ_max). Used to sample the solid angle a sphere
/// subtends.
#[inline]
pub fn uniform_cone(u: Vec2, cos_theta_max: f32) -> Vec3A {
    let z = 1.0 - u.x * (1.0 - cos_theta_max);
    let r = (1.0 - z * z).max(0.0).sqrt();
    let (sin_phi, cos_phi) = sincos_turn(u.y);
    Vec3A::new(r * cos_phi, r * sin_phi, z)
}

/// Density of [`uniform_cone`]: one over the cone's solid angle `2π(1 − cos θ_max)`.
#[inline]
pub fn uniform_cone_pdf(cos_theta_max: f32) -> f32 {
    1.0 / (2.0 * PI * (1.0 - cos_theta_max))
}

/// Inverse of [`uniform_cone`].
#[inline]
pub fn uniform_cone_inverse(w: Vec3A, cos_theta_max: f32) -> Vec2 {
    Vec2::new((1.0 - w.z) / (1.0 - cos_theta_max), phi_fraction(w))
}

/// Uniform point on a triangle, as barycentric coordinates `(b0, b1)` of its
/// first two vertices (the third is `1 − b0 − b1`). Uses the square-root-free
/// map of Heitz, "A Low-Distortion Map Between Triangle and Square" (2019).
/// Its density is `1 / area` of the triangle.
#[inline]
pub fn uniform_triangle(u: Vec2) -> Vec2 {
    let (b0, b1);
    if u.x < u.y {
        b0 = u.x / 2.0;
        b1 = u.y - b0;
    } else {
        b1 = u.y / 2.0;
        b0 = u.x - b1;
    }
    Vec2::new(b0, b1)
}

/// Inverse of [`uniform_triangle`].
#[inline]
pub fn uniform_triangle_inverse(b: Vec2) -> Vec2 {
    // In the first case b1 > b0 (since u.y - u.x/2 > u.x/2).
    if b.y > b.x {
        let ux = 2.0 * b.x;
        Vec2::new(ux, b.y + b.x)
    } else {
        let uy = 2.0 * b.y;
        Vec2::new(b.x + b.y, uy)
    }
}

/// `φ / 2π` of a direction, in `[0, 1)`.
#[inline]
fn phi_fraction(w: Vec3A) -> f32 {
    let phi = w.y.atan2(w.x);
    let f = if phi < 0.0 { phi + 2.0 * PI } else { phi } * INV_2PI;
    if f >= 1.0 { 0.0 } else { f }
}
