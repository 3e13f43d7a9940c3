//! Unit tests of `integrator/roulette.rs`.

use raytracer::integrator::roulette::*;
use raytracer::math::Color;
use raytracer::sampling::Sampler;

/// The survival rate is `q` (capped at `MAX_SURVIVAL`) and the estimate
/// `L'` stays unbiased: 200 000 plays per case, the mean of `L'/L` within
/// 5 standard errors of 1 (false failure < 1e-6 per case). A throughput
/// of zero ends the path without drawing a number.
#[test]
fn survivors_divided_by_q_keep_the_mean() {
    for (throughput, eta_scale, q) in [
        (Color::new(0.3, 0.1, 0.2), 1.0, 0.3),
        (Color::splat(0.2), 2.0, 0.4),
        (Color::splat(5.0), 1.0, MAX_SURVIVAL),
    ] {
        let n = 200_000;
        let (mut survived, mut sum) = (0u32, 0.0f64);
        for i in 0..n {
            let mut s = Sampler::new(3, i, 0);
            if let Some(got) = russian_roulette(throughput, eta_scale, &mut s) {
                assert_eq!(got, q);
                survived += 1;
                sum += 1.0 / got as f64;
            }
            assert_eq!(s.dimension(), 1);
        }
        let mean = sum / n as f64;
        // L'/L is 1/q with probability q: variance (1 − q)/q.
        let se = ((1.0 - q as f64) / q as f64 / n as f64).sqrt();
        assert!((mean - 1.0).abs() < 5.0 * se + 1e-9, "{throughput}: {mean}");
        let rate = survived as f64 / n as f64;
        assert!((rate - q as f64).abs() < 0.01, "{throughput}: rate {rate}");
    }
    let mut s = Sampler::new(3, 0, 0);
    assert_eq!(russian_roulette(Color::ZERO, 1.0, &mut s), None);
    assert_eq!(s.dimension(), 0);
}
