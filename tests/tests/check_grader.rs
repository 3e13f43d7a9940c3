//! The grader tested: correct but different solutions pass, typical wrong
//! ones fail with a reason that names the mistake (each wrong fixture is a
//! correct solution with one change), the pictures of a failure are written
//! readable, and (with the feature `solutions`) the reference solutions pass.
//!
//! Named so that it runs before `exercises`: in `cargo test -p grading` the
//! progress table comes last.

mod fixtures;
mod unit;

use fixtures::{correct, wrong};
use grading::*;

fn passes(name: &str, r: Result<(), String>) {
    if let Err(e) = r {
        panic!("{name}: a correct solution failed: {e}");
    }
}

/// Fails, and the reason mentions `keyword` (case-insensitive; the reason
/// in English).
fn fails(name: &str, r: Result<(), String>, keyword: &str) {
    match r {
        Ok(()) => panic!("{name}: a wrong solution passed"),
        Err(e) => {
            println!("{name}: {e}");
            assert!(
                e.to_lowercase().contains(&keyword.to_lowercase()),
                "{name}: the reason should mention {keyword:?}: {e}"
            );
        }
    }
}

/// The numbers of a message (`0.318`, `-2`, `90`), in order of size, to
/// compare a message with its translation.
fn numbers(message: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut current = String::new();
    for c in message.chars().chain(std::iter::once(' ')) {
        if c.is_ascii_digit() || (c == '.' && !current.is_empty()) {
            current.push(c);
        } else if !current.is_empty() {
            out.push(current.trim_end_matches('.').to_string());
            current.clear();
        }
    }
    out.sort();
    out
}

/// Fails in English with a reason that mentions `keyword` (as [`fails`]),
/// and fails in Bulgarian naming the same mistake: the same messages (keys
/// of `tests/messages/*.toml`) with the same numbers, in Bulgarian words,
/// every placeholder filled. Every grader's messages are keyed, so a failure
/// with no key is one that no table words: it fails here.
fn fails_in_both(name: &str, run: impl Fn() -> Result<(), String>, keyword: &str) {
    use grading::messages::{Lang, keys_used, lang};
    let (en, en_keys) = lang::with(Lang::En, || keys_used(&run));
    fails(name, en.clone(), keyword);
    assert!(
        !en_keys.is_empty(),
        "{name}: its message comes from no key of tests/messages, so no language table words it"
    );
    let (bg, bg_keys) = lang::with(Lang::Bg, || keys_used(&run));
    let (Err(en), Err(bg)) = (en, bg) else {
        panic!("{name}: fails in English but passes in Bulgarian");
    };
    println!("{name} (bg): {bg}");
    assert_eq!(
        en_keys, bg_keys,
        "{name}: other messages in Bulgarian:\n{en}\n{bg}"
    );
    assert_ne!(en, bg, "{name}: the Bulgarian message is the English one");
    assert!(
        bg.chars()
            .any(|c| ('а'..='я').contains(&c.to_lowercase().next().unwrap_or(c))),
        "{name}: no Bulgarian in {bg}"
    );
    let holes: Vec<String> = grading::messages::catalog(Lang::Bg)
        .values()
        .flat_map(|t| lang::placeholders(t))
        .filter(|p| bg.contains(&format!("{{{p}}}")) || bg.contains(&format!("{{{p}:")))
        .collect();
    assert!(holes.is_empty(), "{name}: unfilled {holes:?} in {bg}");
    assert_eq!(
        numbers(&en),
        numbers(&bg),
        "{name}: the Bulgarian message has other numbers than the English one:\n{en}\n{bg}"
    );
}

/// `f` in English, whatever the locale: for the tests that read a message.
fn english<R>(f: impl FnOnce() -> R) -> R {
    grading::messages::lang::with(grading::messages::Lang::En, f)
}

/// `fails!(name, check, keyword)`: [`fails_in_both`], running the check in
/// each language.
macro_rules! fails {
    ($name:expr, $r:expr, $keyword:expr $(,)?) => {
        fails_in_both($name, || $r, $keyword)
    };
}

#[test]
fn ex01_stereo_eyes() {
    use ex01_stereo_eyes::check;
    passes(
        "recomputed rightDir, look_at C ahead, slide from a projected point",
        check(correct::stereo_eyes),
    );
    fails!("swapped eyes", check(wrong::eyes_swapped), "swapped");
    fails!(
        "full separation each side",
        check(wrong::eyes_too_far),
        "twice too far apart",
    );
    fails!("toe-in", check(wrong::eyes_toe_in), "vertical parallax");
    fails!(
        "no slide",
        check(wrong::eyes_no_slide),
        "infinitely far away"
    );
    fails!(
        "slid the wrong way",
        check(wrong::eyes_slide_wrong_way),
        "the wrong way"
    );
    fails!(
        "slide not divided by C",
        check(wrong::eyes_slide_without_c),
        "as if the convergence distance were 1"
    );
    fails!(
        "both windows slid the same way too",
        check(wrong::eyes_off_centre),
        "off-centre"
    );
}

