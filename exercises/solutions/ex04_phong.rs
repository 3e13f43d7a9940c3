//! Reference solution of exercise 4 (see `src/ex04_phong.rs` for the task).

use raytracer::math::{Color, INV_2PI, Vec3A};

/// `S(n)`: the normalization of the Phong lobe `cos^n α`.
pub fn phong_normalization(n: f32) -> f32 {
    // ∫_{H²} cos^{n+1}θ dω = 2π/(n+2).
    (n + 2.0) * INV_2PI
}

/// `f_r(ω_i → ω_o) = ρ_s · S(n) · max(0, cos α)^n`.
pub fn phong_eval(albedo: Color, n: f32, wo: Vec3A, wi: Vec3A) -> Color {
    let mirror = Vec3A::new(-wo.x, -wo.y, wo.z);
    let cos_a = mirror.dot(wi);
    if cos_a <= 0.0 {
        return Color::ZERO;
    }
    albedo * (phong_normalization(n) * cos_a.min(1.0).powf(n))
}
