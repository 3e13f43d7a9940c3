//! The built-in Cornell box is Mitsuba 3's: orientation and direct light.

use raytracer::integrator::Direct;
use raytracer::math::Color;
use raytracer::render::{RenderOptions, render};
use raytracer::scene::Scene;

/// Mitsuba's camera frame puts the red wall (x = −1) on the left of the image
/// and the green wall on the right. A column of pixels near each edge, at
/// mid height, must be dominated by that wall's colour.
#[test]
fn red_wall_is_on_the_left_and_green_on_the_right() {
    let mut scene = Scene::builtin("cornell").unwrap();
    scene.set_resolution(64, 64);
    let options = RenderOptions {
        spp: 16,
        seed: 3,
        threads: None,
        progress: false,
        ..RenderOptions::default()
    };
    let image = render(&scene, &Direct, &options).film.image();
    let column = |x: u32| -> Color { (24..40).map(|y| image.get(x, y)).sum::<Color>() / 16.0 };
    let (left, right) = (column(3), column(60));
    assert!(left.x > 2.0 * left.y, "left edge should be red, got {left}");
    assert!(
        right.y > 1.5 * right.x,
        "right edge should be green, got {right}"
    );
}

/// The light is visible at the top centre and is the brightest thing there:
/// its radiance is (18.387, 13.9873, 6.75357) exactly (depth 1 of Mitsuba's
/// convention), and the pixel at the centre of its image is fully covered.
#[test]
fn the_light_is_seen_with_its_exact_radiance() {
    let mut scene = Scene::builtin("cornell").unwrap();
    scene.set_resolution(256, 256);
    // The light's centre (0, 0.99, 0.01) projects to about pixel (128, 9).
    let p = scene
        .camera
        .raster_of(
            raytracer::math::Vec3A::new(0.0, 0.99, 0.01),
            scene.camera.position(),
        )
        .unwrap();
    let (px, py) = (p.x as u32, p.y as u32);
    let options = RenderOptions {
        spp: 4,
        seed: 3,
        threads: None,
        progress: false,
        ..RenderOptions::default()
    };
    let image = render(&scene, &Direct, &options).film.image();
    let c = image.get(px, py);
    // Direct light reflected by the light's own white surface is zero (no
    // other light shines on it), so the pixel is exactly L_e.
    let le = Color::new(18.387, 13.9873, 6.75357);
    assert!(
        (c - le).abs().max_element() < 1e-3,
        "light pixel {c}, expected {le}"
    );
}
