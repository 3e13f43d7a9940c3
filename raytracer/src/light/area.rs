//! Area lights: emissive quads and spheres.
//!
//! Lecture topic: the emitted radiance `L_e(x, ω)` of the rendering equation
//! for a diffuse emitter, `L_e = L` (a constant) on the emitting side, and the
//! two ways to sample it:
//! - from a receiver `x` (next event estimation): a point `y` on the light,
//!   turned into a direction `ωi` with its density per unit solid angle (the
//!   change of measure `dω = cos θ_y dA / r²` of the lecture; exercise 12
//!   derives the conversion of the density), or, for a sphere seen from
//!   outside, a direction drawn uniformly in the cone the sphere subtends,
//!   `p_ω = 1 / (2π (1 − cos θ_max))`;
//! - from the light itself (light tracing, bidirectional): a point uniform by
//!   area and a cosine-weighted direction, so that every path that leaves
//!   the light starts with the same share of its emitted flux `Φ`.

use crate::frame::Frame;
use crate::geometry::{Quad, Sphere};
use crate::light::{Emission, LightSample};
use crate::math::{Color, INV_PI, PI, Ray, RayPdf, Vec2, Vec3A, ray_offset};
use crate::sampling::sincos::sincos_turn;
use crate::sampling::warp::{cosine_hemisphere, uniform_sphere};

/// The surface of an area light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum AreaShape {
    Quad(Quad),
    Sphere(Sphere),
}

/// A surface emitting constant radiance `radiance` on the side its normal
/// points to (both sides if `two_sided`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AreaLight {
    pub shape: AreaShape,
    pub radiance: Color,
    pub two_sided: bool,
}

impl AreaShape {
    /// Surface area `A`: `‖e1 × e2‖` for a quad, `4π r²` for a sphere.
    #[inline]
    pub fn area(&self) -> f32 {
        match self {
            AreaShape::Quad(q) => q.e1.cross(q.e2).length(),
            AreaShape::Sphere(s) => 4.0 * PI * s.radius * s.radius,
        }
    }

    /// A point uniform by area (density `1/A`) and the shape's unit normal
    /// there (`normalize(e1 × e2)` for a quad, outwards for a sphere).
    #[inline]
    pub fn sample_area(&self, u: Vec2) -> (Vec3A, Vec3A) {
        match self {
            AreaShape::Quad(q) => (
                q.origin + u.x * q.e1 + u.y * q.e2,
                q.e1.cross(q.e2).normalize(),
            ),
            AreaShape::Sphere(s) => {
                let n = uniform_sphere(u);
                (s.center + s.radius * n, n)
            }
        }
    }
}

/// `1 − cos θ_max` and `cos θ_max` of the cone a sphere of radius `r` subtends
/// from a point at distance² `dc2` from its centre (outside: `dc2 > r²`).
/// `1 − cos θ_max` is computed as `sin²θ_max / (1 + cos θ_max)` to avoid the
/// cancellation of `1 − cos` for small, distant spheres.
#[inline]
fn cone_of_sphere(r: f32, dc2: f32) -> (f32, f32) {
    let sin2_max = (r * r / dc2).min(1.0);
    let cos_max = (1.0 - sin2_max).max(0.0).sqrt();
    (sin2_max / (1.0 + cos_max), cos_max)
}

impl AreaLight {
    /// `L_e(y, ω)` for a point with normal `n_light`, `w` pointing away from
    /// the light: `radiance` on the emitting side (`n·w > 0`) or on both
    /// sides if `two_sided`, zero otherwise.
    #[inline]
    pub fn le(&self, n_light: Vec3A, w: Vec3A) -> Color {
        if self.two_sided || n_light.dot(w) > 0.0 {
            self.radiance
        } else {
            Color::ZERO
        }
    }

    /// Whether a receiver at `p` is inside a sphere light, or so close to its
    /// surface that rounding could put it on either side (then it is sampled
    /// by area, not by cone). Area sampling is unbiased from anywhere; the
    /// cone is only a better choice from clearly outside. A receiver *on* the
    /// sphere (the furnace: the light shining on its own inner wall) would
    /// otherwise be taken for an outside point by rounding, and the cone's
    /// nearest intersection would be the receiver itself. The shell is the
    /// ray offset of the sphere's coordinates ([`ray_offset`]): far wider
    /// than the rounding of a point on the sphere (a few ulps of them), and
    /// the same fraction of the sphere at every scale of the scene.
    #[inline]
    fn inside_sphere(s: &Sphere, p: Vec3A) -> bool {
        let shell = s.radius + ray_offset(s.center.abs().max_element() + s.radius);
        (p - s.center).length_squared() <= shell * shell
    }

