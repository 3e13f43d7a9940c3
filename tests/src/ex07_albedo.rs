//! Grader of exercise 7 (Monte Carlo directional albedo): a z-test of the
//! mean of many of the student's estimates against the exact albedo, with
//! the student's own variance.

use raytracer::brdf::{Brdf, Lambert, Phong, Texture};
use raytracer::math::{Color, Vec3A};
use raytracer::sampling::Sampler;

use crate::stats::{MeanVar, ratio_near};

/// The signature of exercise 7.
pub type AlbedoFn = fn(&Brdf, Vec3A, &mut Sampler, u32) -> Color;

/// Independent estimates per case, and samples per estimate.
pub const ESTIMATES: u64 = 2000;
pub const SAMPLES: u32 = 8;

/// The cases: a BRDF, `wo`, its exact albedo.
pub fn cases() -> Vec<(&'static str, Brdf, Vec3A, Color)> {
    let rho = Color::new(0.8, 0.5, 0.2);
    vec![
        (
            "Lambert ρ = (0.8, 0.5, 0.2), wo at 37°",
            Brdf::Lambert(Lambert {
                albedo: Texture::Constant(rho),
            }),
            Vec3A::new(0.6, 0.0, 0.8),
            rho,
        ),
        (
            // At normal incidence the normalized Phong's albedo is exactly ρ_s.
            "Phong ρ_s = 0.9, n = 10, wo = normal",
            Brdf::Phong(Phong {
                albedo: Color::splat(0.9),
                exponent: 10.0,
            }),
            Vec3A::Z,
            Color::splat(0.9),
        ),
    ]
}

pub fn check(f: AlbedoFn) -> Result<(), String> {
    for (k, (what, brdf, wo, exact)) in cases().into_iter().enumerate() {
        let mut stats = MeanVar::default();
        for i in 0..ESTIMATES {
            let mut sampler = Sampler::new(7 + k as u64, i, 0);
            stats.add(f(&brdf, wo, &mut sampler, SAMPLES));
        }
        stats.check(&format!("directional albedo of {what}"), exact, |r| {
            Some(
                if (r / 2.0 - 1.0).abs() < 0.15 {
                    // E[1/cos θ] under cosine sampling is 2 (with a heavy tail).
                    "did you forget the cosine θ_i?"
                } else if ratio_near(r, 2.0 / (3.0 * std::f64::consts::PI)) {
                    "did you forget to divide by the pdf?"
                } else if ratio_near(r, 1.0 / SAMPLES as f64) {
                    "did you divide by N twice?"
                } else if ratio_near(r, SAMPLES as f64) {
                    "divide the sum by N"
                } else if r > 1.0 / exact.max_element() as f64 {
                    "an albedo above 1 creates energy"
                } else {
                    "average f · |cos θ_i| / pdf over the samples"
                }
                .to_string(),
            )
        })?;
    }
    Ok(())
}
