//! Transforms applied to shapes when a scene is loaded.

use crate::math::Mat4;

/// An affine transform of points (`matrix * (p, 1)`), as Mitsuba's
/// `to_world`: `translate(t) · rotate(axis, angle) · scale(s)` applies the
/// scale first.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transform {
    pub matrix: Mat4,
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
