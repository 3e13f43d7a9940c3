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
    /// the surface it starts on; the point's rounding error is estimated from
    /// its magnitude ([`RayEnd::estimated`]). A hit point carries a tighter
    /// bound: [`Ray::spawn_from`] with its [`RayEnd`].
    #[inline]
    pub fn spawn(p: Vec3A, ng: Vec3A, d: Vec3A) -> Self {
        Ray::spawn_from(RayEnd::estimated(p, ng), d)
    }

    /// A ray leaving the surface point `from` in direction `d`, its origin
    /// pushed off the surface by the point's error bound
    /// ([`offset_ray_origin`]).
    #[inline]
    pub fn spawn_from(from: RayEnd, d: Vec3A) -> Self {
        Ray::new(offset_ray_origin(from.p, from.error, from.n, d), d)
    }

    /// A shadow ray from the surface point `p` (normal `ng`) to the point `q`
    /// (normal `nq`, or zero for a point light or a pinhole), both errors
    /// estimated from the magnitudes ([`RayEnd::estimated`]); see
    /// [`Ray::spawn_between`].
    #[inline]
    pub fn spawn_to(p: Vec3A, ng: Vec3A, q: Vec3A, nq: Vec3A) -> Self {
        Ray::spawn_between(RayEnd::estimated(p, ng), RayEnd::estimated(q, nq))
    }

    /// A shadow ray between two surface points: both ends are pushed off
    /// their surfaces, each towards the other, and `t_max` is the distance
    /// between them, so the test "is anything in between?" hits neither the
    /// start nor the target surface. What it may miss near its ends is only
    /// the offsets, a few roundings of the coordinates; there is no
    /// shortening by a fraction of the length (which made a lampshade a few
    /// centimetres from a bulb transparent to a receiver a kilometre away).
    ///
    /// Why the target's surface cannot be hit: the offset target and the
    /// origin lie on the same side of the target's tangent plane, and so does
    /// the whole segment between them, while a plane, or a sphere, lies on
    /// the other side of it. Seen from the origin, the intersection test of
    /// the target's surface subtracts coordinates as large as the origin's,
    /// so the target is pushed by its own error bound plus `γ₅` of the larger
    /// of both ends' magnitudes.
    #[inline]
    pub fn spawn_between(from: RayEnd, to: RayEnd) -> Self {
        let o = offset_ray_origin(from.p, from.error, from.n, to.p - from.p);
        let target = if to.n == Vec3A::ZERO {
            to.p
        } else {
            let test_error = gamma(5) * from.p.abs().max(to.p.abs());
            offset_ray_origin(to.p, to.error + test_error, to.n, o - to.p)
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

/// One end of a ray on a surface: the point, a bound on how far each of its
/// coordinates may lie from the true surface point (its rounding error), and
/// the geometric normal (zero where there is no surface: a point light, a
/// pinhole).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RayEnd {
    pub p: Vec3A,
    /// Per-coordinate bound on the rounding error of `p` (pbrt's `pError`).
    pub error: Vec3A,
    pub n: Vec3A,
}

impl RayEnd {
    /// A point computed by a few roundings from coordinates of its own
    /// magnitude (a point sampled on a small light or a lens): error
    /// `γ₄ |p|` per coordinate. A hit point knows its own bound
    /// ([`crate::geometry::SurfacePoint::p_error`]).
    #[inline]
    pub fn estimated(p: Vec3A, n: Vec3A) -> Self {
        RayEnd {
            p,
            error: gamma(4) * p.abs(),
            n,
        }
    }
}

/// Higham's `γ_n = n u / (1 − n u)` with `u = 2⁻²⁴` (half an ulp of 1 in
/// `f32`): `n` roundings of a sum or product of floats change it by at most
/// `γ_n` times the sum of the magnitudes of its terms (pbrt-v4, section
/// 6.8.1). The bound of every hit point's error is written with it.
#[inline]
pub fn gamma(n: u32) -> f32 {
    let nu = n as f32 * (0.5 * f32::EPSILON);
    nu / (1.0 - nu)
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

/// Pushes a surface point off its surface, to the side of `ng` where `d`
/// points, beyond its rounding error.
///
/// Floating-point hit points lie a little above or below the true surface, so
/// a new ray started exactly there may hit the same surface again ("shadow
/// acne"). The intersection carries a bound `e` on the error of each
/// coordinate of `p` (pbrt-v4's `pError`, section 6.8.6: `γ₃` of the terms of
/// a quad's `origin + a·e1 + b·e2`, `γ₇` of a triangle's barycentric sum,
/// `γ₅` of a sphere's reprojection); along the normal the point is off by
/// at most `|n_x| e_x + |n_y| e_y + |n_z| e_z`. The origin moves
/// [`OFFSET_SAFETY`] times that, plus the rounding of the moved point
/// itself (`γ₁ |p|`). The offset thus follows the point's own
/// arithmetic, a few ulps of its coordinates: it scales with the scene (a
/// 2-metre box in millimetres or kilometres looks the same) and stays far
/// below its features when the scene is moved away from the origin (the
/// Cornell box's 1 cm lamp gap 1000 m away; an offset of 2⁻¹⁵ of the
/// largest coordinate was 3 cm there; `tests/scale.rs`).
#[inline]
pub fn offset_ray_origin(p: Vec3A, error: Vec3A, ng: Vec3A, d: Vec3A) -> Vec3A {
    let bound = ng.abs().dot(error + gamma(1) * p.abs());
    push_off(p, ng, d, (OFFSET_SAFETY * bound).max(f32::MIN_POSITIVE))
}

/// How many times its error bound a ray origin moves off its surface. pbrt's
/// intersection tests round conservatively, so it moves the origin by the
/// bound alone; ours (Möller–Trumbore, the quad's and sphere's tests) make
/// errors of their own in `t` of the same order (a few roundings of the
/// coordinates they subtract), which the factor covers.
pub const OFFSET_SAFETY: f32 = 4.0;

/// `2⁻¹⁵` of a magnitude `m` (at least the smallest normal float): a shell
/// far wider than any rounding of points of that magnitude (256 to 512 ulps
/// of `m`), for the sphere light's test of a receiver on its surface.
#[inline]
pub fn ray_offset(m: f32) -> f32 {
    (m * (1.0 / 32768.0)).max(f32::MIN_POSITIVE)
}

/// `p` moved by `distance` along `ng`, to the side where `d` points, each
/// moved coordinate then rounded one float further away from `p` (as pbrt's
/// `OffsetRayOrigin`): an offset of a few ulps must not round back onto
/// the surface.
#[inline]
fn push_off(p: Vec3A, ng: Vec3A, d: Vec3A, distance: f32) -> Vec3A {
    let n = if ng.dot(d) < 0.0 { -ng } else { ng };
    let offset = distance * n;
    let o = p + offset;
    let away = |v: f32, by: f32| {
        if by > 0.0 {
            next_float_up(v)
        } else if by < 0.0 {
            -next_float_up(-v)
        } else {
            v
        }
    };
    Vec3A::new(
        away(o.x, offset.x),
        away(o.y, offset.y),
        away(o.z, offset.z),
    )
}

/// The next float above `v` (`f32::next_up`, which needs Rust 1.86; the
/// crate supports 1.85): `±0` goes to the smallest positive subnormal,
/// infinities and NaN stay.
#[inline]
fn next_float_up(v: f32) -> f32 {
    if !v.is_finite() {
        v
    } else if v == 0.0 {
        f32::from_bits(1)
    } else if v > 0.0 {
        f32::from_bits(v.to_bits() + 1)
    } else {
        f32::from_bits(v.to_bits() - 1)
    }
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
