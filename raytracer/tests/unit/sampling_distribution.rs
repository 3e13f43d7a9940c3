//! Unit tests of `sampling/distribution.rs`.

use raytracer::math::Vec2;
use raytracer::sampling::distribution::*;

#[test]
fn discrete_probabilities_follow_weights() {
    let d = Distribution1D::new(&[1.0, 0.0, 3.0]);
    assert!((d.discrete_pdf(0) - 0.25).abs() < 1e-6);
    assert_eq!(d.discrete_pdf(1), 0.0);
    assert_eq!(d.sample_discrete(0.1).0, 0);
    assert_eq!(
        d.sample_discrete(0.25).0,
        2,
        "an empty cell is never chosen"
    );
    assert_eq!(d.sample_discrete(0.9999).0, 2);
}

#[test]
fn continuous_density_integrates_to_one_and_matches_samples() {
    let d = Distribution2D::new(&[1.0, 2.0, 0.0, 4.0, 0.5, 0.5], 3, 2);
    // ∫ pdf = 1 on a fine grid.
    let n = 300;
    let mut total = 0.0;
    for j in 0..n {
        for i in 0..n {
            total += d.pdf(Vec2::new(
                (i as f32 + 0.5) / n as f32,
                (j as f32 + 0.5) / n as f32,
            ));
        }
    }
    assert!((total / (n * n) as f32 - 1.0).abs() < 1e-3);
    for k in 0..1000 {
        let u = Vec2::new((k as f32 * 0.618034) % 1.0, (k as f32 + 0.5) / 1000.0);
        let (p, pdf) = d.sample(u);
        assert!((d.pdf(p) - pdf).abs() < 1e-4 * pdf.max(1.0));
        assert!(pdf > 0.0);
    }
}
