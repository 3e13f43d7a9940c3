//! Exercise 5 — normalizing another lobe: a uniform cone.
//!
//! Slides: "BRDF examples" ("Примери за BRDF"), "Properties of BRDFs" ("Свойства на BRDF-ите"), "BRDF examples:
//! a perfect mirror" ("Примери за BRDF: чисто отражение").
//!
//! The lecture normalizes its BRDFs (1/π, `S(n)`) so that they conserve
//! energy. Do it yourself for a lobe the lecture does not show: a "rough
//! mirror" that reflects uniformly into a cone of half-angle θ_m around the
//! mirror direction,
//!
//! ```text
//! f_r(ω_i, ω_o) = ρ · C(θ_m)   if α < θ_m,   0 otherwise,
//! ```
//!
//! α being the angle between `ω_i` and `reflect(ω_o)`, as in exercise 4.
//!
//! Task: derive the constant `C(θ_m)`, in sr⁻¹, that makes the directional
//! albedo `∫_Ω f_r cos θ_i dω_i` exactly ρ at normal incidence (`ω_o = +z`),
//! and return it.
//!
//! Receives: θ_m in radians, `0 < θ_m ≤ π/2`. Returns: `C(θ_m)`.
//!
//! Two checks you can make yourself: at θ_m = π/2 the cone is the whole
//! hemisphere and the lobe must be Lambert's (exercise 3); as θ_m → 0 the
//! lobe narrows to the perfect mirror of exercise 6 and `C` grows without
//! bound — the lecture's "∞" of the mirror.

/// `C(θ_m)`: the normalization of a uniform cone of half-angle `theta_max`.
pub fn cone_lobe_normalization(theta_max: f32) -> f32 {
    // TODO: the albedo at normal incidence is C times an integral over the cone.
    todo!()
}
