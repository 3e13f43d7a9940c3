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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Vec3;

    fn close(a: Vec3A, b: Vec3A) -> bool {
        (a - b).abs().max_element() < 2e-6
    }

    /// Mitsuba's Cornell box (raytracer/tests/data/cornell_box_mitsuba.txt,
    /// section 4): the boxes are `translate · rotate · scale` of `[-1, 1]³`.
    #[test]
    fn mitsuba_box_corners() {
        let small = Transform::translate(Vec3::new(0.335, -0.7, 0.38))
            * Transform::rotate(Vec3::Y, -17.0)
            * Transform::scale(Vec3::splat(0.3));
        let c = small.apply_point(Vec3A::splat(-1.0));
        assert!(close(c, Vec3A::new(0.13582, -1.0, 0.005397)), "{c}");
        let c = small.apply_point(Vec3A::new(1.0, -1.0, 1.0));
        assert!(close(c, Vec3A::new(0.53418, -1.0, 0.754603)), "{c}");
        // large-box: matrix given by the reference (translate (-0.33,-0.4,-0.28),
        // rotate 18.25° about y, scale (0.3, 0.61, 0.3)).
        let large = Transform::translate(Vec3::new(-0.33, -0.4, -0.28))
            * Transform::rotate(Vec3::Y, 18.25)
            * Transform::scale(Vec3::new(0.3, 0.61, 0.3));
        let c = large.apply_point(Vec3A::new(1.0, 1.0, -1.0));
        assert!(close(c, Vec3A::new(-0.139039, 0.21, -0.658859)), "{c}");
        let c = large.apply_point(Vec3A::splat(-1.0));
        assert!(close(c, Vec3A::new(-0.708859, -1.01, -0.470961)), "{c}");
        // Outward normal of face 2 of the small box (local +x).
        let n = small.apply_normal(Vec3A::X);
        assert!(close(n, Vec3A::new(0.956305, 0.0, 0.292372)), "{n}");
    }

    #[test]
    fn normals_stay_perpendicular_and_inverse_undoes() {
        let t = Transform::translate(Vec3::new(1.0, 2.0, 3.0))
            * Transform::rotate(Vec3::new(1.0, 1.0, 0.0), 30.0)
            * Transform::scale(Vec3::new(2.0, 0.5, 1.0));
        let tangent = Vec3A::new(1.0, -1.0, 0.5);
        let n = Vec3A::new(1.0, 1.0, 0.0).normalize();
        assert!(tangent.dot(n).abs() < 1e-6);
        let (tw, nw) = (t.apply_vector(tangent), t.apply_normal(n));
        assert!(tw.dot(nw).abs() < 1e-5);
        assert!((nw.length() - 1.0).abs() < 1e-6);
        let p = Vec3A::new(0.3, -0.2, 4.0);
        assert!(close(t.inverse().apply_point(t.apply_point(p)), p));
        assert!(!t.flips_handedness());
        assert!(Transform::scale(Vec3::new(-1.0, 1.0, 1.0)).flips_handedness());
    }
}
