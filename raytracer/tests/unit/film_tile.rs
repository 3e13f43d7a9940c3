//! Unit tests of `film/tile.rs`.

use raytracer::film::Film;
use raytracer::film::Splat;
use raytracer::film::tile::*;
use raytracer::math::Vec2;
use raytracer::math::{Color, UVec2};

#[test]
fn merged_tile_equals_direct_accumulation() {
    let size = UVec2::new(5, 4);
    let mut tile = FilmTile::new(size, UVec2::new(3, 2), UVec2::new(4, 4));
    assert_eq!(tile.size(), UVec2::new(2, 2));
    let mut direct = Film::new(5, 4);
    for (k, (x, y)) in [(3, 2), (4, 3), (3, 2), (4, 2)].into_iter().enumerate() {
        let p = UVec2::new(x, y);
        let v = Color::splat(k as f32 + 0.5);
        tile.add_sample(p, v);
        direct.add_sample(p, v);
    }
    let mut film = Film::new(5, 4);
    film.merge_tile(&tile);
    assert_eq!(film.image(), direct.image());
    assert_eq!(film.total_samples(), 4);
    assert_eq!(film.sample_count(UVec2::new(3, 2)), 2);
}

#[test]
fn splats_of_one_path_are_grouped_per_pixel() {
    let mut tile = FilmTile::new(UVec2::new(4, 4), UVec2::ZERO, UVec2::new(4, 4));
    let s = |x: f32, y: f32, v: f32| Splat {
        raster: Vec2::new(x, y),
        value: Color::splat(v),
    };
    tile.record(UVec2::ZERO, |splats| {
        splats.push(s(1.2, 1.7, 1.0));
        splats.push(s(9.0, 1.0, 1.0)); // off the film
        splats.push(s(2.5, 0.5, f32::NAN)); // invalid
        splats.push(s(1.9, 1.1, 2.0)); // same pixel as the first
        splats.push(s(0.5, 0.5, 0.0)); // zero
        splats.push(s(3.5, 3.5, 4.0));
        Color::ZERO
    });
    assert_eq!(tile.nonfinite_count(), 1);
    assert_eq!(tile.splats().len(), 2);
    assert_eq!(tile.splats()[0].value, Color::splat(3.0));
    assert_eq!(tile.splats()[1].value, Color::splat(4.0));
    // A second path in the same pixel stays a separate term.
    tile.record(UVec2::ZERO, |splats| {
        splats.push(s(1.5, 1.5, 1.0));
        Color::ZERO
    });
    assert_eq!(tile.splats().len(), 3);
    tile.reset(UVec2::ZERO, UVec2::new(2, 2));
    assert!(tile.splats().is_empty() && tile.nonfinite_count() == 0);
}
