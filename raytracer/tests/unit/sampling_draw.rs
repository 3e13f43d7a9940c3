//! Unit tests of `sampling/draw.rs`.

use raytracer::math::Vec2;
use raytracer::sampling::Sampler;
use raytracer::sampling::draw::*;

#[test]
fn a_draw_takes_the_next_dimensions_in_order() {
    const ONE: Draw<1> = Draw::new("one");
    const TWO: Draw<2> = Draw::new("two");
    let mut plain = Sampler::new(4, 5, 6);
    let expected = [plain.next_1d(), plain.next_1d(), plain.next_1d()];
    let mut s = Sampler::new(4, 5, 6);
    assert_eq!(ONE.draw(&mut s), expected[0]);
    assert_eq!(TWO.draw(&mut s), Vec2::new(expected[1], expected[2]));
    assert_eq!(s.dimension(), ONE.dimensions() + TWO.dimensions());
    assert_eq!((ONE.dimensions(), TWO.dimensions()), (1, 2));
}
