//! Reference solution of exercise 18 (see `src/ex18_metropolis_step.rs` for the task).

use raytracer::render::metropolis::SplatWeights;

/// The probability of accepting a proposal of luminance `f_proposed` from a
/// path of luminance `f_current`.
pub fn acceptance(f_current: f32, f_proposed: f32) -> f32 {
    if f_current > 0.0 {
        (f_proposed / f_current).min(1.0)
    } else {
        1.0
    }
}

/// The expected-value splat weights of one step from `f_current` to a
/// proposal `f_proposed`.
pub fn expected_value_splat(f_current: f32, f_proposed: f32) -> SplatWeights {
    let a = acceptance(f_current, f_proposed);
    let over = |w: f32, f: f32| if f > 0.0 { w / f } else { 0.0 };
    SplatWeights {
        current: over(1.0 - a, f_current),
        proposed: over(a, f_proposed),
    }
}
