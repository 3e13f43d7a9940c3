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

    /// Cosine-weighted sampling: pdf `cos θ_i/π`, which cancels the cosine
    /// and the `1/π`, so the weight `f cos θ_i / pdf` is ρ exactly.
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::brdf::testing::*;
    use crate::brdf::{Brdf, TransportMode};

    fn lambert(rho: Color) -> Brdf {
        Brdf::Lambert(Lambert {
            albedo: Texture::Constant(rho),
        })
    }

    /// Sampling agrees with the pdf: chi-square at normal, oblique and grazing
    /// incidence, and seen from below (two-sided).
    #[test]
    fn sampling_matches_pdf() {
        let b = lambert(Color::splat(0.7));
        for (k, wo) in [dir(0.0), dir(45.0), dir(89.0), dir(120.0)]
            .into_iter()
            .enumerate()
        {
            chi2_brdf(&b, wo, full_sphere(100 + k as u64)).unwrap();
            check_pdfs(&b, wo).unwrap();
        }
    }

    #[test]
    fn is_reciprocal_and_two_sided() {
        check_reciprocity(&lambert(Color::new(0.2, 0.5, 0.9)));
        let b = lambert(Color::splat(0.5));
        let (wo, wi) = (dir(30.0), dir(70.0));
        let flip = |w: Vec3A| Vec3A::new(w.x, w.y, -w.z);
        assert!((b.eval(wo, wi, Vec2::ZERO) - Color::splat(0.5 * INV_PI)).length() < 1e-7);
        assert_eq!(
            b.eval(wo, wi, Vec2::ZERO),
            b.eval(flip(wo), flip(wi), Vec2::ZERO)
        );
        assert_eq!(
            b.eval(wo, flip(wi), Vec2::ZERO),
            Color::ZERO,
            "no transmission"
        );
        assert_eq!(b.pdf(wo, flip(wi), Vec2::ZERO), 0.0);
    }

    /// Directional albedo = ρ at every angle (within 1%, far more than 5
    /// standard errors; here the estimator even has zero variance).
    #[test]
    fn albedo_is_rho() {
        let rho = Color::new(0.9, 0.5, 0.1);
        let b = lambert(rho);
        for theta in [0.0f32, 30.0, 60.0, 85.0, 150.0] {
            let (mean, se) = directional_albedo(dir(theta), 1 << 14, 7, |wo, ul, u| {
                b.sample(wo, Vec2::ZERO, ul, u, TransportMode::Radiance)
            });
            check_albedo(mean, se, Some(rho)).unwrap();
        }
    }

    /// A Lambert without the 1/π (f = ρ) reflects π times too much: the
    /// albedo check must reject it.
    #[test]
    fn lambert_without_one_over_pi_is_caught() {
        let rho = Color::splat(0.5);
        let good = Lambert {
            albedo: Texture::Constant(rho),
        };
        let (mean, se) = directional_albedo(dir(0.0), 1 << 14, 7, |wo, _, u| {
            good.sample(wo, Vec2::ZERO, u).map(|s| BrdfSample {
                f: s.f * crate::math::PI,
                ..s
            })
        });
        let err = check_albedo(mean, se, Some(rho)).unwrap_err();
        assert!(err.contains("1.57"), "{err}");
        // Even without knowing ρ, energy conservation alone rejects it.
        assert!(check_albedo(mean, se, None).is_err());
    }

    #[test]
    fn textured_albedo_is_looked_up_at_uv() {
        let b = Brdf::Lambert(Lambert {
            albedo: Texture::Checker {
                a: Color::X,
                b: Color::Y,
                scale: 2.0,
            },
        });
        let (wo, wi) = (dir(10.0), dir(20.0));
        assert_eq!(b.eval(wo, wi, Vec2::new(0.1, 0.1)), Color::X * INV_PI);
        assert_eq!(b.eval(wo, wi, Vec2::new(0.6, 0.1)), Color::Y * INV_PI);
    }
}
