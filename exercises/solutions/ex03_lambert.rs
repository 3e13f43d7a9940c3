//! Reference solution of exercise 3 (see `src/ex03_lambert.rs` for the task).

use raytracer::brdf::Texture;
use raytracer::math::{Color, INV_PI, Vec2, Vec3A};

/// `f_r(ω_i → ω_o)` of a textured Lambertian surface.
pub fn lambert_eval(albedo: &Texture, uv: Vec2, wo: Vec3A, wi: Vec3A) -> Color {
    if wo.z <= 0.0 || wi.z <= 0.0 {
        return Color::ZERO;
    }
    albedo.eval(uv) * INV_PI
}
