//! A test integral for MIS: `I = ∫_{H²} (cos θ/π) · 1[θ < θ_m] dω = sin²θ_m`,
//! the irradiance (over π) from a cone of directions around the normal.
//! Strategies: cosine-weighted hemisphere, uniform hemisphere, uniform cone.

use raytracer::math::{INV_PI, Vec2, Vec3A};
use raytracer::sampling::warp::{
    cosine_hemisphere, uniform_cone, uniform_cone_pdf, uniform_hemisphere, uniform_hemisphere_pdf,
};

/// `cos θ_m` of the cone (θ_m = 40°).
pub const COS_MAX: f32 = 0.766_044_4;

/// The exact integral `sin²θ_m`.
pub fn exact() -> f32 {
    1.0 - COS_MAX * COS_MAX
}

/// The integrand.
pub fn g(w: Vec3A) -> f32 {
    if w.z >= COS_MAX { w.z * INV_PI } else { 0.0 }
}

/// A sampling strategy: a direction from `u`, and its pdf for any direction.
#[derive(Clone, Copy, Debug)]
pub enum Strategy {
    Cosine,
    Uniform,
    Cone,
}

impl Strategy {
    pub fn sample(self, u: Vec2) -> Vec3A {
        match self {
            Strategy::Cosine => cosine_hemisphere(u),
            Strategy::Uniform => uniform_hemisphere(u),
            Strategy::Cone => uniform_cone(u, COS_MAX),
        }
    }

    pub fn pdf(self, w: Vec3A) -> f32 {
        match self {
            Strategy::Cosine => w.z.max(0.0) * INV_PI,
            Strategy::Uniform if w.z >= 0.0 => uniform_hemisphere_pdf(),
            Strategy::Cone if w.z >= COS_MAX => uniform_cone_pdf(COS_MAX),
            _ => 0.0,
        }
    }
}
