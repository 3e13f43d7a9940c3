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
    /// The mirror direction of `wo` (upper hemisphere, normal `+z`), with the
    /// value and the pdf of the delta convention of [`super`] (exercise 6
    /// derives them): the draw's Monte Carlo weight is `R` at every angle.
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
