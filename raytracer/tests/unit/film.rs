//! Unit tests of `film/mod.rs`.

use raytracer::film::*;
use raytracer::math::{Color, UVec2, Vec2};

#[test]
fn mean_and_variance_of_known_samples() {
    let mut film = Film::new(2, 1);
    let p = UVec2::new(1, 0);
    for v in [1.0, 2.0, 3.0, 6.0] {
        film.add_sample(p, Color::new(v, 2.0 * v, 0.0));
    }
    assert_eq!(film.sample_count(p), 4);
    assert_eq!(film.sample_count(UVec2::ZERO), 0);
    let img = film.image();
    assert_eq!(img.get(1, 0), Color::new(3.0, 6.0, 0.0));
    assert_eq!(img.get(0, 0), Color::ZERO);
    // Sample variance of {1,2,3,6}: (4+1+0+9)/3 = 14/3; of the mean: 14/12.
    let var = film.variance_image();
    assert!((var.get(1, 0).x - 14.0 / 12.0).abs() < 1e-6);
    assert!((var.get(1, 0).y - 4.0 * 14.0 / 12.0).abs() < 1e-5);
    assert_eq!(var.get(1, 0).z, 0.0);
    assert_eq!(var.get(0, 0).x, f32::INFINITY);
}

#[test]
fn invalid_samples_count_as_zero() {
    let mut film = Film::new(1, 1);
    let p = UVec2::ZERO;
    film.add_sample(p, Color::splat(4.0));
    film.add_sample(p, Color::new(f32::NAN, 1.0, 1.0));
    film.add_sample(p, Color::new(1.0, f32::INFINITY, 1.0));
    film.add_sample(p, Color::new(1.0, 1.0, -1.0));
    assert_eq!(film.nonfinite_count(), 3);
    assert_eq!(film.sample_count(p), 4);
    assert_eq!(film.image().get(0, 0), Color::splat(1.0));
    film.add_splat(Splat {
        raster: Vec2::new(0.5, 0.5),
        value: Color::splat(f32::NAN),
    });
    assert_eq!(film.nonfinite_count(), 4);
    assert_eq!(film.image().get(0, 0), Color::splat(1.0));
    assert!(film.variance_image().get(0, 0).is_finite());
}

#[test]
fn splats_land_in_the_nearest_pixel_and_are_scaled() {
    let mut film = Film::new(3, 2);
    for y in 0..2 {
        for x in 0..3 {
            for _ in 0..4 {
                film.add_sample(UVec2::new(x, y), Color::ZERO);
            }
        }
    }
    // 24 samples on 6 pixels: scale 1/4.
    assert_eq!(film.splat_scale(), 0.25);
    let splat = |x: f32, y: f32| Splat {
        raster: Vec2::new(x, y),
        value: Color::splat(2.0),
    };
    film.add_splat(splat(2.99, 1.0)); // pixel (2, 1)
    film.add_splat(splat(2.0, 1.99)); // pixel (2, 1)
    film.add_splat(splat(3.0, 0.5)); // outside: ignored
    film.add_splat(splat(-0.01, 0.5)); // outside: ignored
    film.add_splat(splat(f32::NAN, 0.5)); // outside: ignored
    let img = film.image();
    assert_eq!(img.get(2, 1), Color::splat(1.0));
    let total: f32 = img.pixels.iter().map(|c| c.x).sum();
    assert_eq!(total, 1.0);
    assert_eq!(film.nonfinite_count(), 0);
}

#[test]
fn pixel_of_raster_follows_the_camera_convention() {
    assert_eq!(
        pixel_of_raster(Vec2::new(0.0, 0.0), 4, 3),
        Some(UVec2::ZERO)
    );
    assert_eq!(
        pixel_of_raster(Vec2::new(3.999, 2.5), 4, 3),
        Some(UVec2::new(3, 2))
    );
    assert_eq!(pixel_of_raster(Vec2::new(4.0, 0.0), 4, 3), None);
    assert_eq!(pixel_of_raster(Vec2::new(0.0, -1e-7), 4, 3), None);
    assert_eq!(pixel_of_raster(Vec2::new(f32::INFINITY, 0.0), 4, 3), None);
}
