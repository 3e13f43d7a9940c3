//! Unit tests of `plots/signed_map.rs`.

use lesson11::plots::signed_map::*;

#[test]
fn scales_are_round_and_at_least_the_value() {
    assert_eq!(round_scale(0.03), 0.05);
    assert_eq!(round_scale(0.05), 0.05);
    assert_eq!(round_scale(0.11), 0.2);
    assert_eq!(round_scale(7.0), 10.0);
    assert_eq!(round_scale(0.0), 1.0);
    assert_eq!(round_scale(f64::NAN), 1.0);
}

#[test]
fn the_bar_is_numbered_with_signs_and_zero() {
    let svg = signed_map_svg(&[0.0, 0.1, -0.1, 0.05], 2, 2, 0.1).unwrap();
    // 256 units wide: numbers 16 high, too large for five in a row; the
    // ends and 0 are numbered, and all five ticks drawn.
    for text in [">−0.1<", ">0<", ">+0.1<"] {
        assert!(svg.contains(text), "{text} missing");
    }
    assert_eq!(svg.matches("<text").count(), 3);
    assert_eq!(svg.matches("stroke=\"#111\"").count(), 5);
    assert!(svg.contains("font-size=\"16\""));
    // A picture of 256 pixels drawn twice as large: numbers 32 high.
    let wide = signed_map_svg(&[0.0; 256 * 2], 256, 2, 0.1).unwrap();
    assert!(wide.contains("font-size=\"32\""));
    assert!(svg.contains("data:image/png;base64,"));
    assert!(
        svg.contains("width=\"256\" height=\"256\""),
        "drawn 256 wide"
    );
    let svg = signed_map_svg(&[0.0; 300 * 2], 300, 2, 0.1).unwrap();
    assert!(
        svg.contains("width=\"600\" height=\"4\""),
        "at twice its size at least"
    );
    assert_eq!(label(0.2, 0.2), "+0.2");
    assert_eq!(label(-0.002, 0.004), "−0.002");
    assert_eq!(label(0.025, 0.05), "+0.025", "the half-scale tick exactly");
    assert_eq!(label(0.05, 0.05), "+0.050");
    assert_eq!(label(-5.0, 10.0), "−5");
}
