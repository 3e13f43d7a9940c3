//! Reference solution of exercise 5 (see `src/ex05_mirror.rs` for the task).

use raytracer::brdf::BrdfSample;
use raytracer::math::{Color, Vec3A};

/// The mirror direction of `w` about `n`.
pub fn reflect(w: Vec3A, n: Vec3A) -> Vec3A {
    2.0 * w.dot(n) * n - w
}

/// The one sample of a perfect mirror.
pub fn mirror_sample(reflectance: Color, wo: Vec3A) -> BrdfSample {
    let wi = Vec3A::new(-wo.x, -wo.y, wo.z);
    BrdfSample {
        wi,
        f: reflectance / wi.z.abs(),
        pdf_w: 1.0,
        is_delta: true,
        eta: 1.0,
    }
}
