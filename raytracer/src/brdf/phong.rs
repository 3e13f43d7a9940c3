//! Normalized Phong: a glossy lobe around the mirror direction.
//!
//! Lecture topic: "BRDF-и" — a glossy BRDF that is reciprocal and conserves
//! energy (Lewis, "Making Shaders More Physically Plausible", 1994; the
//! original Phong model is neither).
//!
//! `f_r(ω_i, ω_o) = ρ_s S(n) cos^n α`, with α the angle between `ω_i`
//! and the mirror direction `ω_r` of `ω_o` about the normal, and `f_r = 0`
//! beyond 90° from `ω_r` and below the surface.
//!
//! **Reciprocity.** A reflection keeps angles and is its own inverse, so the
//! angle between `ω_i` and the mirror direction of `ω_o` is the angle between
//! `ω_o` and the mirror direction of `ω_i`: α, hence `f_r`, is symmetric in
//! `ω_i` and `ω_o`.
//!
//! **The constant.** `S(n)` is chosen so that the directional albedo
//! `∫ f_r cos θ_i dω_i` is exactly `ρ_s` at normal incidence, where
//! `ω_r = +z` and `α = θ_i` (the cosine of the rendering equation counts:
//! the lobe alone normalized to 1 is another constant, which lets the
//! albedo exceed `ρ_s`). Exercise 4 derives it; `exercises/INSTRUCTOR.md`
//! has the derivation. At other incidence the lobe (symmetric about `ω_r`)
//! is tilted: part of it falls below the horizon, where `f_r = 0`, and the
//! cosine weights the remaining part less, so the albedo is below `ρ_s` —
//! the model conserves energy for every `ρ_s ≤ 1`.

use super::BrdfSample;
use crate::frame::Frame;
use crate::math::{Color, INV_2PI, PI, Vec2, Vec3A};

/// `f_r = ρ_s S(n) cos^n α`, α the angle between `ω_i` and the mirror
/// direction of `ω_o` (see the module doc for `S(n)`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Phong {
    /// Specular albedo ρ_s (the directional albedo at normal incidence).
    pub albedo: Color,
    /// Phong exponent n ≥ 0.
    pub exponent: f32,
}

/// The mirror direction of `w` about the normal `+z` of the local frame.
#[inline]
pub fn mirror_z(w: Vec3A) -> Vec3A {
    Vec3A::new(-w.x, -w.y, w.z)
}

impl Phong {
    /// The lobe `cos^n α` for `α < 90°`, and 0 outside it (explicitly, so that
    /// `n = 0` gives a hemisphere about `ω_r` and not `0⁰ = 1` everywhere).
    #[inline]
    fn lobe(&self, wo: Vec3A, wi: Vec3A) -> f32 {
        let cos_a = mirror_z(wo).dot(wi);
        if cos_a > 0.0 {
            cos_a.min(1.0).powf(self.exponent)
        } else {
            0.0
        }
    }

    /// `f_r` for `wo`, `wi` in the upper hemisphere (the caller,
    /// [`super::Brdf::eval`], handles the sides and the horizon).
    #[inline]
    pub fn eval(&self, wo: Vec3A, wi: Vec3A) -> Color {
        let n = self.exponent;
        self.albedo * ((n + 2.0) * INV_2PI * self.lobe(wo, wi))
    }

    /// Samples the lobe `cos^n α` about the mirror direction of `wo`: with
    /// density `p(α, φ) ∝ cos^n α sin α` the inverse CDF of `cos α` is
    /// `cos α = (1 − u₁)^{1/(n+1)}`, and `φ = 2π u₂`. Its pdf per solid angle
    /// is proportional to `cos^n α`, normalized over the sphere (exercise 8
    /// derives it).
    /// Directions that fall below the horizon are rejected (`None`); the pdf
    /// stays that of the whole lobe, so accepted directions keep their
    /// density and a Monte Carlo estimate with them stays unbiased (a rejected
    /// sample contributes zero, exactly where `f_r = 0`).
    #[inline]
    pub fn sample(&self, wo: Vec3A, u: Vec2) -> Option<BrdfSample> {
        let n = self.exponent;
        // ln cos α = ln(1 − u₁)/(n+1); 1 − cos α by expm1 keeps sin α accurate
        // in the narrow lobes of large n, where cos α rounds to 1.
        let ln_cos = (-u.x).ln_1p() / (n + 1.0);
        let cos_a = ln_cos.exp();
        let one_minus_cos = -ln_cos.exp_m1();
        let sin_a = (one_minus_cos * (1.0 + cos_a)).max(0.0).sqrt();
        let phi = 2.0 * PI * u.y;
        let local = Vec3A::new(sin_a * phi.cos(), sin_a * phi.sin(), cos_a);
        let wi = Frame::from_normal(mirror_z(wo)).to_world(local);
        if wi.z <= 0.0 {
            return None;
        }
        let lobe = cos_a.powf(n) * INV_2PI;
        Some(BrdfSample {
            wi,
            f: self.albedo * ((n + 2.0) * lobe),
            pdf_w: (n + 1.0) * lobe,
            is_delta: false,
            eta: 1.0,
        })
    }

    /// Density of [`Phong::sample`] per unit solid angle for an accepted `wi`
    /// (upper hemisphere).
    #[inline]
    pub fn pdf(&self, wo: Vec3A, wi: Vec3A) -> f32 {
        let n = self.exponent;
        (n + 1.0) * INV_2PI * self.lobe(wo, wi)
    }
}
