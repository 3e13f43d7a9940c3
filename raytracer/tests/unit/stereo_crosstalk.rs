//! Unit tests of `stereo/crosstalk.rs`.

use raytracer::film::Image;
use raytracer::math::Vec3A;
use raytracer::stereo::anaglyph::Anaglyph;
use raytracer::stereo::crosstalk::*;

/// A white object only in the left image: with perfect filters the right
/// eye sees nothing of it; with leakage it sees a ghost whose brightness
/// is the leaked luminance, k·w_R / (k·w_R + w_G + w_B) for red–cyan.
#[test]
fn leakage_makes_ghosts() {
    let left = Image::from_fn(2, 1, |x, _| if x == 0 { Vec3A::ONE } else { Vec3A::ZERO });
    let right = Image::new(2, 1);
    let ana = Anaglyph::Grey.compose(&left, &right, 0.0);
    let [l0, r0] = eye_views(&ana, Anaglyph::Grey, 0.0);
    assert!(
        (l0.get(0, 0).x - 1.0).abs() < 1e-6,
        "left eye sees its white"
    );
    assert_eq!(r0.get(0, 0), Vec3A::ZERO, "no ghost with ideal filters");
    let k = 0.1;
    let [_, r1] = eye_views(&ana, Anaglyph::Grey, k);
    let expected = k * 0.2126 / (k * 0.2126 + 0.7152 + 0.0722);
    assert!((r1.get(0, 0).x - expected).abs() < 1e-6);
    assert_eq!(r1.get(1, 0), Vec3A::ZERO);
    // Polarised-style leakage.
    let [pl, pr] = leak_pair(&left, &right, k);
    assert!((pl.get(0, 0).x - 0.9).abs() < 1e-6);
    assert!((pr.get(0, 0).x - 0.1).abs() < 1e-6);
}