#[test]
fn ex02_anaglyph() {
    use ex02_anaglyph::check;
    passes(
        "another schedule, channel by channel",
        check(correct::desaturate, correct::anaglyph),
    );
    fails!(
        "towards the mean of the channels",
        check(wrong::desaturate_to_mean, correct::anaglyph),
        "plain average",
    );
    fails!(
        "Rec. 601 weights",
        check(wrong::desaturate_rec601, correct::anaglyph),
        "keep y at every d",
    );
    fails!(
        "a hue that turns",
        check(wrong::desaturate_turning, correct::anaglyph),
        "the colour turns",
    );
    fails!(
        "swapped channels",
        check(correct::desaturate, wrong::anaglyph_swapped),
        "swapped",
    );
    fails!(
        "no desaturation",
        check(correct::desaturate, wrong::anaglyph_saturated),
        "not desaturated",
    );
}

#[test]
fn ex03_lambert() {
    passes("min of cosines", ex03_lambert::check(correct::lambert_eval));
    fails!(
        "missing 1/π",
        ex03_lambert::check(wrong::lambert_no_inv_pi),
        "too bright by a factor π",
    );
    fails!(
        "cosine in the BRDF",
        ex03_lambert::check(wrong::lambert_with_cos),
        "cosine counts twice",
    );
}

#[test]
fn ex04_phong() {
    let (s, f) = (correct::phong_normalization, correct::phong_eval);
    passes("1/integral, mirrored wi", ex04_phong::check(s, f));
    // Issue 12, item 2: with (n+1)/(2π) energy is LOST, not created.
    fails!(
        "(n+1)/2π",
        ex04_phong::check(wrong::phong_s_without_cosine, f),
        "falls short of ρ_s, the more the smaller n is — energy is lost",
    );
    fails!(
        "unnormalized",
        ex04_phong::check(wrong::phong_unnormalized, f),
        "unnormalized",
    );
    fails!(
        "S(n) for integer n only",
        ex04_phong::check(wrong::phong_s_integer, f),
        "rounded to an integer",
    );
    fails!(
        "π missing from S(n)",
        ex04_phong::check(wrong::phong_s_no_pi, f),
        "missing π",
    );
    fails!(
        "no clamp",
        ex04_phong::check(s, wrong::phong_eval_unclamped),
        "a negative cosine went into the power",
    );
    fails!(
        "cos α from the normal",
        ex04_phong::check(s, wrong::phong_eval_from_normal),
        "angle from the normal",
    );
    fails!(
        "powi",
        ex04_phong::check(s, wrong::phong_eval_integer_power),
        "integer exponents only",
    );
}

#[test]
fn ex05_cone_lobe() {
    passes(
        "1/(π(1 − cos²))",
        ex05_cone_lobe::check(correct::cone_normalization),
    );
    passes(
        "f64",
        ex05_cone_lobe::check(correct::cone_normalization_f64),
    );
    fails!(
        "one over the solid angle",
        ex05_cone_lobe::check(wrong::cone_solid_angle),
        "energy is lost",
    );
    fails!(
        "small-angle approximation",
        ex05_cone_lobe::check(wrong::cone_small_angle),
        "sin θ_m ≈ θ_m",
    );
    fails!(
        "Lambert's constant",
        ex05_cone_lobe::check(wrong::cone_lambert),
        "Lambert's constant",
    );
    fails!(
        "π missing",
        ex05_cone_lobe::check(wrong::cone_no_pi),
        "missing π",
    );
}

#[test]
fn ex06_mirror() {
    passes(
        "tangential reflect, f in f64",
        ex06_mirror::check(correct::reflect, correct::mirror_sample),
    );
    fails!(
        "f = R",
        ex06_mirror::check(correct::reflect, wrong::mirror_f_is_r),
        "too dark at grazing angles",
    );
    // The weight f·|cos θ_i|/pdf_w is right, the pdf is not a probability.
    fails!(
        "f = R, pdf_w = cos θ_i",
        ex06_mirror::check(correct::reflect, wrong::mirror_pdf_is_cos),
        "it equals cos θ_i",
    );
    fails!(
        "reflect inwards",
        ex06_mirror::check(wrong::reflect_inwards, correct::mirror_sample),
        "into the surface",
    );
    fails!(
        "a sample at wo.z = 0",
        ex06_mirror::check(correct::reflect, wrong::mirror_at_grazing),
        "no reflected direction above the surface",
    );
}

#[test]
fn ex07_cosine_sampling() {
    passes(
        "concentric disk",
        ex07_cosine_sampling::check(correct::cosine_concentric, correct::cosine_pdf),
    );
    passes(
        "inversion, numbers swapped",
        ex07_cosine_sampling::check(correct::cosine_inversion, correct::cosine_pdf),
    );
    fails!(
        "uniform directions",
        ex07_cosine_sampling::check(wrong::cosine_but_uniform, correct::cosine_pdf),
        "UNIFORM directions",
    );
    fails!(
        "r = u",
        ex07_cosine_sampling::check(wrong::cosine_no_sqrt, correct::cosine_pdf),
        "a uniform radius",
    );
    fails!(
        "sin θ = u",
        ex07_cosine_sampling::check(wrong::cosine_sin_not_squared, correct::cosine_pdf),
        "a uniform radius",
    );
    fails!(
        "cos³ directions",
        ex07_cosine_sampling::check(wrong::cosine_cubed, correct::cosine_pdf),
        "cos³θ",
    );
    let _ = std::fs::remove_file(ex07_cosine_sampling::histogram_path());
    fails!(
        "φ = π·u",
        ex07_cosine_sampling::check(wrong::cosine_half_phi, correct::cosine_pdf),
        "half a turn",
    );
    // The histograms of the student's directions, beside the other pictures.
    let size = pictures::png_size(&ex07_cosine_sampling::histogram_path());
    assert_eq!(size.ok(), Some((512, 384)));
    fails!(
        "uniform pdf",
        ex07_cosine_sampling::check(correct::cosine_concentric, wrong::pdf_uniform),
        "uniform",
    );
    fails!(
        "cos³ pdf",
        ex07_cosine_sampling::check(correct::cosine_concentric, wrong::pdf_cos_cubed),
        "cos³θ",
    );
    fails!(
        "π missing from the pdf",
        ex07_cosine_sampling::check(correct::cosine_concentric, wrong::pdf_no_pi),
        "missing normalization",
    );
}

