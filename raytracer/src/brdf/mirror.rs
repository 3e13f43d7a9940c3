//! Perfect mirror: a delta BRDF.

use crate::math::Color;

/// Perfect specular reflection with reflectance `reflectance`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mirror {
    pub reflectance: Color,
}
