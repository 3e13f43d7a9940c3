//! Unit tests of `sampling/rng.rs`.

use raytracer::sampling::rng::*;

#[test]
fn same_address_same_numbers() {
    let mut a = Sampler::new(7, 1234, 5);
    let mut b = Sampler::new(7, 1234, 5);
    for _ in 0..100 {
        assert_eq!(a.next_1d().to_bits(), b.next_1d().to_bits());
    }
    let mut c = Sampler::new(7, 1234, 6);
    let mut d = Sampler::new(8, 1234, 5);
    let mut a = Sampler::new(7, 1234, 5);
    let (x, y, z) = (a.next_1d(), c.next_1d(), d.next_1d());
    assert!(x != y && x != z && y != z);
}

#[test]
fn set_dimension_addresses_numbers() {
    let mut a = Sampler::new(1, 2, 3);
    let v: Vec<f32> = (0..10).map(|_| a.next_1d()).collect();
    let mut b = Sampler::new(1, 2, 3);
    b.set_dimension(7);
    assert_eq!(b.next_1d(), v[7]);
}

/// Mean and variance of 2^20 numbers against 1/2 and 1/12. The standard
/// error of the mean is sqrt(1/12 / 2^20) ≈ 2.8e-4; a tolerance of 1.5e-3
/// is more than 5 standard errors (false failure < 1e-6). Also a chi-square
/// test over 64 bins across pixels, samples and dimensions.
#[test]
fn uniform_moments_and_histogram() {
    let n = 1 << 20;
    let mut sum = 0.0f64;
    let mut sum_sq = 0.0f64;
    let mut bins = [0u32; 64];
    let mut count = 0;
    for pixel in 0..1024u64 {
        for sample in 0..16u64 {
            let mut s = Sampler::new(42, pixel, sample);
            for _ in 0..64 {
                let x = s.next_1d();
                assert!((0.0..1.0).contains(&x));
                sum += x as f64;
                sum_sq += (x as f64) * (x as f64);
                bins[(x * 64.0) as usize] += 1;
                count += 1;
            }
        }
    }
    assert_eq!(count, n);
    let mean = sum / n as f64;
    let var = sum_sq / n as f64 - mean * mean;
    assert!((mean - 0.5).abs() < 1.5e-3, "mean {mean}");
    assert!((var - 1.0 / 12.0).abs() < 1.5e-3, "variance {var}");
    let expected = n as f64 / 64.0;
    let chi2: f64 = bins
        .iter()
        .map(|&b| (b as f64 - expected).powi(2) / expected)
        .sum();
    // 63 degrees of freedom: the 1e-6 upper quantile is about 130.
    assert!(chi2 < 130.0, "chi-square {chi2}");
}