#[test]
fn ex08_phong_lobe_pdf() {
    passes(
        "exp and ln",
        ex08_phong_lobe_pdf::check(correct::phong_pdf_exp),
    );
    passes("f64", ex08_phong_lobe_pdf::check(correct::phong_pdf_f64));
    fails!(
        "S(n) for the density",
        ex08_phong_lobe_pdf::check(wrong::phong_pdf_is_s),
        "S(n), the BRDF's normalization",
    );
    fails!(
        "density of cos α alone",
        ex08_phong_lobe_pdf::check(wrong::phong_pdf_no_2pi),
        "spread of the directions over φ is missing",
    );
    fails!(
        "per dα dφ",
        ex08_phong_lobe_pdf::check(wrong::phong_pdf_per_dalpha),
        "density per dα dφ",
    );
    fails!(
        "π missing",
        ex08_phong_lobe_pdf::check(wrong::phong_pdf_no_pi),
        "missing π",
    );
    fails!(
        "nonzero below",
        ex08_phong_lobe_pdf::check(wrong::phong_pdf_below),
        "have density 0",
    );
}

#[test]
fn ex09_albedo() {
    passes(
        "uniform sampling",
        ex09_albedo::check(correct::albedo_uniform),
    );
    passes(
        "cosine sampling, other numbers",
        ex09_albedo::check(correct::albedo_cosine),
    );
    passes(
        "stratified BRDF sampling",
        ex09_albedo::check(correct::albedo_stratified),
    );
    fails!(
        "missing cosine",
        ex09_albedo::check(wrong::albedo_no_cos),
        "cosine θ_i is missing",
    );
    fails!(
        "cosine of ω_o",
        ex09_albedo::check(wrong::albedo_cos_o),
        "that of ω_o",
    );
    fails!(
        "missing pdf",
        ex09_albedo::check(wrong::albedo_no_pdf),
        "not divided by the density",
    );
    fails!(
        "N − 1",
        ex09_albedo::check(wrong::albedo_n_minus_1),
        "divided by N − 1",
    );
    fails!(
        "refused draws left out",
        ex09_albedo::check(wrong::albedo_refused_left_out),
        "a refused draw (Brdf::sample returned None) still counts",
    );
}

#[test]
fn ex10_naive_recursive() {
    passes(
        "uniform branches",
        ex10_naive_recursive::check(correct::naive_uniform),
    );
    fails!(
        "branches summed",
        ex10_naive_recursive::check(wrong::naive_not_averaged),
        "summed, not averaged",
    );
    fails!(
        "missing cosine",
        ex10_naive_recursive::check(wrong::naive_no_cos),
        "furnace",
    );
    fails!(
        "signed cosine",
        ex10_naive_recursive::check(wrong::naive_signed_cos),
        "= 0.5 − 0.25: the sign alternates",
    );
    fails!(
        "the lecture's sign with our ω_i",
        ex10_naive_recursive::check(wrong::naive_other_sign),
        "sign flipped",
    );
    fails!(
        "one bounce too many",
        ex10_naive_recursive::check(wrong::naive_one_bounce_more),
        "max_depth D counts the segments",
    );
    // Both give 0.5 at max_depth 2; max_depth 3 (0.75 against 0.5) tells
    // which mistake it is.
    fails!(
        "one bounce too few",
        ex10_naive_recursive::check(wrong::naive_one_bounce_fewer),
        "your mean is that of max_depth 1",
    );
    let e =
        english(|| ex10_naive_recursive::check(wrong::naive_emission_only_at_camera)).unwrap_err();
    assert!(
        e.contains("max_depth 2") && e.contains("only the camera ray's hit adds its emission"),
        "emission only at the camera's hit: {e}"
    );
    assert!(!e.contains("that of max_depth 1"), "{e}");
}

#[test]
fn ex11_path_tracing() {
    passes(
        "roulette on luminance, other numbers",
        ex11_path_tracing::check(correct::path_luminance_rr),
    );
    passes(
        "without roulette",
        ex11_path_tracing::check(correct::path_no_rr),
    );
    passes(
        "recursive",
        ex11_path_tracing::check(correct::path_recursive),
    );
    fails!(
        "roulette without 1/q",
        ex11_path_tracing::check(wrong::path_rr_no_division),
        "survival probability",
    );
    fails!(
        "emission at the first hit only",
        ex11_path_tracing::check(wrong::path_first_emission_only),
        "only the first hit",
    );
    // The case: 0.375 = 0.5 − 0.25 + 0.125 at max_depth 3.
    fails!(
        "signed cosine",
        ex11_path_tracing::check(wrong::path_signed_cos),
        "0.3750 = 0.5 − 0.25 + 0.125: the sign alternates",
    );
    fails!(
        "the lecture's sign with our ω_i",
        ex11_path_tracing::check(wrong::path_other_sign),
        "sign flipped",
    );
    fails!(
        "L_e without β",
        ex11_path_tracing::check(wrong::path_le_without_beta),
        "adds its emission unweighted",
    );
    // The white furnace's throughput stays 1: only the grey sphere sees it.
    fails!(
        "escaped radiance without β",
        ex11_path_tracing::check(wrong::path_escape_without_beta),
        "adds the sky unweighted",
    );
    fails!(
        "no cosine",
        ex11_path_tracing::check(wrong::path_no_cos),
        "cosine θ_i is missing",
    );
}

