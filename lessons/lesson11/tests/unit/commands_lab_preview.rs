//! Unit tests of `commands/lab/preview.rs`.

use lesson11::commands::lab::preview::*;
use raytracer::film::Film;
use raytracer::math::{Color, UVec2};

/// A film with only its left half sampled shows its right half in the
/// left half's colour, not black; a complete film needs no preview.
#[test]
fn unsampled_pixels_take_their_neighbourhoods_mean() {
    let mut film = Film::new(8, 4);
    for y in 0..4 {
        for x in 0..4 {
            film.add_sample(UVec2::new(x, y), Color::new(0.5, 0.25, 1.0));
        }
    }
    let image = film.image();
    let preview = coarse_preview(&film, &image).expect("half the film is unsampled");
    assert_eq!(image.get(6, 2), Color::ZERO);
    assert_eq!(preview.get(6, 2), Color::new(0.5, 0.25, 1.0));
    assert_eq!(preview.get(1, 1), image.get(1, 1));
    for y in 0..4 {
        for x in 4..8 {
            film.add_sample(UVec2::new(x, y), Color::ONE);
        }
    }
    assert!(coarse_preview(&film, &film.image()).is_none());
}
