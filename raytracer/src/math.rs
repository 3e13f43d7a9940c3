//! Vectors, rays and the numeric conventions every other module relies on.
//!
//! Conventions (used across the whole crate):
//! - right-handed world space, y is up in the built-in scenes, units are metres;
//! - radiance is linear RGB in `f32`, carried as a [`Color`] (a SIMD `Vec3A`);
//! - directions are unit vectors; a direction named `wo` points *away* from a
//!   surface towards the viewer, `wi` points away from it towards the light
//!   (the notation of the rendering equation on the lecture's slides);
//! - angles in scene files are degrees, angles in code are radians.

pub use glam::{Mat3, Mat4, UVec2, Vec2, Vec3, Vec3A, Vec4};

/// Linear RGB radiance, irradiance, albedo or throughput.
pub type Color = Vec3A;

pub const PI: f32 = std::f32::consts::PI;
pub const INV_PI: f32 = std::f32::consts::FRAC_1_PI;
pub const INV_2PI: f32 = 0.5 * std::f32::consts::FRAC_1_PI;
pub const INV_4PI: f32 = 0.25 * std::f32::consts::FRAC_1_PI;

/// A half-line `o + t·d` for `t` in `(0, t_max)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    /// Origin.
    pub o: Vec3A,
    /// Direction (unit length unless a function says otherwise).
    pub d: Vec3A,
    /// Far end of the ray; `f32::INFINITY` for an unbounded ray.
    pub t_max: f32,
}

impl Ray {
    #[inline]
    pub fn new(o: Vec3A, d: Vec3A) -> Self {
        Ray {
            o,
            d,
            t_max: f32::INFINITY,
        }
    }

    #[inline]
    pub fn at(&self, t: f32) -> Vec3A {
        self.o + t * self.d
    }

    /// A ray leaving the surface point `p` (with geometric normal `ng`) in
    /// direction `d`, its origin pushed off the surface so that it cannot hit
    /// the surface it starts on (see [`offset_ray_origin`]).
    #[inline]
    pub fn spawn(p: Vec3A, ng: Vec3A, d: Vec3A) -> Self {
        Ray::new(offset_ray_origin(p, ng, d), d)
    }

    /// A shadow ray from the surface point `p` (normal `ng`) to the point `q`
    /// (normal `nq`, or zero for a point light): both ends are pushed off
    /// their surfaces and `t_max` stops just short of `q`, so the test
    /// "is anything in between?" neither hits the start nor the target.
    #[inline]
    pub fn spawn_to(p: Vec3A, ng: Vec3A, q: Vec3A, nq: Vec3A) -> Self {
        let o = offset_ray_origin(p, ng, q - p);
        let target = if nq == Vec3A::ZERO {
            q
        } else {
            offset_ray_origin(q, nq, o - q)
        };
        let d = target - o;
        let len = d.length();
        Ray {
            o,
            d: d / len,
            t_max: len * (1.0 - 1e-4),
        }
    }
}

/// The densities with which a ray leaving a lens or a light was generated:
/// its origin per unit area and its direction per unit solid angle, kept
/// apart (bidirectional MIS converts the direction's density to area
/// measure at whatever the ray reaches).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RayPdf {
    /// Density of the origin per unit area.
    pub pdf_a: f32,
    /// Density of the direction per unit solid angle.
    pub pdf_w: f32,
}

/// Pushes a surface point off its surface, to the side of `ng` where `d` points.
///
/// Floating-point hit points lie a little above or below the true surface, so a
/// new ray started exactly there may hit the same surface again ("shadow acne").
/// This follows Wächter and Binder, "A Fast and Robust Method for Avoiding
/// Self-Intersection" (Ray Tracing Gems, ch. 6): move the point along the normal
/// by a few units in the last place of each coordinate (integer arithmetic on the
/// float bits), and by a small absolute amount near the origin where ulps vanish.
/// The offset scales with the magnitude of the coordinates, so it works for a
/// 2-metre Cornell box and a 1000-metre landscape alike, and it is far too small
/// to let light leak through the corners where two walls meet.
#[inline]
pub fn offset_ray_origin(p: Vec3A, ng: Vec3A, d: Vec3A) -> Vec3A {
    const ORIGIN: f32 = 1.0 / 32.0;
    const FLOAT_SCALE: f32 = 1.0 / 65536.0;
    const INT_SCALE: f32 = 256.0;
    let n = if ng.dot(d) < 0.0 { -ng } else { ng };
    let of_i = n * INT_SCALE;
    let nudge = |p: f32, n: f32, of: f32| -> f32 {
        let bits = p.to_bits() as i32;
        let of = of as i32;
        let moved = f32::from_bits((bits + if p < 0.0 { -of } else { of }) as u32);
        if p.abs() < ORIGIN {
            p + FLOAT_SCALE * n
        } else {
            moved
        }
    };
    Vec3A::new(
        nudge(p.x, n.x, of_i.x),
        nudge(p.y, n.y, of_i.y),
        nudge(p.z, n.z, of_i.z),
    )
}

/// Luminance of linear sRGB/Rec. 709 primaries (used for Russian roulette and
/// for image statistics).
#[inline]
pub fn luminance(c: Color) -> f32 {
    0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z
}

/// Reflects `w` about `n` (both unit; `w` points away from the surface).
#[inline]
pub fn reflect(w: Vec3A, n: Vec3A) -> Vec3A {
    2.0 * w.dot(n) * n - w
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn offset_origin_moves_to_the_side_of_the_direction() {
        for &p in &[
            Vec3A::new(0.3, -1.0, 0.2),
            Vec3A::new(100.0, 2000.0, -3.0),
            Vec3A::ZERO,
        ] {
            let n = Vec3A::Y;
            let up = offset_ray_origin(p, n, Vec3A::Y);
            let down = offset_ray_origin(p, n, -Vec3A::Y);
            assert!(up.y > p.y && down.y < p.y, "{p} -> {up} / {down}");
            // Tiny compared with the scale of the point.
            assert!((up - p).length() <= 1e-3 * (1.0 + p.abs().max_element()));
        }
    }

    #[test]
    fn spawn_to_stops_short_of_the_target() {
        let r = Ray::spawn_to(Vec3A::ZERO, Vec3A::Y, Vec3A::new(0.0, 1.0, 0.0), -Vec3A::Y);
        assert!(r.t_max < 1.0 && r.t_max > 0.99);
        assert!((r.d - Vec3A::Y).length() < 1e-6);
    }
}