#[test]
fn ex12_nee() {
    use fixtures::ex12::{correct, wrong};
    let (pdf, direct) = (correct::area_pdf_to_solid_angle, correct::estimate_direct);
    let path = correct::path_nee;
    passes("geometry term", ex12_nee::check(pdf, direct, path));
    passes(
        "through Light::sample_li, recursive NEE path tracer",
        ex12_nee::check(
            pdf,
            correct::estimate_direct_sample_li,
            correct::path_nee_recursive,
        ),
    );
    fails!(
        "pdf not converted",
        ex12_nee::check(wrong::area_pdf_unchanged, direct, path),
        "per unit AREA",
    );
    fails!(
        "edge-on light",
        ex12_nee::check(wrong::area_pdf_edge_on_infinite, direct, path),
        "edge-on",
    );
    fails!(
        "signed cos θ_y in the conversion",
        ex12_nee::check(wrong::area_pdf_signed, direct, path),
        "a signed cos θ_y",
    );
    for (name, f, keyword) in [
        (
            "estimate in the area measure",
            wrong::direct_area_measure as ex12_nee::DirectFn,
            "divided by the density per unit AREA",
        ),
        (
            "no shadow ray",
            wrong::direct_no_shadow_ray,
            "no shadow ray tests the visibility",
        ),
        (
            "no cosine at the surface",
            wrong::direct_no_surface_cosine,
            "the cosine at the surface is missing",
        ),
        (
            "r instead of r²",
            wrong::direct_r_not_squared,
            "divided by r instead of r²",
        ),
        ("no light-choice pmf", wrong::direct_no_pmf, "is left out"),
        (
            "two-sided emission",
            wrong::direct_two_sided,
            "emits on one side only",
        ),
        (
            "signed cos θ_i",
            wrong::direct_signed_cos,
            "a signed cos θ_i",
        ),
        (
            "signed cos θ_y behind a two-sided light",
            wrong::direct_signed_light_cos,
            "negative behind a two-sided light",
        ),
    ] {
        fails!(name, ex12_nee::check(pdf, f, path), keyword);
    }
    for (name, p, keyword) in [
        (
            "emission counted at every hit",
            wrong::path_emission_everywhere as exercises::plug::PathRadianceFn,
            "already counts the light",
        ),
        (
            "no emission after a mirror",
            wrong::path_no_emission_after_delta,
            "the light seen in a mirror is missing",
        ),
        (
            "light sample without β",
            wrong::path_nee_without_beta,
            "not weighted by the throughput β",
        ),
        (
            "light sample beyond the depth",
            wrong::path_nee_beyond_depth,
            "one bounce too many",
        ),
        (
            "the sky after every bounce",
            wrong::path_sky_everywhere,
            "the sky is a light as well",
        ),
        (
            "roulette without 1/q",
            wrong::path_roulette_no_divide,
            "too dark with roulette",
        ),
    ] {
        fails!(name, ex12_nee::check(pdf, direct, p), keyword);
    }
}

#[test]
fn ex13_mis() {
    use fixtures::ex13::{correct, wrong};
    passes(
        "ratio in f64, other order",
        ex13_mis::check(correct::mis_ratio_f64),
    );
    passes("recursive", ex13_mis::check(correct::mis_recursive));
    for (name, f, keyword) in [
        (
            "balance heuristic",
            wrong::mis_balance as exercises::plug::PathRadianceFn,
            "that is the balance heuristic",
        ),
        ("exponent 3", wrong::mis_exponent_3, "exponent 3"),
        (
            "BRDF hit unweighted",
            wrong::mis_brdf_hit_unweighted,
            "counts unweighted while the light sample of the same direction is weighted",
        ),
        (
            "area density in the BRDF hit's weight",
            wrong::mis_area_density,
            "density per unit AREA",
        ),
        (
            "MIS after a delta bounce",
            wrong::mis_after_delta,
            "MIS after a delta",
        ),
        (
            "no pmf in the BRDF hit's weight",
            wrong::mis_no_pmf_in_brdf_weight,
            "P(light) is missing from the light strategy's density in the weight of the emitter found by the BRDF sample",
        ),
        (
            "no pmf in the light sample's weight",
            wrong::mis_no_pmf_in_light_weight,
            "P(light) is missing from the light strategy's density in the light sample's weight",
        ),
        ("swapped weights", wrong::mis_swapped, "swapped"),
        ("weights 1/2", wrong::mis_half, "spread of your estimates"),
    ] {
        fails!(name, ex13_mis::check(f), keyword);
    }
}

