//! Unit tests of `commands/lab/brdf.rs`.

use lesson11::commands::lab::brdf::*;
use lesson11::commands::lab::query::Query;
use raytracer::math::Vec3A;

fn choice(query: &str) -> Result<BrdfChoice, String> {
    let mut allowed = BRDF_PARAMS.to_vec();
    allowed.extend(["spp", "seed"]);
    choose(&Query::parse(query, &allowed)?)
}

/// At normal incidence normalized Phong's albedo is exactly ρ and
/// Lambert's is ρ at every angle: the midpoint rule gets them to 2e-3
/// (Lambert's weight is constant, so exactly up to rounding).
#[test]
fn the_albedo_is_exact_where_it_is_known() {
    for n in [0.0, 1.0, 10.0, 100.0, 1000.0] {
        let c = choice(&format!("model=phong&albedo=0.7&exponent={n}")).unwrap();
        let a = directional_albedo(&c.brdf, Vec3A::Z);
        assert!((a - 0.7).abs() < 2e-3, "n = {n}: {a}");
    }
    let c = choice("model=lambert&albedo=0.5").unwrap();
    for d in [0.0, 45.0, 85.0] {
        assert!((directional_albedo(&c.brdf, dir(d)) - 0.5).abs() < 1e-5);
    }
    for q in ["model=mirror&albedo=0.9", "model=glass&albedo=0.9&ior=1.5"] {
        let c = choice(q).unwrap();
        let a = directional_albedo(&c.brdf, dir(30.0));
        assert!((a - 0.9).abs() < 1e-5, "{q}: {a}");
    }
}

/// The lecture's point: original Phong with n = 1 reflects 2π/3 ≈ 2.09
/// times ρ at normal incidence; normalized Phong never exceeds ρ.
#[test]
fn the_verdict_tells_normalized_from_original_phong() {
    crate::english();
    let good = analyse(&choice("model=phong&exponent=1&albedo=1").unwrap(), 30.0);
    assert!(good.conserves_energy, "{}", good.verdict);
    assert!((good.max_albedo - 1.0).abs() < 2e-3 && good.max_at == 0.0);
    let bad = analyse(
        &choice("model=phong&exponent=1&albedo=1&phong=original").unwrap(),
        30.0,
    );
    assert!(!bad.conserves_energy);
    assert!((bad.max_albedo - 2.0 * std::f32::consts::PI / 3.0).abs() < 5e-3);
    assert!(bad.verdict.starts_with("violates"), "{}", bad.verdict);
    assert_eq!(good.lobe.len(), 181);
    // The lobe peaks in the mirror direction of the light (θ_o = +30°).
    let peak = good
        .lobe
        .iter()
        .fold([0.0, 0.0], |m, p| if p[1] > m[1] { *p } else { m });
    assert_eq!(peak[0], 30.0);
}

#[test]
fn delta_lobes_point_where_the_light_goes() {
    let m = analyse(&choice("model=mirror&albedo=0.5").unwrap(), 40.0);
    assert_eq!(m.deltas.len(), 1);
    assert!((m.deltas[0][0] - 40.0).abs() < 1e-3 && (m.deltas[0][1] - 0.5).abs() < 1e-6);
    let g = analyse(&choice("model=glass&albedo=1&ior=1.5").unwrap(), 40.0);
    assert_eq!(g.deltas.len(), 2, "{:?}", g.deltas);
    // Reflection F and refraction 1 − F add up to 1; Snell: sin 40° = 1.5 sin θ_t.
    assert!((g.deltas[0][1] + g.deltas[1][1] - 1.0).abs() < 1e-5);
    let t = 180.0 - (40f32.to_radians().sin() / 1.5).asin().to_degrees();
    assert!((g.deltas[1][0] - t).abs() < 1e-2, "{:?} vs {t}", g.deltas);
}

#[test]
fn bad_parameters_are_named() {
    for (q, reason) in [
        ("model=velvet", "`model` must be"),
        ("albedo=1.5", "`albedo` must be in [0, 1]"),
        (
            "model=lambert&exponent=3",
            "`exponent` is not a parameter of the lambert",
        ),
        ("exponent=-1", "`exponent` must be in"),
        ("phong=maybe", "`phong` must be"),
        ("model=glass&ior=0.5", "`ior` must be in"),
    ] {
        let e = choice(q).err().unwrap();
        assert!(e.contains(reason), "{q}: {e}");
    }
}
