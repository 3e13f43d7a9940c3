//! Unit tests of `plots/solid_angle.rs`.

use lesson11::plots::solid_angle::*;
use raytracer::math::Vec2;

#[test]
fn the_arc_covers_the_patch_as_cos_theta_y_da_over_r_squared() {
    let g = SolidAngle::default();
    let svg = solid_angle_svg(&g);
    assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
    for symbol in ["dω", "dA", "θ", ">r<", "cos"] {
        assert!(svg.contains(symbol), "{symbol}");
    }
    // The angle the patch subtends at x is, for a small patch,
    // 2·half·cos θ_y / r (radians of the unit circle): the figure's arc.
    let u = Vec2::from_angle(g.elevation_deg.to_radians());
    let y = X + g.r * u;
    let n_y = Vec2::from_angle(-g.theta_y_deg.to_radians()).rotate(-u);
    let t = n_y.perp();
    let (a, b) = ((y - g.half * t - X), (y + g.half * t - X));
    let subtended = a.angle_to(b).abs();
    let formula = 2.0 * g.half * g.theta_y_deg.to_radians().cos() / g.r;
    assert!(
        (subtended - formula).abs() < 0.05 * formula,
        "{subtended} vs {formula}"
    );
}
