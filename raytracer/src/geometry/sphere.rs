//! Sphere: centre and radius.

use crate::math::Vec3A;

/// A sphere; its geometric normal points outwards.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere {
    pub center: Vec3A,
    pub radius: f32,
}
