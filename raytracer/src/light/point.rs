//! Point lights.
//!
//! Lecture topic: `L_e` of an idealised emitter with no area. A point light of
//! radiant intensity `I` (W/sr) produces, at distance `r`, the irradiance
//! `E = I cos θ / r²` (inverse-square law). Its emission is a Dirac delta in
//! position: next event estimation is its only sampling technique (a BRDF
//! sample never hits it), so [`LightSample::pdf_w`] is 1, meaning "a delta
//! with weight one", and MIS must give it full weight. Its flux is `Φ = 4π I`.

use crate::light::{Emission, LightSample};
use crate::math::{Color, INV_4PI, PI, Ray, Vec2, Vec3A};
use crate::sampling::warp::uniform_sphere;

/// An isotropic point light of radiant intensity `intensity` (W/sr).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointLight {
    pub position: Vec3A,
    pub intensity: Color,
}

impl PointLight {
    /// The only direction to the light, with `L_i = I / r²` (the delta's weight).
    #[inline]
    pub fn sample_li(&self, p: Vec3A) -> Option<LightSample> {
        let d = self.position - p;
        let dist2 = d.length_squared();
        if dist2 == 0.0 {
            return None;
        }
        let dist = dist2.sqrt();
        Some(LightSample {
            wi: d / dist,
            li: self.intensity / dist2,
            pdf_w: 1.0,
            dist,
            p: self.position,
            n: Vec3A::ZERO,
            is_delta: true,
        })
    }

    /// Emits a ray from the light's position in a uniform direction:
    /// `p_A = 1` (the delta), `p_ω = 1/(4π)`, and `le` is the intensity.
    #[inline]
    pub fn sample_le(&self, u_dir: Vec2) -> Emission {
        Emission {
            p: self.position,
            ray: Ray::new(self.position, uniform_sphere(u_dir)),
            n: Vec3A::ZERO,
            le: self.intensity,
            pdf_a: 1.0,
            pdf_w: INV_4PI,
            is_delta_position: true,
        }
    }

    /// Flux `Φ = ∫_{S²} I dω = 4π I`.
    #[inline]
    pub fn power(&self) -> Color {
        4.0 * PI * self.intensity
    }
}
