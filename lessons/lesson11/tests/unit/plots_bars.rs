//! Unit tests of `plots/bars.rs`.

use lesson11::plots::bars::*;

#[test]
fn every_part_of_every_bar_is_drawn_with_its_legend() {
    let part = |value, bound| Part { value, bound };
    let bars = Bars {
        title: "t".into(),
        y_label: "MSE".into(),
        parts: vec!["bias²".into(), "variance".into()],
        bound_label: "at most".into(),
        bars: vec![
            ("path".into(), vec![part(1e-5, true), part(2e-3, false)]),
            ("photon".into(), vec![part(1e-3, false), part(1e-4, false)]),
        ],
    };
    let svg = bars.to_svg();
    assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
    // Four parts, three legend swatches, the frame and the background.
    assert_eq!(svg.matches("<rect").count(), 4 + 3 + 2);
    for text in [
        "path", "photon", "bias²", "variance", "MSE", "at most", "1e-5",
    ] {
        assert!(svg.contains(text), "{text}");
    }
}
