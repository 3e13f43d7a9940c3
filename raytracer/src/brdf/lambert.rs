//! Lambert: the ideal diffuse BRDF.
//!
//! Lecture topic: "BRDF-и" — the constant BRDF. A surface that reflects the
//! same radiance in every direction has `f_r = ρ·k`, with the constant `k`
//! that makes its directional albedo `∫_{H²} f_r cos θ_i dω_i` equal to `ρ`
//! at every angle of incidence (exercise 3 derives it), so `ρ ≤ 1` conserves
//! energy; `f_r` does not depend on the directions at all, so it is
//! trivially reciprocal.

use super::{BrdfSample, Texture};
use crate::math::{Color, INV_PI, Vec2, Vec3A};
use crate::sampling::warp::{cosine_hemisphere, cosine_hemisphere_pdf};

/// Ideal diffuse reflection: a constant `f_r` of albedo ρ from a texture.
#[derive(Clone, Debug)]
pub struct Lambert {
    pub albedo: Texture,
}

impl Lambert {
    /// `f_r` of albedo `ρ(uv)` for directions in the upper hemisphere (the
    /// caller, [`super::Brdf::eval`], handles the sides).
    #[inline]
    pub fn eval(&self, _wo: Vec3A, _wi: Vec3A, uv: Vec2) -> Color {
        self.albedo.eval(uv) * INV_PI
    }

    /// Cosine-weighted sampling (exercise 7): its density cancels both the
    /// cosine and the constant of `f_r`, so every draw's Monte Carlo weight is
    /// ρ exactly.
    #[inline]
    pub fn sample(&self, wo: Vec3A, uv: Vec2, u: Vec2) -> Option<BrdfSample> {
        let wi = cosine_hemisphere(u);
        Some(BrdfSample {
            wi,
            f: self.eval(wo, wi, uv),
            pdf_w: cosine_hemisphere_pdf(wi.z),
            is_delta: false,
            eta: 1.0,
        })
    }

    /// Density of [`Lambert::sample`]: `cos θ_i/π`.
    #[inline]
    pub fn pdf(&self, _wo: Vec3A, wi: Vec3A) -> f32 {
        cosine_hemisphere_pdf(wi.z)
    }
}