/// The variance ratios of MIS renders of Veach's plates against each
/// strategy alone (printed for the documentation of
/// [`ex13_mis::MAX_VARIANCE_RATIO`]): a correct variant passes the
/// threshold, weights of 1/2 and swapped weights (unbiased both) do not.
#[test]
fn ex13_variance_ratios() {
    use exercises::plug::PathRadianceFn;
    use fixtures::ex13::{correct, wrong};
    let max = ex13_mis::MAX_VARIANCE_RATIO;
    for (name, f, below) in [
        ("correct", correct::mis_ratio_f64 as PathRadianceFn, true),
        ("balance", wrong::mis_balance, true),
        ("weights 1/2", wrong::mis_half, false),
        ("swapped", wrong::mis_swapped, false),
    ] {
        let (brdf, light) = ex13_mis::variance_ratios(f).unwrap();
        println!("{name}: MIS / BRDF only = {brdf:.3}, MIS / light only = {light:.3}");
        assert_eq!(brdf.max(light) <= max, below, "{name}: {brdf} {light}");
    }
}

#[test]
fn ex14_light_tracing() {
    use fixtures::ex14;
    passes(
        "G · W_e over the lens density, q = 0.95",
        ex14_light_tracing::check(ex14::by_geometry),
    );
    passes(
        "Camera::sample_wi, a uniform light choice of its own, q from the walk",
        ex14_light_tracing::check(ex14::by_sample_wi_uniform),
    );
    for (name, f, keyword) in [
        (
            "no W_e",
            ex14::no_importance as ex14_light_tracing::LightFn,
            "importance W_e",
        ),
        (
            "no cosine at the surface",
            ex14::no_cos_surface,
            "cosine at the surface",
        ),
        (
            "no cosine at the lens",
            ex14::no_cos_lens,
            "cosine at the lens",
        ),
        ("signed cosines", ex14::signed_cos, "signed cosine"),
        ("1/d", ex14::inv_distance, "too slowly with distance"),
        (
            "no 1/d²",
            ex14::no_inv_distance2,
            "do not fall off with distance",
        ),
        (
            "radiance mode at glass",
            ex14::radiance_mode,
            "radiance transport",
        ),
        (
            "splats off the film",
            ex14::off_film,
            "where the camera sees nothing",
        ),
        ("roulette without 1/q", ex14::roulette_no_divide, "roulette"),
        ("no light-choice pmf", ex14::no_light_pmf, "probability"),
        (
            "β without the cosine at the light",
            ex14::no_cos_light,
            "cosine at the light",
        ),
        ("no shadow ray", ex14::no_visibility, "shadow test"),
    ] {
        fails!(name, ex14_light_tracing::check(f), keyword);
    }
}

/// The false-failure rate of exercise 14's grader, measured over seeds (light
/// tracing's splats are heavy-tailed, so the normal approximation of its
/// z-tests is checked): the reference solution (with the feature
/// `solutions`) and the two correct fixtures, 20 seeds each; 7 s on two
/// cores (`cargo test -p grading --features solutions --test check_grader
/// ex14_false_failures`).
#[test]
fn ex14_false_failures() {
    use fixtures::ex14;
    let mut failed = Vec::new();
    for (name, f) in [
        (
            "reference solution",
            exercises::ex14_light_tracing::trace_light_path as ex14_light_tracing::LightFn,
        ),
        ("by_geometry", ex14::by_geometry),
        ("by_sample_wi_uniform", ex14::by_sample_wi_uniform),
    ] {
        if name == "reference solution" && !exercises::SOLUTIONS {
            continue; // the stub: not started
        }
        for seed in 0..20u64 {
            if let Err(e) = ex14_light_tracing::check_with_seed(f, 1000 + 10 * seed) {
                failed.push(format!("{name}, seed {seed}: {e}"));
            }
        }
    }
    assert!(
        failed.is_empty(),
        "{} of 60 failed:\n{}",
        failed.len(),
        failed.join("\n")
    );
}

#[test]
fn ex15_bdpt() {
    fixtures::ex15::check();
}

#[test]
fn ex17_photon_mapping() {
    use fixtures::ex17::*;
    use grading::ex17_photon_mapping::{RadianceFn, TraceFn, check};
    passes(
        "other order of numbers, survival 1/2, f64 flux; full sort, f64 kernel",
        check(trace::<0>, radiance::<0>),
    );
    passes(
        "survival by the throughput capped at 0.9; the renderer's kernel",
        check(trace::<OTHER_ROULETTE>, radiance::<LIBRARY_KERNEL>),
    );
    let t = trace::<0> as TraceFn;
    let r = radiance::<0> as RadianceFn;
    for (name, (tf, rf), keyword) in [
        (
            "flux not shared among the N paths",
            (trace::<NO_SHARE> as TraceFn, r),
            "N paths",
        ),
        (
            "roulette without dividing the flux",
            (trace::<ROULETTE_UNDIVIDED> as TraceFn, r),
            "not divided by its survival",
        ),
        (
            "photons stored on glass",
            (trace::<STORE_AT_SPECULAR> as TraceFn, r),
            "specular hits",
        ),
        (
            "cosine at the hit in the stored flux",
            (trace::<COSINE_AT_HIT> as TraceFn, r),
            "cosine at the hit",
        ),
        (
            "no cosine at the light",
            (trace::<NO_COSINE_AT_LIGHT> as TraceFn, r),
            "cosine at the light",
        ),
        (
            "the flux without the light's probability",
            (trace::<NO_PICK> as TraceFn, r),
            "weighted by how often that light is picked",
        ),
        (
            "no π in the kernel",
            (t, radiance::<NO_PI> as RadianceFn),
            "misses the π",
        ),
        (
            "the radius not squared",
            (t, radiance::<RADIUS_NOT_SQUARED> as RadianceFn),
            "its square",
        ),
        (
            "Epanechnikov's shape with a plain disk's constant",
            (t, radiance::<BOX_CONSTANT> as RadianceFn),
            "plain disk's constant",
        ),
        (
            "half the radius",
            (t, radiance::<HALF_RADIUS> as RadianceFn),
            "half as wide",
        ),
        (
            "the (k+1)-th neighbour's distance",
            (t, radiance::<K_PLUS_ONE> as RadianceFn),
            "(k+1)-th",
        ),
        (
            "the mean distance as the radius",
            (t, radiance::<MEAN_DISTANCE> as RadianceFn),
            "mean distance",
        ),
        (
            "f_r in world space",
            (t, radiance::<WORLD_FRAME> as RadianceFn),
            "local frame",
        ),
        (
            "f_r with the direction of travel",
            (t, radiance::<TRAVEL_DIRECTION> as RadianceFn),
            "direction of travel",
        ),
        (
            "the cosine at x in the estimate",
            (t, radiance::<COSINE_IN_ESTIMATE> as RadianceFn),
            "already carries",
        ),
    ] {
        fails!(name, check(tf, rf), keyword);
    }
}

