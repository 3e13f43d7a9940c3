//! Exercise 5 — the perfect mirror, a delta BRDF.
//!
//! Slide: "Examples of BRDFs (2)" ("Примери за BRDF", perfect reflection):
//! `f_r = ∞` if `ω_o = reflect(ω_i)`, 0 otherwise — a BRDF need not be a
//! function one can evaluate; only sampling can find the mirror direction.
//!
//! Part 1: `reflect(w, n)`: the mirror direction of the unit vector `w`
//! about the unit normal `n` (world space; `w` points away from the surface,
//! so does the result).
//!
//! Part 2: `mirror_sample(reflectance, wo)`: the BRDF sample of a mirror in
//! the local frame (normal `+z`): the direction `wi` is the mirror direction
//! of `wo`; the lobe is a delta (`is_delta: true`), chosen with probability
//! `pdf_w = 1`; and the value `f` must be such that the path tracer's usual
//! weight `f · |cos θ_i| / pdf_w` equals the reflectance `R` (the integral
//! `∫ f_r L_i cos θ_i dω_i` of a delta is `R · L_i(ω_r)`). `eta` is 1.
//!
//! Receives: `w`, `n` / the reflectance `R` and `wo`. Returns: the reflected
//! direction / a [`BrdfSample`].

use raytracer::brdf::BrdfSample;
use raytracer::math::{Color, Vec3A};

/// The mirror direction of `w` about `n`.
pub fn reflect(w: Vec3A, n: Vec3A) -> Vec3A {
    // TODO: draw w, n and the result; the component along n stays.
    todo!()
}

/// The one sample of a perfect mirror.
pub fn mirror_sample(reflectance: Color, wo: Vec3A) -> BrdfSample {
    // TODO: wi, then f such that f·|cos θ_i|/pdf_w = R.
    todo!()
}
