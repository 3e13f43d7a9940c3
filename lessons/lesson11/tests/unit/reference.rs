//! Unit tests of `reference.rs`.

use lesson11::reference::*;
use raytracer::film::Image;
use raytracer::math::Color;
use raytracer::render::RenderOptions;
use raytracer::scene::Scene;

#[test]
fn a_smaller_reference_averages_blocks_and_their_variances() {
    let mean = Image::from_fn(4, 2, |x, y| Color::splat((x + 4 * y) as f32));
    let variance = Image::from_fn(4, 2, |_, _| Color::splat(4.0));
    let r = Reference {
        mean,
        variance,
        spp: 1,
        source: String::new(),
        name: "",
    };
    let half = r.at_size(2, 1).unwrap();
    // (0 + 1 + 4 + 5) / 4 and (2 + 3 + 6 + 7) / 4.
    assert_eq!(half.mean.pixels, [Color::splat(2.5), Color::splat(4.5)]);
    // Four independent pixels of variance 4: the mean has variance 16/16.
    assert_eq!(half.variance.get(0, 0), Color::splat(1.0));
    assert!((r.noise_floor() - 2.0).abs() < 1e-12);
    assert!(r.at_size(3, 1).is_none(), "3 does not divide 4");
    assert!(r.at_size(2, 2).is_none(), "another aspect");
    assert!(r.at_size(4, 2).is_some());
}

#[test]
fn settings_survive_their_text_and_know_the_scene() {
    let s = door_settings();
    assert_eq!(StoredSettings::from_text(&s.to_text()), Some(s.clone()));
    let other = StoredSettings {
        scene_hash: s.scene_hash ^ 1,
        ..s.clone()
    };
    assert_ne!(other, s);
    assert_ne!(fnv1a(b"a"), fnv1a(b"b"));
}

/// The stored references are there and fit the scene as it is now: a
/// changed door scene, size or depth must be followed by `lesson11
/// references`, or the tour would fall back to a noisier reference.
#[test]
fn the_stored_references_are_current() {
    let door = door_settings().load().unwrap_or_else(|e| panic!("{e:#}"));
    assert_eq!((door.mean.width, door.mean.height), (128, 96));
    let caustic = caustic_settings()
        .load()
        .unwrap_or_else(|e| panic!("{e:#}"));
    assert_eq!((caustic.mean.width, caustic.mean.height), (128, 96));
    let mitsuba = mitsuba_cornell().unwrap();
    assert_eq!((mitsuba.mean.width, mitsuba.mean.height), (256, 256));
    // Mitsuba's 16 passes of 128 spp: a floor far below the errors measured.
    assert!(mitsuba.noise_floor() < 0.01, "{}", mitsuba.noise_floor());
}

/// The stored door reference is what the renderer computes now: a small
/// bidirectional render with another seed agrees with it tile by tile
/// (8-pixel tiles of the 32 × 24 reduction, 36 z-scores; false failure
/// below 1e-4 by the union bound of `z_threshold`).
#[test]
fn the_stored_door_reference_agrees_with_a_fresh_render() {
    use raytracer::metrics::{z_test, z_threshold};
    let settings = door_settings();
    let stored = settings.load().unwrap().at_size(32, 24).unwrap();
    let mut scene = Scene::builtin("door").unwrap();
    scene.set_resolution(32, 24);
    let base = RenderOptions {
        seed: 12345,
        ..RenderOptions::default()
    };
    let fresh = render_now(&scene, &base, settings.max_depth, 64);
    let z = z_test(
        &fresh.mean,
        &fresh.variance,
        &stored.mean,
        &stored.variance,
        8,
    );
    let threshold = z_threshold(z.z.len() * 3, 1e-4) as f32;
    assert!(
        z.max_abs_z < threshold,
        "tile {}: |z| = {} > {threshold}",
        z.worst_tile,
        z.max_abs_z
    );
}
