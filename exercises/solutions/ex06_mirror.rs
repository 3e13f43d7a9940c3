//! Reference solution of exercise 6 (see `src/ex06_mirror.rs` for the task).

use raytracer::brdf::BrdfSample;
use raytracer::math::{Color, Vec3A};

/// The mirror direction of `w` about `n`.
pub fn reflect(w: Vec3A, n: Vec3A) -> Vec3A {
    2.0 * w.dot(n) * n - w
}

/// The one sample of a perfect mirror (`None` if `wo.z ≤ 0`).
pub fn mirror_sample(reflectance: Color, wo: Vec3A) -> Option<BrdfSample> {
    if wo.z <= 0.0 {
        return None;
    }
    let wi = Vec3A::new(-wo.x, -wo.y, wo.z);
    Some(BrdfSample {
        wi,
        f: reflectance / wi.z,
        pdf_w: 1.0,
        is_delta: true,
        eta: 1.0,
    })
}
