//! The local shading frame: an orthonormal basis `(s, t, n)` around a normal.
//!
//! BRDFs work in this frame, where the normal is `+z` and `cos θ` of a
//! direction is simply its `z` coordinate (as on the slides about BRDFs,
//! θ is measured from the normal). The frame converts world ↔ local once per
//! shading point.

use crate::math::Vec3A;

/// An orthonormal basis with `n` as its third axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    pub s: Vec3A,
    pub t: Vec3A,
    pub n: Vec3A,
}

impl Frame {
    /// Builds a frame around the unit normal `n` (Duff et al., "Building an
    /// Orthonormal Basis, Revisited": branchless and continuous almost everywhere).
    #[inline]
    pub fn from_normal(n: Vec3A) -> Self {
        let (s, t) = n.any_orthonormal_pair();
        Frame { s, t, n }
    }

    /// World direction → local coordinates (`z` = cos θ).
    #[inline]
    pub fn to_local(&self, v: Vec3A) -> Vec3A {
        Vec3A::new(v.dot(self.s), v.dot(self.t), v.dot(self.n))
    }

    /// Local direction → world coordinates.
    #[inline]
    pub fn to_world(&self, v: Vec3A) -> Vec3A {
        self.s * v.x + self.t * v.y + self.n * v.z
    }

    /// The same frame seen from the other side (normal flipped, still right-handed).
    #[inline]
    pub fn flipped(&self) -> Self {
        Frame {
            s: self.t,
            t: self.s,
            n: -self.n,
        }
    }
}

/// cos θ of a local direction.
#[inline]
pub fn cos_theta(w: Vec3A) -> f32 {
    w.z
}

/// Whether two local directions lie on the same side of the surface.
#[inline]
pub fn same_hemisphere(a: Vec3A, b: Vec3A) -> bool {
    a.z * b.z > 0.0
}
