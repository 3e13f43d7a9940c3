//! Unit tests of `film/image.rs`.

use raytracer::film::image::*;
use raytracer::math::Color;

#[test]
fn rows_go_from_the_top() {
    let img = Image::from_fn(3, 2, |x, y| Color::new(x as f32, y as f32, 0.0));
    assert_eq!(img.pixels[4], Color::new(1.0, 1.0, 0.0));
    assert_eq!(img.get(2, 0), Color::new(2.0, 0.0, 0.0));
    let mut img = img.map(|c| 2.0 * c);
    img.set(0, 1, Color::ONE);
    assert_eq!(img.get(0, 1), Color::ONE);
    assert_eq!(img.get(2, 1), Color::new(4.0, 2.0, 0.0));
}

#[test]
#[should_panic(expected = "outside")]
fn out_of_bounds_panics() {
    Image::new(2, 2).get(2, 0);
}