/// The caustic comparison of exercise 17 over many seeds of the student's
/// photon maps: a correct solution (another roulette, another order of the
/// random numbers) passes for every seed, with the largest |z| well under
/// the threshold (measured: see `tests/src/ex17_photon_mapping.rs`).
/// 24 renders of 32 photon maps each: 3 s on two cores.
#[test]
fn ex17_caustic_comparison_over_seeds() {
    use fixtures::ex17::*;
    let mut largest = 0.0f64;
    for seed in 0..24u64 {
        let mut z = 0.0;
        passes(
            &format!("seed {seed}"),
            ex17_photon_mapping::compare_caustic_z(
                trace::<OTHER_ROULETTE>,
                radiance::<0>,
                1_000 + 97 * seed,
                Some(&mut z),
            ),
        );
        largest = largest.max(z);
    }
    println!("largest |z| / threshold over 24 seeds: {largest:.3}");
}

#[test]
fn ex18_instant_radiosity() {
    use ex18_instant_radiosity::check;
    use fixtures::ex18::*;
    passes(
        "variant A: f64, other order of numbers, fixed roulette",
        check(generate::<A, NONE>, gather::<A, NONE>),
    );
    passes(
        "variant B: roulette from the mean throughput, weight from the area",
        check(generate::<B, NONE>, gather::<B, NONE>),
    );
    fails!(
        "signed G",
        check(generate::<A, NONE>, gather::<A, SIGNED>),
        "signed cosines",
    );
    fails!(
        "the VPL's cosine with its incoming direction",
        check(generate::<A, NONE>, gather::<A, INCOMING>),
        "cosine at the wrong end",
    );
    fails!(
        "r for r²",
        check(generate::<A, NONE>, gather::<A, R>),
        "r for r²",
    );
    fails!(
        "clamp on the contribution",
        check(generate::<A, NONE>, gather::<A, CLAMP_LIGHT>),
        "applied to the contribution",
    );
    fails!(
        "clamp where none is asked",
        check(generate::<A, NONE>, gather::<A, CLAMP_ALWAYS>),
        "where none is asked",
    );
    fails!(
        "no shadow ray",
        check(generate::<A, NONE>, gather::<A, NO_SHADOW>),
        "shadow ray",
    );
    fails!(
        "no cosine at a surface VPL",
        check(generate::<A, NONE>, gather::<A, NO_COS_SURFACE>),
        "cosine at a VPL on a surface is missing",
    );
    fails!(
        "no cosine at any VPL",
        check(generate::<A, NONE>, gather::<A, NO_COS_Y>),
        "the cosine at the VPL's end is missing",
    );
    fails!(
        "the VPL on the light without the light's probability",
        check(generate::<A, NO_PICK_WEIGHT>, gather::<A, NONE>),
        "a light picked more often gets heavier VPLs",
    );
    fails!(
        "the light path's flux without the light's probability",
        check(generate::<A, NO_PICK_FLUX>, gather::<A, NONE>),
        "weighted by how often that light is picked",
    );
    fails!(
        "flux not divided by N",
        check(generate::<A, NOT_SHARED>, gather::<A, NONE>),
        "do not share the light",
    );
    fails!(
        "no VPL on the light",
        check(generate::<A, NO_LIGHT_VPL>, gather::<A, NONE>),
        "direct light is missing",
    );
    fails!(
        "VPLs on mirrors",
        check(generate::<A, SPECULAR_VPL>, gather::<A, NONE>),
        "specular hits",
    );
    fails!(
        "roulette without division",
        check(generate::<A, ROULETTE_NO_DIV>, gather::<A, NONE>),
        "roulette without division",
    );
}

#[test]
fn ex16_metropolis() {
    use fixtures::ex16;
    use grading::ex16_metropolis::check;
    passes(
        "reservoir start, normal small steps",
        check(ex16::reservoir),
    );
    passes("list and cumulative sum in f64", check(ex16::in_f64));
    fails!("ratio upside down", check(ex16::upside_down), "upside down");
    fails!(
        "accepted state only",
        check(ex16::accepted_only),
        "only the state the chain moves to",
    );
    fails!("splats without b", check(ex16::no_b), "normalization b̂");
    fails!(
        "splats without 1/I",
        check(ex16::not_over_i),
        "not divided by the scalar contribution",
    );
    fails!(
        "small step without wrapping",
        check(ex16::no_wrap),
        "leave [0, 1)",
    );
    fails!(
        "small step clamped at the edges",
        check(ex16::clamped),
        "not symmetric",
    );
    fails!("uniform start", check(ex16::uniform_start), "start-up bias");
    fails!(
        "b over the paths that found light",
        check(ex16::b_over_nonzero),
        "found light only",
    );
    fails!("b over n - 1", check(ex16::b_over_n_minus_one), "n/(n − 1)");
}