    /// Whether the point `q` of a sphere lies on the cap that a receiver at
    /// `p` outside it sees, the only part cone sampling draws:
    /// `(q − c)·(p − c) ≥ r²` (on the boundary the line p q is tangent),
    /// with a relative slack of 1e-4 for the rounding of `q`.
    #[inline]
    fn on_visible_cap(s: &Sphere, p: Vec3A, q: Vec3A) -> bool {
        (q - s.center).dot(p - s.center) >= s.radius * s.radius * (1.0 - 1e-4)
    }

    /// Next event estimation from the receiver `p` (see [`crate::light::Light::sample_li`]).
    pub fn sample_li(&self, p: Vec3A, u: Vec2) -> Option<LightSample> {
        let s = match &self.shape {
            AreaShape::Quad(q) => return self.sample_li_quad(q, p, u),
            AreaShape::Sphere(s) => s,
        };
        let (q, n, pdf_w) = if !Self::inside_sphere(s, p) {
            // Uniform in the cone of directions the sphere subtends. The
            // cone's axis points to the centre; θ is measured from it.
            let to_c = s.center - p;
            let dc2 = to_c.length_squared();
            let dc = dc2.sqrt();
            let (one_minus_cos_max, _) = cone_of_sphere(s.radius, dc2);
            // 1 − cos θ is uniform in [0, 1 − cos θ_max] (the solid angle
            // of a cap grows linearly in 1 − cos θ); then
            // sin²θ = (1 − cos θ)(1 + cos θ) without cancellation.
            let one_minus_cos = u.x * one_minus_cos_max;
            let cos_t = 1.0 - one_minus_cos;
            let sin2_t = (one_minus_cos * (2.0 - one_minus_cos)).max(0.0);
            let sin_t = sin2_t.sqrt();
            let (sin_phi, cos_phi) = sincos_turn(u.y);
            let frame = Frame::from_normal(to_c / dc);
            let wi = frame.to_world(Vec3A::new(sin_t * cos_phi, sin_t * sin_phi, cos_t));
            // Nearest intersection of p + t·wi with the sphere:
            // t = dc cos θ − sqrt(r² − dc² sin²θ) (clamped: rounding may
            // put θ a hair outside the cone, where the ray grazes it).
            let t = dc * cos_t - (s.radius * s.radius - dc2 * sin2_t).max(0.0).sqrt();
            let n = (p + t * wi - s.center).normalize();
            // Re-project onto the sphere so the point lies on its surface.
            let q = s.center + s.radius * n;
            (q, n, 1.0 / (2.0 * PI * one_minus_cos_max))
        } else {
            // Uniform by area, converted to solid angle at p:
            // p_ω = (1/A) · r² / |cos θ_y|.
            let (q, n) = self.shape.sample_area(u);
            let d = q - p;
            let dist2 = d.length_squared();
            let cos_l = n.dot(-d) / dist2.sqrt();
            if cos_l.abs() <= 1e-7 {
                return None;
            }
            (q, n, dist2 / (cos_l.abs() * self.shape.area()))
        };
        let d = q - p;
        let dist = d.length();
        self.light_sample(d / dist, dist, q, n, pdf_w)
    }

    /// [`Self::sample_li`] on a quad: a point `y = origin + u.x e1 + u.y e2`
    /// uniform by area, its density turned into one per unit solid angle.
    /// The area vector `e1 × e2 = A n` gives both the area and the normal,
    /// and `A |cos θ_y| = |(e1 × e2)·(p − y)| / r`: one cross product and two
    /// square roots (A and r) per sample.
    #[inline]
    fn sample_li_quad(&self, quad: &Quad, p: Vec3A, u: Vec2) -> Option<LightSample> {
        let y = quad.origin + u.x * quad.e1 + u.y * quad.e2;
        let area_n = quad.e1.cross(quad.e2);
        let area = area_n.length();
        let d = y - p;
        let dist2 = d.length_squared();
        let dist = dist2.sqrt();
        let wi = d / dist;
        let n = area_n / area;
        // A cos θ_y, signed: positive when the light faces the receiver.
        let area_cos = -area_n.dot(wi);
        if area_cos.abs() <= 1e-7 * area {
            return None;
        }
        self.light_sample(wi, dist, y, n, dist2 / area_cos.abs())
    }

