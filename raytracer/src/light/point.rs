//! Point lights.

use crate::math::{Color, Vec3A};

/// An isotropic point light of radiant intensity `intensity` (W/sr).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointLight {
    pub position: Vec3A,
    pub intensity: Color,
}
