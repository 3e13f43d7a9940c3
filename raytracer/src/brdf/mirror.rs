//! Perfect mirror: a delta BRDF.
//!
//! Lecture topic: "BRDF-и" — ideal specular reflection. The BRDF is the
//! distribution `f_r(ω_i → ω_o) = R δ(ω_i − ω_r) / |cos θ_i|`, `ω_r` the
//! mirror direction of `ω_o`, so that `∫ f_r L_i cos θ_i dω_i = R L_i(ω_r)`.
//! No finite function can be evaluated for it; only sampling makes sense.

use super::BrdfSample;
use crate::math::{Color, Vec3A};

/// Perfect specular reflection with reflectance `reflectance`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mirror {
    pub reflectance: Color,
}

impl Mirror {
    /// The mirror direction of `wo` (upper hemisphere, normal `+z`) with
    /// `f = R/|cos θ_i|` and pdf 1 (the only lobe, always chosen), so the
    /// weight `f |cos θ_i| / pdf` is `R`.
    #[inline]
    pub fn sample(&self, wo: Vec3A) -> Option<BrdfSample> {
        let wi = Vec3A::new(-wo.x, -wo.y, wo.z);
        Some(BrdfSample {
            wi,
            f: self.reflectance / wi.z.abs(),
            pdf_w: 1.0,
            is_delta: true,
            eta: 1.0,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::brdf::testing::directional_albedo;
    use crate::brdf::{Brdf, TransportMode};
    use crate::math::{Vec2, reflect};

    #[test]
    fn reflects_about_the_normal_from_either_side() {
        let m = Brdf::Mirror(Mirror {
            reflectance: Color::new(0.9, 0.8, 0.7),
        });
        for wo in [
            Vec3A::new(0.3, 0.4, 0.866).normalize(),
            Vec3A::new(-0.7, 0.1, -0.2).normalize(),
            Vec3A::Z,
        ] {
            let s = m
                .sample(
                    wo,
                    Vec2::ZERO,
                    0.3,
                    Vec2::new(0.1, 0.2),
                    TransportMode::Radiance,
                )
                .unwrap();
            let n = Vec3A::new(0.0, 0.0, wo.z.signum());
            assert!((s.wi - reflect(wo, n)).length() < 1e-6, "{wo} -> {}", s.wi);
            assert!(s.is_delta && s.pdf_w == 1.0 && s.eta == 1.0);
            let weight = s.f * s.wi.z.abs() / s.pdf_w;
            assert!((weight - Color::new(0.9, 0.8, 0.7)).abs().max_element() < 1e-6);
            assert_eq!(m.eval(wo, s.wi, Vec2::ZERO), Color::ZERO);
            assert_eq!(m.pdf(wo, s.wi, Vec2::ZERO), 0.0);
        }
        assert!(m.is_delta());
        // Grazing: no reflection can be formed.
        assert!(
            m.sample(
                Vec3A::X,
                Vec2::ZERO,
                0.3,
                Vec2::ZERO,
                TransportMode::Radiance
            )
            .is_none()
        );
    }

    #[test]
    fn albedo_is_the_reflectance() {
        let r = Color::new(1.0, 0.5, 0.25);
        let m = Brdf::Mirror(Mirror { reflectance: r });
        for theta in [0.0f32, 45.0, 89.0] {
            let t = theta.to_radians();
            let wo = Vec3A::new(t.sin(), 0.0, t.cos());
            let (mean, _) = directional_albedo(wo, 256, 1, |wo, ul, u| {
                m.sample(wo, Vec2::ZERO, ul, u, TransportMode::Radiance)
            });
            assert!((mean - r).abs().max_element() < 1e-5, "{theta}: {mean}");
        }
    }
}
