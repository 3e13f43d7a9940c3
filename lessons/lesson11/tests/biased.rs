//! Chapter 9 as its table and pictures state it (issue 24): bias² is an
//! estimate, so the table gives it with its standard error or as a bound,
//! never as a bare 0; every algorithm's bias is a signed picture whose
//! colour bar has numbers.

use std::path::PathBuf;
use std::process::Command;

fn out_dir() -> PathBuf {
    let dir = std::env::temp_dir().join(format!("lesson11-biased-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// `1.2e-4 ± 0.3e-4` or `< 2.0e-5`: a number in the `e` notation the table
/// prints.
fn is_estimate(cell: &str) -> bool {
    let number = |s: &str| {
        s.split_once('e').is_some_and(|(m, e)| {
            m.parse::<f64>().is_ok_and(f64::is_finite) && e.parse::<i32>().is_ok()
        })
    };
    match (cell.strip_prefix("< "), cell.split_once(" ± ")) {
        (Some(bound), _) => number(bound) && bound.parse::<f64>().is_ok_and(|b| b > 0.0),
        (None, Some((b, se))) => number(b) && number(se),
        _ => false,
    }
}

#[test]
fn the_estimate_reader_accepts_only_estimates() {
    assert!(is_estimate("4.1e-5 ± 0.5e-5"));
    assert!(is_estimate("< 2.0e-5"));
    assert!(!is_estimate("0"));
    assert!(!is_estimate("0.000e0"));
    assert!(!is_estimate("< 0e0"), "a bound of zero is no bound");
    assert!(!is_estimate("4.1e-5"), "an estimate without its error");
}

#[test]
fn bias_is_printed_with_its_error_and_shown_with_a_numbered_scale() {
    let dir = out_dir();
    let o = Command::new(env!("CARGO_BIN_EXE_lesson11"))
        .env("LESSON11_LANG", "en")
        .args(["biased", "--quality", "tiny", "--out"])
        .arg(&dir)
        .output()
        .expect("lesson11 runs");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let chapter = dir.join("09-biased");
    let csv = std::fs::read_to_string(chapter.join("biased.csv")).unwrap();
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let column = header
        .iter()
        .position(|h| h.starts_with("bias²"))
        .expect("a bias² column");
    assert_eq!(header[column], "bias² ± SE");
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 6, "{csv}");
    for row in &rows {
        assert!(
            is_estimate(row[column]),
            "{}: bias² `{}` is not an estimate with its error",
            row[0],
            row[column]
        );
    }
    for stem in ["path", "bdpt", "photon", "sppm", "vpl", "irradiance-cache"] {
        let svg = chapter.join(format!("cornell-{stem}-bias.svg"));
        let text =
            std::fs::read_to_string(&svg).unwrap_or_else(|e| panic!("{}: {e}", svg.display()));
        assert!(
            text.contains("data:image/png;base64,"),
            "{stem}: the picture"
        );
        assert!(text.contains(">0</text>"), "{stem}: a bar with 0 on it");
        // The ends and 0 (numbers large enough for a slide leave the
        // half-way ticks bare: plots/signed_map.rs).
        assert_eq!(text.matches("</text>").count(), 3, "{stem}: three numbers");
    }
    for name in [
        "cornell-photon-error",
        "caustic-photon-error",
        "cornell-vpl-clamping",
    ] {
        assert!(chapter.join(format!("{name}.svg")).is_file(), "{name}.svg");
    }
    std::fs::remove_dir_all(&dir).ok();
}
