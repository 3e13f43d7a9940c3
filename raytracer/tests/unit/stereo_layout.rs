//! Unit tests of `stereo/layout.rs`.

use raytracer::film::Image;
use raytracer::math::Color;
use raytracer::stereo::layout::*;

#[test]
fn layouts_put_each_eye_where_it_belongs() {
    let l = Image::from_fn(4, 3, |_, _| Color::X);
    let r = Image::from_fn(4, 3, |_, _| Color::Z);
    let s = Layout::SideBySide.compose(&l, &r);
    assert_eq!((s.width, s.height), (8, 3));
    assert_eq!((s.get(0, 0), s.get(7, 2)), (Color::X, Color::Z));
    let c = Layout::CrossEyed.compose(&l, &r);
    assert_eq!((c.get(0, 0), c.get(7, 2)), (Color::Z, Color::X));
    let o = Layout::OverUnder.compose(&l, &r);
    assert_eq!((o.width, o.height), (4, 6));
    assert_eq!((o.get(3, 2), o.get(0, 3)), (Color::X, Color::Z));
}
