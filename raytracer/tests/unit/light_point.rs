//! Unit tests of `light/point.rs`.

use raytracer::light::point::*;
use raytracer::math::{Color, Vec3A};
use raytracer::sampling::Sampler;

#[test]
fn inverse_square_and_delta() {
    let l = PointLight {
        position: Vec3A::new(0.0, 2.0, 0.0),
        intensity: Color::splat(8.0),
    };
    let s = l.sample_li(Vec3A::ZERO).unwrap();
    assert!((s.li - Color::splat(2.0)).length() < 1e-6);
    assert!((s.wi - Vec3A::Y).length() < 1e-6 && s.dist == 2.0);
    assert!(s.is_delta && s.pdf_w == 1.0 && s.n == Vec3A::ZERO);
    assert!(l.sample_li(l.position).is_none());
}

/// Flux by light tracing's estimator `le / p_ω` (p_A = 1) is `4π I`; the
/// estimator is constant, so the tolerance is float rounding only.
/// Directions must also cover the sphere: their mean must be near zero
/// (2^14 samples, std. error of each coordinate 1/sqrt(3·2^14) ≈ 0.0045;
/// 0.03 is more than 6 σ: false failure < 1e-9).
#[test]
fn emitted_flux_and_isotropy() {
    let l = PointLight {
        position: Vec3A::new(1.0, 2.0, 3.0),
        intensity: Color::new(1.0, 2.0, 3.0),
    };
    let n = 1 << 14;
    let mut flux = Color::ZERO;
    let mut mean_dir = Vec3A::ZERO;
    for i in 0..n {
        let e = l.sample_le(Sampler::new(11, i, 0).next_2d());
        assert!(e.is_delta_position && e.ray.o == l.position);
        flux += e.le / (e.pdf_a * e.pdf_w);
        mean_dir += e.ray.d;
    }
    flux /= n as f32;
    mean_dir /= n as f32;
    assert!((flux - l.power()).length() < 1e-3 * l.power().length());
    assert!(mean_dir.abs().max_element() < 0.03, "{mean_dir}");
}
