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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampling::Sampler;

    #[test]
    fn inverse_square_and_delta() {
        let l = PointLight {
            position: Vec3A::new(0.0, 2.0, 0.0),
            intensity: Color::splat(8.0),
        };
        let s = l.sample_li(Vec3A::ZERO).unwrap();
        assert!((s.li - Color::splat(2.0)).length() < 1e-6);
        assert!((s.wi - Vec3A::Y).length() < 1e-6 && s.dist == 2.0);
        assert!(s.is_delta && s.pdf_w == 1.0 && s.n == Vec3A::ZERO);
        assert!(l.sample_li(l.position).is_none());
    }

    /// Flux by light tracing's estimator `le / p_ω` (p_A = 1) is `4π I`; the
    /// estimator is constant, so the tolerance is float rounding only.
    /// Directions must also cover the sphere: their mean must be near zero
    /// (2^14 samples, std. error of each coordinate 1/sqrt(3·2^14) ≈ 0.0045;
    /// 0.03 is more than 6 σ: false failure < 1e-9).
    #[test]
    fn emitted_flux_and_isotropy() {
        let l = PointLight {
            position: Vec3A::new(1.0, 2.0, 3.0),
            intensity: Color::new(1.0, 2.0, 3.0),
        };
        let n = 1 << 14;
        let mut flux = Color::ZERO;
        let mut mean_dir = Vec3A::ZERO;
        for i in 0..n {
            let e = l.sample_le(Sampler::new(11, i, 0).next_2d());
            assert!(e.is_delta_position && e.ray.o == l.position);
            flux += e.le / (e.pdf_a * e.pdf_w);
            mean_dir += e.ray.d;
        }
        flux /= n as f32;
        mean_dir /= n as f32;
        assert!((flux - l.power()).length() < 1e-3 * l.power().length());
        assert!(mean_dir.abs().max_element() < 0.03, "{mean_dir}");
    }
}
