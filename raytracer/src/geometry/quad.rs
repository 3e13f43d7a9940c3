//! Quad: a parallelogram `origin + a·e1 + b·e2`, `a, b ∈ [0, 1]`.

use crate::math::Vec3A;

/// A parallelogram; its geometric normal is `normalize(e1 × e2)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Quad {
    /// One corner.
    pub origin: Vec3A,
    /// The edge from `origin` to the second corner.
    pub e1: Vec3A,
    /// The edge from `origin` to the fourth corner.
    pub e2: Vec3A,
}