    /// The sample in direction `wi` towards the light point `q` (normal
    /// `n`) at distance `dist`, with density `pdf_w`, or `None` where the
    /// light sends nothing that way or the density is unusable.
    #[inline]
    fn light_sample(
        &self,
        wi: Vec3A,
        dist: f32,
        q: Vec3A,
        n: Vec3A,
        pdf_w: f32,
    ) -> Option<LightSample> {
        let li = self.le(n, -wi);
        if li == Color::ZERO || !(pdf_w > 0.0 && pdf_w.is_finite()) || dist == 0.0 {
            // Behind a one-sided light (or inside a one-sided sphere): the
            // light sends nothing towards p.
            return None;
        }
        Some(LightSample {
            wi,
            li,
            pdf_w,
            dist,
            p: q,
            n,
            is_delta: false,
        })
    }

    /// Solid-angle density of `sample_li` for the direction `wi` from `p`
    /// that hit the light at `p_light` with normal `n_light`. Zero where
    /// `sample_li` never samples: the back of a one-sided light, and for a
    /// sphere seen from outside, every point off the cap that `p` sees (cone
    /// sampling never draws it: a ray from `p` can only reach it through the
    /// sphere, but the density must not rely on that).
    pub fn pdf_li_w(&self, p: Vec3A, p_light: Vec3A, n_light: Vec3A, wi: Vec3A) -> f32 {
        if !self.two_sided && n_light.dot(wi) >= 0.0 {
            return 0.0;
        }
        match &self.shape {
            AreaShape::Sphere(s) if !Self::inside_sphere(s, p) => {
                if !Self::on_visible_cap(s, p, p_light) {
                    return 0.0;
                }
                let (one_minus_cos_max, _) =
                    cone_of_sphere(s.radius, (s.center - p).length_squared());
                1.0 / (2.0 * PI * one_minus_cos_max)
            }
            shape => {
                let dist2 = (p_light - p).length_squared();
                let cos_l = n_light.dot(wi).abs();
                if cos_l <= 1e-7 {
                    return 0.0;
                }
                dist2 / (cos_l * shape.area())
            }
        }
    }

    /// Emits a ray: a point uniform by area (`p_A = 1/A`) and a
    /// cosine-weighted direction on the emitting side (`p_ω = cos θ/π`; a
    /// two-sided light first picks a side with probability 1/2, which halves
    /// `p_ω`). `Emission::n` is the shape's normal, not flipped; the ray's
    /// origin is pushed off the surface towards the direction of travel.
    pub fn sample_le(&self, u_pos: Vec2, u_dir: Vec2) -> Option<Emission> {
        let (p, n) = self.shape.sample_area(u_pos);
        let area = self.shape.area();
        if area <= 0.0 {
            return None;
        }
        let (frame, u, side_prob) = if self.two_sided {
            // Reuse u_dir.x to choose the side, then stretch it back to [0,1).
            if u_dir.x < 0.5 {
                (
                    Frame::from_normal(n),
                    Vec2::new(2.0 * u_dir.x, u_dir.y),
                    0.5,
                )
            } else {
                (
                    Frame::from_normal(-n),
                    Vec2::new(2.0 * u_dir.x - 1.0, u_dir.y),
                    0.5,
                )
            }
        } else {
            (Frame::from_normal(n), u_dir, 1.0)
        };
        let local = cosine_hemisphere(u);
        let cos_t = local.z;
        if cos_t <= 0.0 {
            return None;
        }
        let d = frame.to_world(local);
        Some(Emission {
            p,
            ray: Ray::spawn(p, n, d),
            n,
            le: self.radiance,
            pdf_a: 1.0 / area,
            pdf_w: side_prob * cos_t * INV_PI,
            is_delta_position: false,
        })
    }

    /// `p_A` and `p_ω` of emitting from `p` (normal `n`) in direction `w`.
    pub fn pdf_le(&self, _p: Vec3A, n: Vec3A, w: Vec3A) -> RayPdf {
        let pdf_a = 1.0 / self.shape.area();
        let cos_t = n.dot(w);
        let pdf_w = if self.two_sided {
            0.5 * cos_t.abs() * INV_PI
        } else {
            cos_t.max(0.0) * INV_PI
        };
        RayPdf { pdf_a, pdf_w }
    }

    /// Emitted flux `Φ = ∫_A ∫_Ω L cos θ dω dA = π A L` per emitting side.
    pub fn power(&self) -> Color {
        let sides = if self.two_sided { 2.0 } else { 1.0 };
        self.radiance * (sides * PI * self.shape.area())
    }
}
