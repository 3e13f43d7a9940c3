//! Unit tests of `plots/bars.rs`.

use lesson11::plots::bars::*;

#[test]
fn every_part_of_every_bar_is_drawn_with_its_legend() {
    let bars = Bars {
        title: "t".into(),
        y_label: "MSE".into(),
        parts: vec!["bias²".into(), "variance".into()],
        bars: vec![
            ("path".into(), vec![0.0, 2e-3]),
            ("photon".into(), vec![1e-3, 1e-4]),
        ],
    };
    let svg = bars.to_svg();
    assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
    // Four parts, two legend swatches, the frame and the background.
    assert_eq!(svg.matches("<rect").count(), 4 + 2 + 2);
    for text in ["path", "photon", "bias²", "variance", "MSE"] {
        assert!(svg.contains(text), "{text}");
    }
    assert_eq!(step(1.0), 0.2);
    assert_eq!(format_tick(0.002), "2e-3");
}
