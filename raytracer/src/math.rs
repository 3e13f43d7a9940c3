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
    /// (normal `nq`, or zero for a point light or a pinhole): both ends are
    /// pushed off their surfaces, each towards the other, and `t_max` is the
    /// distance between them, so the test "is anything in between?" hits
    /// neither the start nor the target surface. What it may miss near its
    /// ends is only the offsets, which follow the coordinates' magnitudes;
    /// there is no shortening by a fraction of the length (which made a
    /// lampshade a few centimetres from a bulb transparent to a receiver a
    /// kilometre away).
    ///
    /// Why the target's surface cannot be hit: the offset target and the
    /// origin lie on the same side of the target's tangent plane, and so does
    /// the whole segment between them, while a plane, or a sphere, lies on
    /// the other side of it. The target is pushed by the offset of the larger
    /// of both ends' magnitudes (see [`ray_offset`]), which bounds the
    /// rounding of the intersection test along this segment.
    #[inline]
    pub fn spawn_to(p: Vec3A, ng: Vec3A, q: Vec3A, nq: Vec3A) -> Self {
        let o = offset_ray_origin(p, ng, q - p);
        let target = if nq == Vec3A::ZERO {
            q
        } else {
            let scale = p.abs().max(q.abs()).max_element();
            push_off(q, nq, o - q, ray_offset(scale))
        };
        let d = target - o;
        let len = d.length();
        Ray {
            o,
            d: d / len,
            t_max: len,
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

/// Pushes a surface point off its surface, to the side of `ng` where `d` points,
/// by [`ray_offset`] of its largest coordinate.
///
/// Floating-point hit points lie a little above or below the true surface, so a
/// new ray started exactly there may hit the same surface again ("shadow acne").
/// The rounding error of a point computed from coordinates of magnitude `m`
/// (a quad's `origin + a·e1 + b·e2`, a triangle's barycentric sum, a sphere's
/// reprojection) is a few units in the last place of `m`; the point moves
/// along the normal by 256 to 512 of them (`m · 2⁻¹⁵`). This is the idea of
/// Wächter and Binder, "A Fast and Robust Method for Avoiding
/// Self-Intersection" (Ray Tracing Gems, ch. 6), without their absolute
/// offset near the origin: that one (1/65536 m below 1/32 m) was 1.5 % of a
/// Cornell box scaled by 0.001, more than the 1 cm gap between its lamp and
/// ceiling. Relative to the largest coordinate, the offset scales with the
/// scene: a 2-metre box, the same box in millimetres or in kilometres get
/// the same picture (`tests/scale.rs`), and it is far too small to let light
/// leak through the corners where two walls meet. (The point's magnitude
/// stands for the magnitudes it was computed from; a primitive far larger
/// than its distance from the origin, whose points near the origin carry the
/// rounding of its far corners, would need a bound from the primitive.)
#[inline]
pub fn offset_ray_origin(p: Vec3A, ng: Vec3A, d: Vec3A) -> Vec3A {
    push_off(p, ng, d, ray_offset(p.abs().max_element()))
}

/// The distance [`offset_ray_origin`] moves a point whose largest coordinate
/// has magnitude `m`: `m · 2⁻¹⁵` (256 to 512 units in the last place of `m`),
/// and at least the smallest normal float (a point exactly at the origin).
#[inline]
pub fn ray_offset(m: f32) -> f32 {
    (m * (1.0 / 32768.0)).max(f32::MIN_POSITIVE)
}

/// `p` moved by `distance` along `ng`, to the side where `d` points.
#[inline]
fn push_off(p: Vec3A, ng: Vec3A, d: Vec3A, distance: f32) -> Vec3A {
    let n = if ng.dot(d) < 0.0 { -ng } else { ng };
    p + distance * n
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

    /// A point with a coordinate of `-0.0` is pushed off along `-x`: the
    /// offset used to add ulps to the float's bits, and `-0.0`'s bits
    /// (`i32::MIN`) plus a negative offset overflowed — "attempt to add with
    /// overflow" in dev and test builds (OBJ files write `-0.000000`). Every
    /// sign of zero, either side, every axis.
    #[test]
    fn offset_of_signed_zero_coordinates_does_not_overflow() {
        for z in [0.0f32, -0.0] {
            for axis in [Vec3A::X, Vec3A::Y, Vec3A::Z] {
                for side in [1.0, -1.0] {
                    let n = side * axis;
                    for p in [
                        Vec3A::splat(z),
                        Vec3A::new(z, 1.0, 0.0),
                        Vec3A::new(z, z, -2.0),
                    ] {
                        let moved = offset_ray_origin(p, n, n);
                        assert!(moved.is_finite());
                        assert!((moved - p).dot(n) > 0.0, "{p} along {n}: {moved}");
                    }
                }
            }
        }
        let q = offset_ray_origin(Vec3A::new(-0.0, 1.0, 0.0), -Vec3A::X, -Vec3A::X);
        assert!(q.x < 0.0 && q.y == 1.0);
    }

    /// The offset is the same fraction of the scene at every scale: a point
    /// of a 2-metre box and the same point of the box scaled by 10⁻³ or 10³
    /// move by the same fraction of their coordinates (within float
    /// rounding), and the scaled-down box's 1 cm lamp gap stays far wider
    /// than the offset (it was not: 1.5e-5 absolute below 1/32).
    #[test]
    fn offset_scales_with_the_scene() {
        let p = Vec3A::new(0.13, 0.999, -0.4);
        let base = (offset_ray_origin(p, -Vec3A::Y, -Vec3A::Y) - p).length() / 0.999;
        for scale in [1e-3f32, 1e3, 1.0 / 1024.0] {
            let q = p * scale;
            let moved = (offset_ray_origin(q, -Vec3A::Y, -Vec3A::Y) - q).length() / (0.999 * scale);
            assert!(
                (moved / base - 1.0).abs() < 0.02,
                "scale {scale}: {moved} vs {base}"
            );
            // Below 1% of the (scaled) 1 cm gap between lamp and ceiling.
            assert!(
                moved * 0.999 * scale < 0.01 * (0.01 * scale),
                "the lamp gap"
            );
        }
    }

    /// The shadow ray ends exactly at the target pushed off its surface, by
    /// the offset of the coordinates' magnitude (the ray used to stop 1e-4 of
    /// its length short as well: 0.1 m over 1 km, where the offset is 3 cm).
    #[test]
    fn spawn_to_ends_at_the_offset_target() {
        let r = Ray::spawn_to(Vec3A::ZERO, Vec3A::Y, Vec3A::new(0.0, 1.0, 0.0), -Vec3A::Y);
        assert!(r.t_max < 1.0 && r.t_max > 1.0 - 1e-4);
        assert!((r.d - Vec3A::Y).length() < 1e-6);
        let far = Vec3A::new(0.0, 1000.0, 0.0);
        let r = Ray::spawn_to(Vec3A::ZERO, Vec3A::Y, far, -Vec3A::Y);
        let end = r.at(r.t_max).y;
        assert!(
            end < 1000.0 && end > 1000.0 - 2.0 * ray_offset(1000.0),
            "{end}"
        );
        assert!(1000.0 - end < 0.04, "{end}");
        // To a point light (no normal): exactly there.
        let r = Ray::spawn_to(Vec3A::ZERO, Vec3A::Y, far, Vec3A::ZERO);
        assert_eq!(r.o + r.d * r.t_max, far);
    }
}
