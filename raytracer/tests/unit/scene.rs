//! Unit tests of `scene/mod.rs`.

use raytracer::scene::*;

#[test]
fn max_depth_has_one_rule() {
    assert_eq!(max_depth_from(-1), Ok(None));
    assert_eq!(max_depth_from(1), Ok(Some(1)));
    assert_eq!(max_depth_from(65_535), Ok(Some(65_535)));
    for bad in [0, -2, -5, 65_536, 70_000, i64::MIN, i64::MAX] {
        let e = max_depth_from(bad).unwrap_err();
        assert!(e.ends_with(&format!("got {bad}")), "{e}");
    }
}
