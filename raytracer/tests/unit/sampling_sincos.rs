//! Unit tests of `sampling/sincos.rs`.

use raytracer::math::PI;
use raytracer::sampling::sincos::*;

/// Both agree with f64's sin and cos to a few f32 ulps over their domains.
#[test]
fn matches_the_library() {
    let n = 100_000;
    let mut worst = 0.0f64;
    for i in 0..=n {
        let u = i as f32 / n as f32;
        let (s, c) = sincos_turn(u);
        let a = 2.0 * std::f64::consts::PI * u as f64;
        worst = worst
            .max((s as f64 - a.sin()).abs())
            .max((c as f64 - a.cos()).abs());
        let x = (u - 0.5) * (PI / 2.0);
        let (s, c) = sincos_small(x);
        worst = worst
            .max((s as f64 - (x as f64).sin()).abs())
            .max((c as f64 - (x as f64).cos()).abs());
    }
    // The argument 2πu itself is rounded in f32 (half an ulp of 2π,
    // 2.4e-7 at most), so the bound allows for that.
    assert!(worst < 3e-7, "largest error {worst:e}");
}
