//! Unit tests of `plots/palette.rs`.

use lesson11::plots::palette::*;

#[test]
fn every_algorithm_has_a_colour_of_its_own_that_no_other_curve_takes() {
    let mut seen: Vec<&str> = Vec::new();
    for d in Drawn::ALL {
        assert!(!seen.contains(&d.color()), "{d:?} shares its colour");
        seen.push(d.color());
    }
    for c in OTHERS.iter().chain([&GUIDE]) {
        assert!(!seen.contains(c), "{c} is an algorithm's colour");
    }
}

#[test]
fn the_labels_of_both_chapters_and_both_languages_name_their_algorithm() {
    for (label, d) in [
        ("naive recursion, N = 4 then 1", Drawn::Naive),
        ("наивна рекурсия", Drawn::Naive),
        ("path (MIS)", Drawn::Path),
        ("path tracing", Drawn::Path),
        ("path (BRDF only)", Drawn::PathBrdf),
        ("path tracing (само BRDF)", Drawn::PathBrdf),
        ("light", Drawn::Light),
        ("light tracing", Drawn::Light),
        ("bidirectional", Drawn::Bdpt),
        ("Metropolis (over bidirectional)", Drawn::Metropolis),
        ("photon mapping", Drawn::Photon),
        ("SPPM", Drawn::Sppm),
        ("instant radiosity", Drawn::Vpl),
        ("irradiance caching", Drawn::IrradianceCache),
    ] {
        assert_eq!(Drawn::of_label(label), Some(d), "{label}");
    }
    for other in ["Lambert", "Phong n=10", "reference noise floor", "bias²"] {
        assert_eq!(Drawn::of_label(other), None, "{other}");
    }
}
