//! Reference solution of exercise 9 (see `src/ex09_albedo.rs` for the task).

use raytracer::brdf::{Brdf, TransportMode};
use raytracer::math::{Color, Vec2, Vec3A};
use raytracer::sampling::Sampler;

/// A Monte Carlo estimate of `∫ f_r cos θ_i dω_i` for `wo`, by BRDF sampling.
pub fn estimate_albedo(brdf: &Brdf, wo: Vec3A, sampler: &mut Sampler, samples: u32) -> Color {
    let mut sum = Color::ZERO;
    for _ in 0..samples {
        let (u_lobe, u) = (sampler.next_1d(), sampler.next_2d());
        if let Some(s) = brdf.sample(wo, Vec2::ZERO, u_lobe, u, TransportMode::Radiance) {
            sum += s.f * (s.wi.z.abs() / s.pdf_w);
        }
    }
    sum / samples.max(1) as f32
}