/// The tables of deterministic answers the grader compares with: a change
/// here changes what students must produce (`cargo insta review`).
#[test]
fn reference_tables() {
    let mut t = String::from("S(n) of the normalized Phong lobe\n");
    for n in ex04_phong::EXPONENTS {
        t.push_str(&format!(
            "  n = {n:>6}: S = {:.6}\n",
            ex04_phong::expected_s(n)
        ));
    }
    t.push_str("C(θ_m) of the uniform cone lobe\n");
    for a in ex05_cone_lobe::ANGLES {
        t.push_str(&format!(
            "  θ_m = {a:.4}: C = {:.6}\n",
            ex05_cone_lobe::expected(a)
        ));
    }
    t.push_str("density of the Phong-lobe warp\n");
    for (n, c) in ex08_phong_lobe_pdf::cases()
        .into_iter()
        .filter(|&(_, c)| c == 1.0)
    {
        t.push_str(&format!(
            "  n = {n:>5}, cos α = 1: p = {:.6}\n",
            ex08_phong_lobe_pdf::expected(n, c)
        ));
    }
    t.push_str("anaglyph(left, right, d)\n");
    for (l, r, d) in ex02_anaglyph::cases() {
        let a = ex02_anaglyph::expected(l, r, d);
        t.push_str(&format!("  {l:.3} {r:.3} d = {d:.2} -> {a:.4}\n"));
    }
    t.push_str("stereo eyes (left, right): position, window shift\n");
    for (c, s, conv) in ex01_stereo_eyes::cameras() {
        let (l, r) = ex01_stereo_eyes::expected(&c, s, conv);
        t.push_str(&format!(
            "  s = {s}, C = {conv}: {:.4} {:.6}, {:.4} {:.6}\n",
            l.position, l.shift, r.position, r.shift
        ));
    }
    insta::assert_snapshot!(t);
}

/// Exercise 12's analytic cases can name a mistake only if the values the
/// mistakes converge to lie far from the right answer and from each other:
/// more than 10% (the tests' noise is about 0.3%). That Lambert's formula
/// and the quadrature agree is `polygon`'s own test.
#[test]
fn nee_mistakes_are_far_apart() {
    let cases = ex12_nee::cases();
    assert_eq!(cases.len(), 6);
    for c in &cases {
        assert!(c.exact.min_element() > 0.0, "{}", c.what);
        for (k, (v, why)) in c.named.iter().enumerate() {
            let apart = |a: raytracer::math::Color, b: raytracer::math::Color| {
                ((a - b).abs() / b.abs().max(raytracer::math::Color::splat(1e-6))).max_element()
                    > 0.1
            };
            assert!(apart(*v, c.exact), "{}: {why}", c.what);
            for (w, other) in &c.named[k + 1..] {
                assert!(apart(*v, *w), "{why} vs {other}");
            }
        }
    }
}

