//! Smooth glass: Fresnel reflection and refraction.

use crate::math::Color;

/// A smooth dielectric interface; the normal points out of the glass.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Glass {
    /// Index of refraction of the inside relative to the outside (1.5 for glass).
    pub ior: f32,
    /// Colour filter applied to both reflection and refraction (1 = clear).
    pub tint: Color,
}
