//! Unit tests of `render/sppm/mod.rs`.

use raytracer::math::Color;
use raytracer::render::RenderOptions;
use raytracer::render::sppm::*;
use raytracer::scene::Scene;
use std::sync::atomic::AtomicBool;

fn options(spp: u32, threads: usize) -> RenderOptions {
    RenderOptions {
        spp,
        seed: 5,
        threads: Some(threads),
        progress: false,
        ..RenderOptions::default()
    }
}

/// The watcher sees every pass in order, and the image it is shown after
/// pass `k` is, bit for bit, the image of a `k`-pass render (on another
/// number of threads, too).
#[test]
fn each_pass_shown_is_the_image_of_a_shorter_render() {
    let mut scene = Scene::builtin("cornell").unwrap();
    scene.set_resolution(12, 10);
    let settings = SppmSettings {
        photons: 2000,
        ..SppmSettings::default()
    };
    let never = AtomicBool::new(false);
    let mut seen = Vec::new();
    let full = render_sppm_watched(&scene, &settings, &options(3, 2), &never, &mut |p| {
        seen.push((p.passes, p.image().bits()))
    });
    let passes: Vec<u32> = seen.iter().map(|s| s.0).collect();
    assert_eq!(passes, [1, 2, 3]);
    let two = render_sppm_with_stop(&scene, &settings, &options(2, 1), &never);
    assert_eq!(seen[1].1, two.image.bits());
    assert_eq!(seen[2].1, full.image.bits());
    assert_ne!(seen[1].1, seen[2].1);
}

/// One thread or three: the same image to the last bit; a raised stop
/// flag keeps no pass at all (the flag is seen before the first).
#[test]
fn sppm_is_deterministic_and_stops() {
    let mut scene = Scene::builtin("cornell").unwrap();
    scene.set_resolution(12, 10);
    let settings = SppmSettings {
        photons: 3000,
        ..SppmSettings::default()
    };
    let never = AtomicBool::new(false);
    let a = render_sppm_with_stop(&scene, &settings, &options(3, 1), &never);
    let b = render_sppm_with_stop(&scene, &settings, &options(3, 3), &never);
    assert_eq!(a.passes, 3);
    assert!(a.final_radius < a.initial_radius);
    assert_eq!(a.image.bits(), b.image.bits());
    assert!(raytracer::metrics::mean(&a.image).x > 0.0);
    let s = render_sppm_with_stop(&scene, &settings, &options(3, 2), &AtomicBool::new(true));
    assert!(s.stats.interrupted && s.passes == 0);
    assert_eq!(raytracer::metrics::mean(&s.image), Color::ZERO);
}
