//! Unit tests of `plots/zmap.rs`.

use lesson11::plots::zmap::*;
use raytracer::math::Color;
use raytracer::math::UVec2;
use raytracer::metrics::ZTest;

#[test]
fn the_map_runs_from_blue_through_white_to_red() {
    let (b, m, r) = (diverging(-1.0), diverging(0.0), diverging(1.0));
    assert!(b.z > b.x && r.x > r.z, "{b} {r}");
    assert!((m.x - m.y).abs() < 1e-6 && (m.y - m.z).abs() < 1e-6);
    assert_eq!(diverging(-5.0), b, "clamped");
}

#[test]
fn each_tile_shows_its_largest_z_with_its_sign() {
    let z = ZTest {
        tile: 2,
        grid: UVec2::new(2, 1),
        z: vec![Color::new(0.5, -3.0, 1.0), Color::new(0.0, 0.0, 4.0)],
        max_abs_z: 4.0,
        worst_tile: UVec2::new(1, 0),
    };
    let img = zmap_image(&z, 4, 2, 4.0, 3.5);
    assert_eq!(img.get(0, 0), diverging(-0.75));
    assert_eq!(img.get(3, 1), diverging(1.0));
    assert!(img.height > 2, "a colour bar below");
    // The bar's middle is white-grey, its ends the extremes.
    // The bar's last row: under the map (2), the gap (2) and the bar (6);
    // the bar's numbers are drawn under it.
    let last = 2 + 2 + 6 - 1;
    assert_eq!(img.get(0, last), diverging(-1.0));
    assert_eq!(img.get(3, last), diverging(1.0));
}
