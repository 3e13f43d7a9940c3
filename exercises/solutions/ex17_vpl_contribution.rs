//! Reference solution of exercise 17 (see `src/ex17_vpl_contribution.rs` for the task).

use raytracer::math::{Color, Vec3A};

/// The contribution of the VPL at `y` to `x`, with G clamped at `clamp` (0: not clamped).
pub fn vpl_contribution(x: Vec3A, nx: Vec3A, y: Vec3A, ny: Vec3A, fff: Color, clamp: f32) -> Color {
    let d = y - x;
    let d2 = d.length_squared();
    let w = d / d2.sqrt();
    let g = nx.dot(w).abs() * ny.dot(w).abs() / d2;
    let g = if clamp > 0.0 { g.min(clamp) } else { g };
    fff * g
}
