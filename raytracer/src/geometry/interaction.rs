//! A surface interaction: a hit point seen from the ray that found it.
//!
//! Lecture topic: the point `x` and the direction `ω_o` of the rendering
//! equation `L_o(x, ω_o)`. Geometry makes it ([`super::Geometry::interaction`]);
//! every estimator starts from one.

use super::SurfacePoint;
use crate::frame::Frame;
use crate::math::{Ray, RayEnd, Vec2, Vec3A};

/// A ray's hit, in the form the estimators of the lecture use: the point `x`,
/// its normals, its shading frame and the direction `ω_o` back along the ray.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interaction {
    pub p: Vec3A,
    /// Geometric normal, as the shape orients it (not flipped towards `wo`).
    pub ng: Vec3A,
    /// Shading frame around the shading normal (same side as `ng`).
    pub frame: Frame,
    pub uv: Vec2,
    /// Unit direction from the hit back towards the ray's origin (`ω_o`).
    pub wo: Vec3A,
    /// Distance from the ray's origin.
    pub t: f32,
    /// Index of the shape hit.
    pub shape: u32,
    /// Bound on the rounding error of each coordinate of `p`
    /// ([`SurfacePoint::p_error`]).
    pub p_error: Vec3A,
}

impl Interaction {
    #[inline]
    pub fn new(sp: SurfacePoint, t: f32, wo: Vec3A) -> Self {
        Interaction {
            p: sp.p,
            ng: sp.ng,
            frame: Frame::from_normal(sp.ns),
            uv: sp.uv,
            wo,
            t,
            shape: sp.shape,
            p_error: sp.p_error,
        }
    }

    /// This point as the end of a ray: position, error bound, normal.
    #[inline]
    pub fn ray_end(&self) -> RayEnd {
        RayEnd {
            p: self.p,
            error: self.p_error,
            n: self.ng,
        }
    }

    /// A ray leaving the surface in world direction `d`.
    #[inline]
    pub fn spawn_ray(&self, d: Vec3A) -> Ray {
        Ray::spawn_from(self.ray_end(), d)
    }

    /// A shadow ray from this point to `q` (normal `nq`, zero for a point
    /// light), whose error is estimated from its magnitude.
    #[inline]
    pub fn spawn_ray_to(&self, q: Vec3A, nq: Vec3A) -> Ray {
        Ray::spawn_between(self.ray_end(), RayEnd::estimated(q, nq))
    }
}
