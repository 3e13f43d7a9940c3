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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fresnel_known_values() {
        // Normal incidence: ((1.5 − 1)/(1.5 + 1))² = 0.04, from either side.
        assert!((fresnel_dielectric(1.0, 1.5) - 0.04).abs() < 1e-6);
        assert!((fresnel_dielectric(-1.0, 1.5) - 0.04).abs() < 1e-6);
        // Grazing incidence reflects everything.
        assert!(fresnel_dielectric(1e-4, 1.5) > 0.99);
        // Brewster's angle tan θ_B = η: r_∥ = 0, so F = r_⊥²/2.
        let theta_b = 1.5f32.atan();
        let c = theta_b.cos();
        let cos_t = (1.0 - theta_b.sin().powi(2) / 2.25).sqrt();
        let r_perp = (c - 1.5 * cos_t) / (c + 1.5 * cos_t);
        assert!((fresnel_dielectric(c, 1.5) - 0.5 * r_perp * r_perp).abs() < 1e-6);
        // Total internal reflection beyond the critical angle asin(1/1.5) ≈ 41.8°.
        let critical = (1.0f32 / 1.5).asin();
        assert_eq!(fresnel_dielectric(-(critical + 0.01).cos(), 1.5), 1.0);
        assert!(fresnel_dielectric(-(critical - 0.01).cos(), 1.5) < 1.0);
        // An index-matched interface reflects nothing.
        assert!(fresnel_dielectric(0.3, 1.0).abs() < 1e-7);
    }

    /// Reciprocity: F seen from outside at θ_i equals F seen from inside at θ_t.
    #[test]
    fn fresnel_is_the_same_from_both_sides() {
        for k in 1..50 {
            let cos_i = k as f32 / 50.0;
            let w = Vec3A::new((1.0 - cos_i * cos_i).sqrt(), 0.0, cos_i);
            let t = refract(w, 1.5).unwrap();
            let a = fresnel_dielectric(cos_i, 1.5);
            let b = fresnel_dielectric(t.z, 1.5);
            assert!((a - b).abs() < 1e-5, "cos {cos_i}: {a} vs {b}");
        }
    }

    #[test]
    fn refraction_obeys_snell() {
        for &(z, eta) in &[
            (0.9f32, 1.5f32),
            (0.2, 1.5),
            (-0.95, 1.0 / 1.5),
            (0.5, 1.33),
        ] {
            let w = Vec3A::new(0.6, -0.8, 0.0) * (1.0 - z * z).sqrt() + Vec3A::new(0.0, 0.0, z);
            let t = refract(w, eta).unwrap();
            assert!((t.length() - 1.0).abs() < 1e-5);
            assert!(t.z * w.z < 0.0, "the refracted ray crosses the surface");
            let sin_i = (w.x * w.x + w.y * w.y).sqrt();
            let sin_t = (t.x * t.x + t.y * t.y).sqrt();
            assert!(
                (sin_i - eta * sin_t).abs() < 1e-5,
                "η_i sin θ_i = η_t sin θ_t"
            );
            // In the plane of w and the normal, on the other side of the normal.
            assert!((w.x * t.y - w.y * t.x).abs() < 1e-6);
            assert!(w.x * t.x + w.y * t.y <= 0.0);
        }
        // Beyond the critical angle from inside there is no refracted ray.
        assert!(refract(Vec3A::new(0.8, 0.0, -0.6), 1.0 / 1.5).is_none());
    }
}
