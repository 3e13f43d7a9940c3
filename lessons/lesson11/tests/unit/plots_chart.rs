//! Unit tests of `plots/chart.rs`.

use lesson11::plots::chart::*;
use lesson11::plots::series::Series;

#[test]
fn ticks_cover_the_range_with_round_steps() {
    assert_eq!(
        ticks(0.0, 1.0, Scale::Linear),
        vec![0.0, 0.2, 0.4, 0.6000000000000001, 0.8, 1.0]
    );
    assert_eq!(ticks(-1.3, 2.0, Scale::Log), vec![-1.0, 0.0, 1.0, 2.0]);
    // Less than a decade: 2 and 5 times the decades join in, or every multiple.
    let labels = |lo: f64, hi: f64| -> Vec<String> {
        ticks(lo, hi, Scale::Log)
            .into_iter()
            .map(|t| tick_label(t, Scale::Log))
            .collect()
    };
    assert_eq!(labels(-2.5, -1.2), ["0.005", "0.01", "0.02", "0.05"]);
    assert_eq!(labels(0.1, 0.65), ["2", "3", "4"]);
    assert_eq!(labels(-7.0, -5.0), ["1e-7", "1e-6", "1e-5"]);
}

#[test]
fn svg_has_every_series_and_axis_label() {
    let chart = Chart {
        title: "t".into(),
        x_label: "seconds".into(),
        y_label: "RMSE".into(),
        x_scale: Scale::Log,
        y_scale: Scale::Log,
        series: vec![
            Series {
                label: "path".into(),
                points: vec![(0.1, 0.5), (1.0, 0.15)],
            },
            Series {
                label: "bdpt".into(),
                points: vec![(0.1, 0.2), (1.0, 0.06)],
            },
        ],
    };
    let svg = chart.to_svg();
    assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
    assert_eq!(svg.matches("<polyline").count(), 2);
    for text in ["path", "bdpt", "seconds", "RMSE"] {
        assert!(svg.contains(text), "{text}");
    }
}

#[test]
fn every_log_axis_gets_at_least_three_labelled_ticks_however_narrow() {
    // From many decades down to 5 % of a value, anywhere on the axis.
    for lo in [-9.0, -4.3, -2.0, -1.0, -0.31, 0.0, 0.7, 2.5] {
        for span in [6.0, 2.0, 1.0, 0.5, 0.2, 0.1, 0.05, 0.02] {
            let (a, b) = (lo, lo + span);
            let t = ticks(a, b, Scale::Log);
            assert!(t.len() >= 3, "[{a}, {b}]: {t:?}");
            assert!(
                t.iter().all(|t| *t >= a - 1e-9 && *t <= b + 1e-9),
                "[{a}, {b}]: {t:?}"
            );
            let labels: Vec<String> = t.iter().map(|t| tick_label(*t, Scale::Log)).collect();
            let mut distinct = labels.clone();
            distinct.dedup();
            assert_eq!(distinct, labels, "[{a}, {b}]: labels that repeat");
        }
    }
}
