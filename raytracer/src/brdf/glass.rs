//! Smooth glass: Fresnel reflection and refraction.
//!
//! Lecture topic: "BRDF-и" — specular surfaces. Strictly a BSDF (it also
//! transmits), with two delta lobes: the mirror direction, taken with the
//! Fresnel probability `F`, and the refracted direction of Snell's law, taken
//! with `1 − F`. Choosing the lobe with the probability of its weight makes
//! every sample carry the weight `tint` (times `1/η²` for radiance through an
//! interface, see [`Glass::sample`]).

use super::fresnel::{fresnel_dielectric, refract};
use super::{BrdfSample, TransportMode};
use crate::math::{Color, Vec3A};

/// A smooth dielectric interface; the normal points out of the glass.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Glass {
    /// Index of refraction of the inside relative to the outside (1.5 for glass).
    pub ior: f32,
    /// Colour filter applied to both reflection and refraction (1 = clear).
    pub tint: Color,
}

impl Glass {
    /// Samples one of the two delta lobes for the local `wo` (`wo.z > 0`:
    /// outside, the path is about to enter; `wo.z < 0`: inside, about to
    /// leave). `u_lobe` chooses reflection if `u_lobe < F`.
    ///
    /// Returned values (pbrt's delta convention, see [`super`]):
    /// - reflection: `wi` = mirror of `wo`, `f = tint·F/|cos θ_i|`, pdf `F`, `eta = 1`;
    /// - refraction: `wi` by Snell's law, `f = tint·(1 − F)/|cos θ_i|` (over
    ///   `η²` for radiance), pdf `1 − F`, `eta = η(wi side)/η(wo side)`,
    ///   which is `ior` when entering and `1/ior` when leaving.
    ///
    /// Why `1/η²` for radiance: radiance is not conserved across an interface,
    /// `L/η²` is (the same flux is squeezed into a solid angle `η²` times
    /// smaller in the denser medium, since `η² cos θ dω` is invariant under
    /// Snell's law). Radiance arriving along `wi` from the medium of index
    /// `η_i` leaves along `wo` in the medium `η_o` as `L_o = (η_o/η_i)² L_i`,
    /// i.e. divided by `eta²`. Importance (light tracing, Veach's thesis §5.2)
    /// flows the other way and the adjoint BSDF has no such factor: the two
    /// factors together make `f_T(wo→wi)/η_o² = f_T(wi→wo)/η_i²`, the
    /// generalized reciprocity of refraction.
    pub fn sample(&self, wo: Vec3A, u_lobe: f32, mode: TransportMode) -> Option<BrdfSample> {
        if wo.z == 0.0 {
            return None;
        }
        let f = fresnel_dielectric(wo.z, self.ior);
        if u_lobe < f {
            let wi = Vec3A::new(-wo.x, -wo.y, wo.z);
            return Some(BrdfSample {
                wi,
                f: self.tint * (f / wi.z.abs()),
                pdf_w: f,
                is_delta: true,
                eta: 1.0,
            });
        }
        // η(wi side)/η(wo side): entering when wo is outside.
        let eta = if wo.z > 0.0 { self.ior } else { 1.0 / self.ior };
        let wi = refract(wo, eta)?;
        let mut ft = self.tint * ((1.0 - f) / wi.z.abs());
        if mode == TransportMode::Radiance {
            ft /= eta * eta;
        }
        Some(BrdfSample {
            wi,
            f: ft,
            pdf_w: 1.0 - f,
            is_delta: true,
            eta,
        })
    }
}