/// An image comparison that fails writes the student's picture, the
/// reference and the z-map enlarged to at least 256 pixels across.
#[test]
fn failure_pictures_are_enlarged() {
    use grading::compare::{EX12_CORNELL_DIRECT, compare_into};
    let dir = std::env::temp_dir().join(format!("grading-pictures-{}", std::process::id()));
    let wrong = exercises::plug::StudentDirect(fixtures::ex12::wrong::direct_area_measure);
    let e = english(|| compare_into(&EX12_CORNELL_DIRECT, &wrong, 5, &dir)).unwrap_err();
    assert!(e.contains(&dir.display().to_string()), "{e}");
    for suffix in ["student", "reference", "z"] {
        let path = dir.join(format!("ex12_cornell_direct_{suffix}.png"));
        let (w, h) = pictures::png_size(&path).expect("written");
        assert!(
            w >= pictures::MIN_WIDTH && w == h,
            "{}: {w}×{h}",
            path.display()
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Every reference solution passes, graded as the student's code is (the
/// shortcut check included).
#[cfg(feature = "solutions")]
#[test]
fn reference_solutions_pass() {
    let threads = std::thread::available_parallelism().map_or(2, |n| n.get());
    for g in grade_all(threads, TIMEOUT) {
        assert!(g.outcome.is_passed(), "{}: {}", g.exercise.name, g.outcome);
    }
}

/// The image comparison of correct integrators against the stored references
/// under 12 other seeds: at the family level α = 1e-4 none may fail (a failure here
/// would mean the z-test's tails are heavier than assumed). Also the light
/// sampling reference of exercise 12.
#[test]
fn image_comparison_does_not_fail_correct_integrators() {
    use grading::compare::{EX11_CORNELL, EX12_CORNELL_DIRECT, compare_with_seed};
    let variant = exercises::plug::StudentPathTracer {
        path_radiance: correct::path_luminance_rr,
        max_depth: Some(5),
        rr_depth: 3,
    };
    let direct = exercises::plug::StudentDirect(fixtures::ex12::correct::estimate_direct);
    for seed in 0..12u64 {
        let r = compare_with_seed(&EX11_CORNELL, &variant, 100 + seed);
        assert!(r.is_ok(), "seed {seed}: {r:?}");
        let r = compare_with_seed(&EX12_CORNELL_DIRECT, &direct, 300 + seed);
        assert!(r.is_ok(), "seed {seed}: {r:?}");
    }
}

/// Exercises 12 and 13's image comparisons under 12 other seeds, with
/// correct variants: none may fail (family level α = 1e-4 each).
#[test]
fn ex12_ex13_image_comparisons_do_not_fail_correct_integrators() {
    use exercises::plug::{PathRadianceFn, StudentPathTracer};
    use grading::compare::{EX12_CORNELL, EX13_CORNELL, EX13_VEACH, compare_with_seed};
    let tracer = |f: PathRadianceFn, max_depth| StudentPathTracer {
        path_radiance: f,
        max_depth: Some(max_depth),
        rr_depth: 3,
    };
    for seed in 0..12u64 {
        let r = compare_with_seed(
            &EX12_CORNELL,
            &tracer(fixtures::ex12::correct::path_nee, 5),
            400 + seed,
        );
        assert!(r.is_ok(), "seed {seed}: {r:?}");
        let mis = fixtures::ex13::correct::mis_recursive;
        let r = compare_with_seed(&EX13_CORNELL, &tracer(mis, 5), 500 + seed);
        assert!(r.is_ok(), "seed {seed}: {r:?}");
        let r = compare_with_seed(&EX13_VEACH, &tracer(mis, 2), 600 + seed);
        assert!(r.is_ok(), "seed {seed}: {r:?}");
    }
}

/// `lesson11 render --student` puts beside the student's picture the
/// renderer's integrator with the same estimator: with the reference
/// solutions as the student's code, the two pictures have the same noise
/// (mean variance within ×1.5 either way), where the MIS path tracer would
/// show several times less. 16×16 Cornell box, 64 spp.
#[cfg(feature = "solutions")]
#[test]
fn render_student_puts_the_same_estimator_beside() {
    use exercises::plug::StudentRender;
    use raytracer::integrator::{DirectStrategy, PathTracer};
    use raytracer::render::{RenderOptions, render};
    let mut scene = raytracer::scene::Scene::builtin("cornell").expect("cornell");
    scene.set_resolution(16, 16);
    let options = |seed| RenderOptions {
        spp: 64,
        seed,
        threads: None,
        tile_size: 16,
        progress: false,
        label: String::new(),
    };
    let noise = |i: &dyn raytracer::integrator::Integrator, seed| {
        let r = render(&scene, i, &options(seed));
        raytracer::metrics::mean(&r.film.variance_image()).element_sum() as f64
    };
    let path = StudentRender::Path {
        max_depth: Some(5),
        rr_depth: 3,
    };
    let nee = StudentRender::PathNee {
        max_depth: Some(5),
        rr_depth: 3,
    };
    let mis_student = StudentRender::PathMis {
        max_depth: Some(5),
        rr_depth: 3,
    };
    let bdpt = StudentRender::Bdpt {
        max_depth: Some(4),
        rr_depth: 3,
    };
    for which in [path, StudentRender::Direct, nee, mis_student, bdpt] {
        let (a, b) = (
            noise(which.student().as_ref(), 3),
            noise(which.reference().as_ref(), 4),
        );
        assert!(
            (a / b - 1.0).abs() < 0.5,
            "{which:?}: student {a}, reference {b}"
        );
    }
    let mis = PathTracer {
        max_depth: Some(5),
        rr_depth: 3,
        strategy: DirectStrategy::Mis,
    };
    let (a, b) = (noise(path.student().as_ref(), 3), noise(&mis, 4));
    assert!(
        a > 2.0 * b,
        "BRDF sampling {a} vs MIS {b}: MIS is the unlike reference"
    );
}

/// An estimator whose estimates do not vary (or vary only by f32 rounding)
/// is told its relative error, not a z of millions or "|z| = inf": its
/// difference from the answer is no noise.
#[test]
fn zero_variance_failures_give_a_relative_error_not_a_z() {
    use grading::stats::MeanVar;
    use raytracer::math::Color;
    let constant = |values: &[f32]| {
        let mut m = MeanVar::default();
        for i in 0..1000 {
            m.add(Color::splat(values[i % values.len()]));
        }
        m
    };
    // Exactly constant (standard error 0, |z| would be inf), and constant
    // up to the last bits of an f32 (|z| would be ~10⁸).
    let near = f32::from_bits(0.5f32.to_bits() + 1);
    for (name, stats) in [
        ("constant", constant(&[0.5])),
        ("f32 rounding", constant(&[0.5, near])),
    ] {
        let e = english(|| stats.check("zero variance", Color::splat(0.4), |_| None)).unwrap_err();
        assert!(
            e.contains("your mean is 0.5000, expected 0.4000 (relative error +25.00%")
                && e.contains("your estimates barely vary")
                && e.contains("so this is no noise"),
            "{name}: {e}"
        );
        assert!(
            !e.contains("inf") && !e.contains("standard errors of your own"),
            "{name}: {e}"
        );
    }
    // An exact answer of 0 has no relative error: the error itself.
    let e = english(|| constant(&[0.5]).check("zero variance at 0", Color::ZERO, |_| None))
        .unwrap_err();
    assert!(
        e.contains("(error +0.5000; your estimates barely vary"),
        "{e}"
    );
    // A noisy estimator keeps its |z|.
    let e =
        english(|| constant(&[0.3, 0.7]).check("noisy", Color::splat(0.4), |_| None)).unwrap_err();
    assert!(e.contains("standard errors of your own"), "{e}");
}
