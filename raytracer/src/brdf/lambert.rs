//! Lambert: the ideal diffuse BRDF.

use super::Texture;

/// Ideal diffuse reflection, `f_r = ρ/π` with albedo ρ from a texture.
#[derive(Clone, Debug)]
pub struct Lambert {
    pub albedo: Texture,
}
