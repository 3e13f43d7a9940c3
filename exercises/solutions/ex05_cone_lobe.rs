//! Reference solution of exercise 5 (see `src/ex05_cone_lobe.rs` for the task).

use raytracer::math::PI;

/// `C(θ_m)`: the normalization of a uniform cone of half-angle `theta_max`.
pub fn cone_lobe_normalization(theta_max: f32) -> f32 {
    // ∫_cone cos θ dω = 2π ∫_0^{θ_m} cos θ sin θ dθ = π sin²θ_m.
    let s = theta_max.sin();
    1.0 / (PI * s * s)
}
