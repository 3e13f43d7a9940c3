//! Unit tests of `chapters/c01_stereo.rs`.

#[test]
fn refocus_depths_get_names_of_their_own() {
    assert_eq!(refocus_digits(&[0.5, 1.0, 3.0]), 2);
    assert_eq!(refocus_digits(&[2.001, 2.004]), 3);
    assert_eq!(refocus_digits(&[1.0, 1.000_01]), 5);
}
use lesson11::chapters::c01_stereo::*;
use raytracer::stereo::Composite;

#[test]
fn modes_are_parsed_with_all_and_without_repeats() {
    let all = parse_modes(&["all".into()]).unwrap();
    assert_eq!(all, Composite::all());
    let two = parse_modes(&["dubois".into(), "cross".into(), "dubois".into()]).unwrap();
    assert_eq!(two.len(), 2);
    let err = parse_modes(&["nope".into()]).unwrap_err().to_string();
    assert!(err.contains("nope"), "{err}");
}
