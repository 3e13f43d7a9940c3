//! Unit tests of `render/sppm/estimator.rs`.

use raytracer::math::Color;
use raytracer::render::sppm::estimator::*;

/// The radius shrinks by √((N + αM)/(N + M)) and τ keeps its density:
/// τ/r² before adding φ is unchanged by the reduction.
#[test]
fn the_update_keeps_a_fraction_alpha_of_the_new_photons() {
    let mut s = PixelState::new(0.5);
    s.update(30, Color::splat(3.0), 2.0 / 3.0);
    assert!((s.n - 20.0).abs() < 1e-5);
    assert!((s.r - 0.5 * (20.0f32 / 30.0).sqrt()).abs() < 1e-6);
    assert!((s.tau.x - 3.0 * 20.0 / 30.0).abs() < 1e-5);
    let density = s.tau.x / (s.r * s.r);
    s.update(0, Color::ZERO, 2.0 / 3.0);
    assert_eq!(s.tau.x / (s.r * s.r), density);
    s.update(12, Color::splat(1.2), 2.0 / 3.0);
    assert!((s.n - 28.0).abs() < 1e-4);
    // Bad input is refused with one line.
    for bad in [
        SppmSettings {
            alpha: 1.0,
            ..SppmSettings::default()
        },
        SppmSettings {
            alpha: f32::NAN,
            ..SppmSettings::default()
        },
        SppmSettings {
            radius: Some(-1.0),
            ..SppmSettings::default()
        },
        SppmSettings {
            photons: 0,
            ..SppmSettings::default()
        },
    ] {
        let e = bad.check().unwrap_err();
        assert!(!e.contains('\n') && e.starts_with("--"), "{e}");
    }
}
