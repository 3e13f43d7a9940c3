//! Normalized Phong: a glossy lobe around the mirror direction.

use crate::math::Color;

/// `f_r = ρ_s (n+2)/(2π) cos^n α`, α the angle between `ω_i` and the mirror
/// direction of `ω_o`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Phong {
    /// Specular albedo ρ_s (the directional albedo at normal incidence).
    pub albedo: Color,
    /// Phong exponent n ≥ 0.
    pub exponent: f32,
}
