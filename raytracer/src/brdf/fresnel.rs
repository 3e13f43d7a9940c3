//! Fresnel equations and Snell's law for a smooth dielectric interface.
//!
//! Lecture topic: "BRDF-и" — the specular part of a BRDF, glass. How much
//! light a smooth interface between two dielectrics reflects follows from
//! Maxwell's equations (Fresnel, 1823); the rest is refracted by Snell's law
//! `η_i sin θ_i = η_t sin θ_t`.

use crate::math::Vec3A;

/// Unpolarized Fresnel reflectance of a smooth dielectric interface.
///
/// `cos_theta_i` is the cosine between the incident direction and the normal;
/// `eta = η_inside / η_outside` is the relative index of the side the normal
/// does *not* point to (1.5 for glass in air). A negative `cos_theta_i` means
/// the direction lies inside, and the interface is then seen with `1/eta`.
///
/// With `η = η_t/η_i` (the relative index across the interface as the light
/// crosses it) and `cos θ_t = sqrt(1 − sin²θ_i / η²)`, the amplitude
/// reflection coefficients of the two polarizations are
///
/// `r_∥ = (η cos θ_i − cos θ_t) / (η cos θ_i + cos θ_t)`,
/// `r_⊥ = (cos θ_i − η cos θ_t) / (cos θ_i + η cos θ_t)`,
///
/// and unpolarized light reflects `F = (r_∥² + r_⊥²)/2`. If `sin²θ_t ≥ 1`
/// there is no refracted wave: total internal reflection, `F = 1`.
/// At normal incidence `F = ((η − 1)/(η + 1))²`, 0.04 for glass. The value is
/// the same whichever side the light comes from (Helmholtz reciprocity), so it
/// may be computed from `ω_o` as well as from `ω_i`.
#[inline]
pub fn fresnel_dielectric(cos_theta_i: f32, eta: f32) -> f32 {
    let (cos_i, eta) = if cos_theta_i < 0.0 {
        (-cos_theta_i, 1.0 / eta)
    } else {
        (cos_theta_i, eta)
    };
    let cos_i = cos_i.min(1.0);
    let sin2_i = (1.0 - cos_i * cos_i).max(0.0);
    let sin2_t = sin2_i / (eta * eta);
    if sin2_t >= 1.0 {
        return 1.0;
    }
    let cos_t = (1.0 - sin2_t).max(0.0).sqrt();
    let r_par = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    let r_perp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    (0.5 * (r_par * r_par + r_perp * r_perp)).clamp(0.0, 1.0)
}

/// Refracts the local direction `w` (pointing away from the surface, normal
/// `+z`) through the interface; `eta = η_t/η_i` is the index of the side the
/// refracted direction enters over the index of `w`'s side. Returns `None` on
/// total internal reflection.
///
/// With `n` the normal turned to `w`'s side, Snell's law gives the refracted
/// direction `ω_t = −w/η + (cos θ_i/η − cos θ_t) n`, `cos θ_t = sqrt(1 − sin²θ_i/η²)`:
/// its tangential part `−w_⊥/η` has length `sin θ_i/η = sin θ_t`, and its
/// normal part `−cos θ_t` points to the other side.
#[inline]
pub fn refract(w: Vec3A, eta: f32) -> Option<Vec3A> {
    let cos_i = w.z.abs();
    let sin2_t = (1.0 - cos_i * cos_i).max(0.0) / (eta * eta);
    if sin2_t >= 1.0 {
        return None;
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    let n = Vec3A::new(0.0, 0.0, w.z.signum());
    Some(-w / eta + (cos_i / eta - cos_t) * n)
}
