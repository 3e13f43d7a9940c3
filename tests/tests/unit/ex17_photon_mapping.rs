//! Unit tests of `ex17_photon_mapping.rs`.

use grading::ex17_photon_mapping::*;

/// The grader's own estimate is the renderer's, in every case.
#[test]
fn the_right_variant_is_the_renderers_estimate() {
    for (m, it, b, s) in cases() {
        let (got, want) = (
            variant(&(m.clone(), it, b.clone(), s), V::Right),
            m.radiance(&it, &b, s, |_| true),
        );
        assert!(
            (got - want).abs().max_element() <= 1e-5 * want.max_element().max(1e-3),
            "{got} {want}"
        );
        assert!(want.max_element() > 0.0);
    }
}

/// Known quantiles of Student's t.
#[test]
fn t_quantiles() {
    for (nu, p, t) in [
        (15, 0.025, 2.131),
        (15, 0.0005, 4.073),
        (39, 0.001, 3.313),
        (1, 0.025, 12.706),
        (4, 0.005, 4.604),
    ] {
        let got = t_quantile(nu, p);
        assert!(
            (got - t).abs() < 2e-3 * t,
            "ν = {nu}, p = {p}: {got} vs {t}"
        );
    }
}
