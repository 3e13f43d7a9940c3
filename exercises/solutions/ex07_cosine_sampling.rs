//! Reference solution of exercise 7 (see `src/ex07_cosine_sampling.rs` for the task).

use raytracer::math::{INV_PI, PI, Vec2, Vec3A};

/// A direction with density `cos θ / π` (Malley: a uniform disk point lifted up).
pub fn sample_cosine_hemisphere(u: Vec2) -> Vec3A {
    let r = u.x.sqrt();
    let phi = 2.0 * PI * u.y;
    let z = (1.0 - u.x).max(0.0).sqrt();
    Vec3A::new(r * phi.cos(), r * phi.sin(), z)
}

/// The density of [`sample_cosine_hemisphere`] per unit solid angle.
pub fn cosine_hemisphere_pdf(w: Vec3A) -> f32 {
    w.z.max(0.0) * INV_PI
}
