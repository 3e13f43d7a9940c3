//! Unit tests of `stereo/mod.rs`.

use anaglyph::Anaglyph;
use raytracer::stereo::*;

#[test]
fn names_round_trip_and_unknown_names_are_explained() {
    for c in Composite::all() {
        assert_eq!(c.name().parse::<Composite>().unwrap(), c);
    }
    assert_eq!(
        "Gray".parse::<Composite>().unwrap(),
        Composite::Anaglyph(Anaglyph::Grey)
    );
    let err = "purple".parse::<Composite>().unwrap_err();
    assert!(err.contains("purple") && err.contains("dubois"), "{err}");
}
