//! Area lights: emissive quads and spheres.

use crate::geometry::{Quad, Sphere};
use crate::math::Color;

/// The surface of an area light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum AreaShape {
    Quad(Quad),
    Sphere(Sphere),
}

/// A surface emitting constant radiance `radiance` on the side its normal
/// points to (both sides if `two_sided`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AreaLight {
    pub shape: AreaShape,
    pub radiance: Color,
    pub two_sided: bool,
}
