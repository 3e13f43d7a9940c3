//! Reference solution of exercise 8 (see `src/ex08_phong_lobe_pdf.rs` for the task).

use raytracer::math::INV_2PI;

/// The density per unit solid angle of the Phong-lobe warp.
pub fn phong_lobe_pdf(n: f32, cos_alpha: f32) -> f32 {
    // P(cos α ≤ t) = t^{n+1}: density (n+1) t^n in t = cos α; dω = dt dφ and
    // φ is uniform over 2π.
    if cos_alpha <= 0.0 {
        return 0.0;
    }
    (n + 1.0) * INV_2PI * cos_alpha.min(1.0).powf(n)
}
