//! Unit tests of `bias.rs`.

use lesson11::bias::*;
use raytracer::film::Image;
use raytracer::math::Color;

/// A deterministic stand-in for noise: ±1 by a hash of (run, pixel),
/// so that each pixel's values have mean 0 and variance 1 over even K.
fn sign(run: usize, pixel: usize) -> f32 {
    let h = (run as u64).wrapping_mul(0x9e37_79b9_7f4a_7c15)
        ^ (pixel as u64).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    if (h.wrapping_mul(0x94d0_49bb_1331_11eb) >> 63) == 0 {
        1.0
    } else {
        -1.0
    }
}

fn runs(k: usize, bias: f32, sigma: f32) -> (Vec<Image>, Image, Image) {
    let reference = Image::from_fn(16, 16, |x, _| Color::splat(0.1 * x as f32));
    let zero = Image::from_fn(16, 16, |_, _| Color::ZERO);
    let runs = (0..k)
        .map(|r| {
            Image::from_fn(16, 16, |x, y| {
                let p = (y * 16 + x) as usize;
                reference.get(x, y) + Color::splat(bias + sigma * sign(r, p))
            })
        })
        .collect();
    (runs, reference, zero)
}

/// Exact answers: runs of a constant offset b with no noise have
/// bias² = b² and variance 0, at zero standard error.
#[test]
fn a_constant_offset_is_all_bias() {
    let (runs, reference, zero) = runs(4, 0.3, 0.0);
    let split = split(&runs, &reference, &zero, &[true; 256]);
    assert!((split.bias2 - 0.09).abs() < 1e-6, "{}", split.bias2);
    assert!(split.variance.abs() < 1e-12);
    assert!(split.bias2_se < 1e-9);
    assert!(split.resolved());
    assert_eq!(split.bias2_text(), "9.0e-2 ± 0.0e-2");
    assert!((split.signed.get(3, 3).x - 0.3).abs() < 1e-6);
}

/// Noise alone: the U-statistic removes s²/K exactly, so a bias of zero
/// is estimated near zero (not at s²/K above it), is not resolved, and
/// is printed as a bound, never as 0.
#[test]
fn noise_alone_is_not_bias() {
    let (runs, reference, zero) = runs(16, 0.0, 0.5);
    let split = split(&runs, &reference, &zero, &[true; 256]);
    assert!((split.variance - 0.25).abs() < 0.03, "{}", split.variance);
    let naive: f64 = split
        .signed
        .pixels
        .iter()
        .map(|c| (c.x * c.x) as f64)
        .sum::<f64>()
        / 256.0;
    assert!(
        split.bias2.abs() < 4.0 * split.bias2_se,
        "{} ± {}",
        split.bias2,
        split.bias2_se
    );
    assert!(
        naive > 0.25 / 16.0 * 0.5,
        "the raw squared mean error holds variance/K"
    );
    assert!(!split.resolved());
    assert!(
        split.bias2_text().starts_with("< "),
        "{}",
        split.bias2_text()
    );
}

/// The reference's own variance is subtracted: a run equal to a
/// reference said to have variance v per channel has b̂² = −v.
#[test]
fn the_references_noise_is_not_bias() {
    let (runs, reference, _) = runs(3, 0.0, 0.0);
    let noisy = Image::from_fn(16, 16, |_, _| Color::splat(1e-4));
    let split = split(&runs, &reference, &noisy, &[true; 256]);
    assert!((split.bias2 + 1e-4).abs() < 1e-9, "{}", split.bias2);
}

/// A bias larger than the noise is resolved, with a standard error of
/// the size the jackknife gives: SE² ≈ 4 b² σ² / (K · pixels).
#[test]
fn a_bias_above_the_noise_is_resolved() {
    let (runs, reference, zero) = runs(16, 0.1, 0.5);
    let split = split(&runs, &reference, &zero, &[true; 256]);
    assert!(
        (split.bias2 - 0.01).abs() < 4.0 * split.bias2_se,
        "{}",
        split.bias2
    );
    assert!(split.resolved(), "{} ± {}", split.bias2, split.bias2_se);
    assert!(split.bias2_text().contains(" ± "));
}

/// Only the counted pixels count.
#[test]
fn uncounted_pixels_are_left_out() {
    let (mut runs, reference, zero) = runs(4, 0.0, 0.0);
    for r in &mut runs {
        r.pixels[0] = Color::splat(100.0);
    }
    let mut counted = [true; 256];
    counted[0] = false;
    let split = split(&runs, &reference, &zero, &counted);
    assert!(split.bias2.abs() < 1e-12 && split.variance.abs() < 1e-12);
}
