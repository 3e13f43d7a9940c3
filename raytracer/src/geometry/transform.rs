//! Transforms applied to shapes when a scene is loaded.
//!
//! Lecture topic: none of its own. Points transform by the matrix, directions
//! by its upper 3×3 part, normals by the inverse transpose of that part (so
//! that they stay perpendicular to transformed tangents: if `n·t = 0` then
//! `(M⁻ᵀn)·(Mt) = nᵀM⁻¹Mt = 0`).

use crate::math::{Mat3, Mat4, Vec3A};

/// An affine transform of points (`matrix * (p, 1)`), as Mitsuba's
/// `to_world`: `translate(t) · rotate(axis, angle) · scale(s)` applies the
/// scale first.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transform {
    pub matrix: Mat4,
}

impl Default for Transform {
    fn default() -> Self {
        Transform::identity()
    }
}

impl Transform {
    pub fn identity() -> Self {
        Transform {
            matrix: Mat4::IDENTITY,
        }
    }

    pub fn translate(t: crate::math::Vec3) -> Self {
        Transform {
            matrix: Mat4::from_translation(t),
        }
    }

    /// Right-handed rotation by `degrees` about `axis` (counter-clockwise
    /// looking down the axis towards the origin).
    pub fn rotate(axis: crate::math::Vec3, degrees: f32) -> Self {
        Transform {
            matrix: Mat4::from_axis_angle(axis.normalize(), degrees.to_radians()),
        }
    }

    pub fn scale(s: crate::math::Vec3) -> Self {
        Transform {
            matrix: Mat4::from_scale(s),
        }
    }

    /// `M·(p, 1)`.
    #[inline]
    pub fn apply_point(&self, p: Vec3A) -> Vec3A {
        self.matrix.transform_point3a(p)
    }

    /// `M·(v, 0)`: directions and edge vectors (not normalized).
    #[inline]
    pub fn apply_vector(&self, v: Vec3A) -> Vec3A {
        self.matrix.transform_vector3a(v)
    }

    /// The unit normal `normalize(M⁻ᵀ·n)`. Computes the inverse each call;
    /// use [`Transform::normal_matrix`] once for many normals.
    #[inline]
    pub fn apply_normal(&self, n: Vec3A) -> Vec3A {
        (self.normal_matrix() * n).normalize()
    }

    /// The inverse transpose of the linear part, `M⁻ᵀ` (3×3).
    pub fn normal_matrix(&self) -> Mat3 {
        Mat3::from_mat4(self.matrix).inverse().transpose()
    }

    /// The inverse transform.
    pub fn inverse(&self) -> Transform {
        Transform {
            matrix: self.matrix.inverse(),
        }
    }

    /// True when the transform mirrors space (negative determinant), which
    /// turns counter-clockwise triangles clockwise.
    pub fn flips_handedness(&self) -> bool {
        Mat3::from_mat4(self.matrix).determinant() < 0.0
    }
}

/// `a * b` applies `b` first, then `a` (as matrices do).
impl std::ops::Mul for Transform {
    type Output = Transform;
    fn mul(self, rhs: Transform) -> Transform {
        Transform {
            matrix: self.matrix * rhs.matrix,
        }
    }
}
