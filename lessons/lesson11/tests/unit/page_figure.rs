//! Unit tests of `page/figure.rs`.

use lesson11::page::figure::*;
use std::path::Path;

#[test]
fn times_are_never_shown_as_zero() {
    assert_eq!(seconds_text(41.7), "41.7 s");
    assert_eq!(seconds_text(2.54), "2.5 s");
    assert_eq!(seconds_text(0.314), "0.31 s");
    assert_eq!(seconds_text(0.0042), "4.2 ms");
    assert_eq!(seconds_text(0.00001), "< 0.1 ms");
    assert_eq!(seconds_text(123.4), "123 s");
    assert_eq!(seconds_number(0.000412), "0.000412");
    assert_eq!(seconds_number(0.97), "0.970");
    assert_eq!(seconds_number(12.34), "12.3");
    assert_eq!(seconds_number(1234.4), "1234");
}

#[test]
fn exposure_is_stated_in_stops_and_as_a_factor() {
    lang::with(lang::Lang::En, || {
        assert_eq!(exposure_text(0.0), "exposure 0");
        assert_eq!(exposure_text(4.0), "exposure +4 stops (×16)");
        assert_eq!(exposure_text(-1.0), "exposure -1 stops (×0.500)");
    });
}

#[test]
fn a_render_caption_says_spp_exposure_and_time() {
    lang::with(lang::Lang::En, a_render_caption_in_english);
}

fn a_render_caption_in_english() {
    let picture = Picture {
        png: "/o/a/x.png".into(),
        exr: "/o/a/x.exr".into(),
        spp: 64,
        exposure: 4.0,
        seconds: Some(0.004),
    };
    let f = Figure::new(Path::new("/o"), &picture, "Door.");
    assert_eq!(f.src, "a/x.png");
    assert_eq!(f.caption, "Door. (64 spp, exposure +4 stops (×16), 4.0 ms)");
    let derived = Picture {
        seconds: None,
        ..picture
    };
    let f = Figure::new(Path::new("/o"), &derived, "Strategy.");
    assert_eq!(f.caption, "Strategy. (64 spp, exposure +4 stops (×16))");
}

#[test]
fn a_png_width_is_read_from_its_header() {
    let dir = std::env::temp_dir().join(format!("lesson11-png-width-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let png = dir.join("x.png");
    let mut bytes = b"\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR".to_vec();
    bytes.extend(300u32.to_be_bytes());
    bytes.extend(200u32.to_be_bytes());
    std::fs::write(&png, bytes).unwrap();
    assert_eq!(png_width(&png), Some(300));
    std::fs::write(&png, b"not a png, but long enough").unwrap();
    assert_eq!(png_width(&png), None);
    let _ = std::fs::remove_dir_all(&dir);
}
