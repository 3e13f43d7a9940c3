//! The grader tested: correct but different solutions pass, typical wrong
//! ones fail with a reason that names the mistake (each wrong fixture is a
//! correct solution with one change), the pictures of a failure are written
//! readable, and (with the feature `solutions`) the reference solutions pass.
//!
//! Named so that it runs before `exercises`: in `cargo test -p grading` the
//! progress table comes last.

mod fixtures;

use fixtures::{correct, wrong};
use grading::*;

fn passes(name: &str, r: Result<(), String>) {
    if let Err(e) = r {
        panic!("{name}: a correct solution failed: {e}");
    }
}

/// Fails, and the reason mentions `keyword` (case-insensitive).
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

#[test]
fn ex01_stereo_eyes() {
    passes(
        "recomputed rightDir",
        ex01_stereo_eyes::check(correct::stereo_eyes),
    );
    fails(
        "swapped eyes",
        ex01_stereo_eyes::check(wrong::eyes_swapped),
        "swapped",
    );
    fails(
        "full separation each side",
        ex01_stereo_eyes::check(wrong::eyes_too_far),
        "apart",
    );
}

#[test]
fn ex02_anaglyph() {
    passes(
        "channel by channel",
        ex02_anaglyph::check(correct::anaglyph),
    );
    fails(
        "swapped channels",
        ex02_anaglyph::check(wrong::anaglyph_swapped),
        "swapped",
    );
    fails(
        "no desaturation",
        ex02_anaglyph::check(wrong::anaglyph_saturated),
        "desaturated",
    );
}

#[test]
fn ex03_lambert() {
    passes("min of cosines", ex03_lambert::check(correct::lambert_eval));
    fails(
        "missing 1/π",
        ex03_lambert::check(wrong::lambert_no_inv_pi),
        "forget 1/π",
    );
    fails(
        "cosine in the BRDF",
        ex03_lambert::check(wrong::lambert_with_cos),
        "cosine belongs",
    );
}

#[test]
fn ex04_phong() {
    let (s, f) = (correct::phong_normalization, correct::phong_eval);
    passes("1/integral, mirrored wi", ex04_phong::check(s, f));
    // Issue 12, item 2: with (n+1)/(2π) energy is LOST, not created.
    fails(
        "(n+1)/2π",
        ex04_phong::check(wrong::phong_s_without_cosine, f),
        "(n+1)/(n+2)·ρ_s < ρ_s — energy is lost",
    );
    fails(
        "unnormalized",
        ex04_phong::check(wrong::phong_unnormalized, f),
        "unnormalized",
    );
    fails(
        "no clamp",
        ex04_phong::check(s, wrong::phong_eval_unclamped),
        "max(0, cos α)",
    );
    fails(
        "cos α from the normal",
        ex04_phong::check(s, wrong::phong_eval_from_normal),
        "angle from the normal",
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
    fails(
        "one over the solid angle",
        ex05_cone_lobe::check(wrong::cone_solid_angle),
        "energy is lost",
    );
    fails(
        "small-angle approximation",
        ex05_cone_lobe::check(wrong::cone_small_angle),
        "sin θ_m ≈ θ_m",
    );
    fails(
        "Lambert's constant",
        ex05_cone_lobe::check(wrong::cone_lambert),
        "Lambert's constant",
    );
}

#[test]
fn ex06_mirror() {
    passes(
        "tangential reflect, lobe pdf 1/2",
        ex06_mirror::check(correct::reflect, correct::mirror_sample),
    );
    fails(
        "f = R",
        ex06_mirror::check(correct::reflect, wrong::mirror_f_is_r),
        "R/|cos θ_i|",
    );
    fails(
        "reflect inwards",
        ex06_mirror::check(wrong::reflect_inwards, correct::mirror_sample),
        "into the surface",
    );
    fails(
        "a sample at wo.z = 0",
        ex06_mirror::check(correct::reflect, wrong::mirror_at_grazing),
        "wo.z ≤ 0 return None",
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
    fails(
        "uniform directions",
        ex07_cosine_sampling::check(wrong::cosine_but_uniform, correct::cosine_pdf),
        "UNIFORM directions",
    );
    fails(
        "r = u",
        ex07_cosine_sampling::check(wrong::cosine_no_sqrt, correct::cosine_pdf),
        "r = √u",
    );
    let _ = std::fs::remove_file(ex07_cosine_sampling::histogram_path());
    fails(
        "φ = π·u",
        ex07_cosine_sampling::check(wrong::cosine_half_phi, correct::cosine_pdf),
        "is φ = 2π·u?",
    );
    // The histograms of the student's directions, beside the other pictures.
    let size = pictures::png_size(&ex07_cosine_sampling::histogram_path());
    assert_eq!(size.ok(), Some((512, 384)));
    fails(
        "uniform pdf",
        ex07_cosine_sampling::check(correct::cosine_concentric, wrong::pdf_uniform),
        "uniform",
    );
}

#[test]
fn ex08_phong_lobe_pdf() {
    passes(
        "exp and ln",
        ex08_phong_lobe_pdf::check(correct::phong_pdf_exp),
    );
    passes("f64", ex08_phong_lobe_pdf::check(correct::phong_pdf_f64));
    fails(
        "S(n) for the density",
        ex08_phong_lobe_pdf::check(wrong::phong_pdf_is_s),
        "S(n), the BRDF's normalization",
    );
    fails(
        "density of cos α alone",
        ex08_phong_lobe_pdf::check(wrong::phong_pdf_no_2pi),
        "divide by 2π",
    );
    fails(
        "per dα dφ",
        ex08_phong_lobe_pdf::check(wrong::phong_pdf_per_dalpha),
        "divide by sin α",
    );
    fails(
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
    fails(
        "missing cosine",
        ex09_albedo::check(wrong::albedo_no_cos),
        "cosine",
    );
    fails(
        "missing pdf",
        ex09_albedo::check(wrong::albedo_no_pdf),
        "pdf",
    );
    fails(
        "N − 1",
        ex09_albedo::check(wrong::albedo_n_minus_1),
        "divided by N − 1",
    );
    fails(
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
    fails(
        "branches summed",
        ex10_naive_recursive::check(wrong::naive_not_averaged),
        "divide their sum by N",
    );
    fails(
        "missing cosine",
        ex10_naive_recursive::check(wrong::naive_no_cos),
        "furnace",
    );
    fails(
        "signed cosine",
        ex10_naive_recursive::check(wrong::naive_signed_cos),
        "= 0.5 − 0.25: the sign alternates",
    );
    fails(
        "one bounce too many",
        ex10_naive_recursive::check(wrong::naive_one_bounce_more),
        "max_depth D counts the segments",
    );
    // Both give 0.5 at max_depth 2; max_depth 3 (0.75 against 0.5) tells
    // which mistake it is.
    fails(
        "one bounce too few",
        ex10_naive_recursive::check(wrong::naive_one_bounce_fewer),
        "your mean is that of max_depth 1",
    );
    let e = ex10_naive_recursive::check(wrong::naive_emission_only_at_camera).unwrap_err();
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
    fails(
        "roulette without 1/q",
        ex11_path_tracing::check(wrong::path_rr_no_division),
        "survival probability",
    );
    fails(
        "emission at the first hit only",
        ex11_path_tracing::check(wrong::path_first_emission_only),
        "every hit",
    );
    // The case: 0.375 = 0.5 − 0.25 + 0.125 at max_depth 3.
    fails(
        "signed cosine",
        ex11_path_tracing::check(wrong::path_signed_cos),
        "0.3750 = 0.5 − 0.25 + 0.125: the sign alternates",
    );
    fails(
        "L_e without β",
        ex11_path_tracing::check(wrong::path_le_without_beta),
        "L += β·L_e",
    );
}

#[test]
fn ex12_nee() {
    let (pdf, direct) = (correct::area_pdf_to_solid_angle, correct::estimate_direct);
    passes("geometry term", ex12_nee::check(pdf, direct));
    passes(
        "through Light::sample_li",
        ex12_nee::check(pdf, correct::estimate_direct_sample_li),
    );
    fails(
        "pdf not converted",
        ex12_nee::check(wrong::area_pdf_unchanged, direct),
        "per unit AREA",
    );
    fails(
        "edge-on light",
        ex12_nee::check(wrong::area_pdf_edge_on_infinite, direct),
        "edge-on",
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
            "test visibility with a shadow ray",
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
        (
            "no light-choice pmf",
            wrong::direct_no_pmf,
            "divide by the probability of choosing the light",
        ),
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
    ] {
        fails(name, ex12_nee::check(pdf, f), keyword);
    }
}

#[test]
fn ex13_mis() {
    passes("power as a ratio", ex13_mis::check(correct::power_ratio));
    fails(
        "balance heuristic",
        ex13_mis::check(wrong::mis_balance),
        "balance heuristic (exponent 1): a valid MIS weight, but this exercise asks for the power heuristic",
    );
    fails(
        "not normalized",
        ex13_mis::check(wrong::mis_not_normalized),
        "not normalized",
    );
    fails("swapped", ex13_mis::check(wrong::mis_swapped), "swapped");
    fails(
        "0/0",
        ex13_mis::check(wrong::mis_nan_when_both_zero),
        "mis_weight(0, 0)",
    );
}

#[test]
fn ex14_light_tracing() {
    passes(
        "importance × geometry term",
        ex14_light_tracing::check(correct::splat_by_geometry),
    );
    fails(
        "no importance",
        ex14_light_tracing::check(wrong::splat_no_importance),
        "importance",
    );
    fails(
        "no cosine",
        ex14_light_tracing::check(wrong::splat_no_cos),
        "|cos θ_p| at the vertex",
    );
    fails(
        "signed cosine at a vertex facing away",
        ex14_light_tracing::check(wrong::splat_signed_cos),
        "a signed cos θ_p",
    );
    fails(
        "f_r(−wi)",
        ex14_light_tracing::check(wrong::splat_f_of_minus_wi),
        "f_r(−wi)",
    );
    fails(
        "a splat where the camera sees nothing",
        ex14_light_tracing::check(wrong::splat_zero_when_unseen),
        "returns None and so must you",
    );
}

#[test]
fn ex15_bdpt_connection() {
    let (g, w) = (correct::geometry_term, correct::power_many_f64);
    passes(
        "|d·n| products over r⁴, f64 weights",
        ex15_bdpt_connection::check(g, w),
    );
    fails(
        "signed cosines",
        ex15_bdpt_connection::check(wrong::g_signed, w),
        "absolute",
    );
    fails(
        "distance not squared",
        ex15_bdpt_connection::check(wrong::g_not_squared, w),
        "SQUARED",
    );
    fails(
        "one cosine",
        ex15_bdpt_connection::check(wrong::g_one_cosine, w),
        "the cosine at y is missing",
    );
    fails(
        "balance heuristic",
        ex15_bdpt_connection::check(g, wrong::balance_many),
        "balance heuristic",
    );
    fails(
        "weights by the max",
        ex15_bdpt_connection::check(g, wrong::weights_by_max),
        "sum of the squares",
    );
}

#[test]
fn ex17_photon_density() {
    passes(
        "full sort, f64 kernel",
        ex17_photon_density::check(correct::photon_radiance_sorted),
    );
    fails(
        "box kernel",
        ex17_photon_density::check(wrong::density_box),
        "box kernel",
    );
    fails(
        "kernel normalized by 1/(π r²)",
        ex17_photon_density::check(wrong::density_half),
        "not normalized",
    );
    fails(
        "every photon",
        ex17_photon_density::check(wrong::density_all),
        "only the k nearest",
    );
    fails(
        "π (r²)²",
        ex17_photon_density::check(wrong::density_area_of_r4),
        "SQUARED distances",
    );
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
    fails(
        "signed G",
        check(generate::<A, NONE>, gather::<A, SIGNED>),
        "signed cosines",
    );
    fails(
        "the VPL's cosine with its incoming direction",
        check(generate::<A, NONE>, gather::<A, INCOMING>),
        "cosine at the wrong end",
    );
    fails(
        "r for r²",
        check(generate::<A, NONE>, gather::<A, R>),
        "r for r²",
    );
    fails(
        "clamp on the contribution",
        check(generate::<A, NONE>, gather::<A, CLAMP_LIGHT>),
        "applied to the contribution",
    );
    fails(
        "clamp where none is asked",
        check(generate::<A, NONE>, gather::<A, CLAMP_ALWAYS>),
        "where none is asked",
    );
    fails(
        "no shadow ray",
        check(generate::<A, NONE>, gather::<A, NO_SHADOW>),
        "shadow ray",
    );
    fails(
        "flux not divided by N",
        check(generate::<A, NOT_SHARED>, gather::<A, NONE>),
        "1/N of its path's flux",
    );
    fails(
        "no VPL on the light",
        check(generate::<A, NO_LIGHT_VPL>, gather::<A, NONE>),
        "direct light is missing",
    );
    fails(
        "VPLs on mirrors",
        check(generate::<A, SPECULAR_VPL>, gather::<A, NONE>),
        "specular hits",
    );
    fails(
        "roulette without division",
        check(generate::<A, ROULETTE_NO_DIV>, gather::<A, NONE>),
        "roulette without division",
    );
}

#[test]
fn ex16_metropolis_step() {
    use ex16_metropolis_step::{check, check_chain};
    let (a, w) = (correct::acceptance_by_branch, correct::splat_in_f64);
    passes("branch, weights as 1/f − a/f in f64", check(a, w));
    fails(
        "upside down",
        check(wrong::acceptance_upside_down, w),
        "upside down",
    );
    fails(
        "unclamped",
        check(wrong::acceptance_unclamped, w),
        "min(1, f(y)/f(x))",
    );
    fails("Barker", check(wrong::acceptance_barker, w), "Barker");
    fails(
        "stuck at f(x) = 0",
        check(wrong::acceptance_stuck_at_zero, w),
        "must leave it",
    );
    fails(
        "weights not over f",
        check(a, wrong::splat_not_over_f),
        "not divided by f",
    );
    fails("swapped weights", check(a, wrong::splat_swapped), "swapped");
    fails(
        "proposal only",
        check(a, wrong::splat_proposal_only),
        "only the proposal",
    );
    fails("NaN at f = 0", check(a, wrong::splat_nan_at_zero), "finite");
    // The chain alone can fail: weights not over f make every pixel's
    // estimate follow f² instead of f.
    fails(
        "chain with weights not over f",
        check_chain(a, wrong::splat_not_over_f),
        "biased",
    );
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
    t.push_str("stereo eyes (left, right)\n");
    for (c, s) in ex01_stereo_eyes::cameras() {
        let (l, r) = ex01_stereo_eyes::expected(&c, s);
        t.push_str(&format!("  s = {s}: {l:.4} {r:.4}\n"));
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
    assert_eq!(cases.len(), 5);
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
    let wrong = exercises::plug::StudentDirect(wrong::direct_area_measure);
    let e = compare_into(&EX12_CORNELL_DIRECT, &wrong, 5, &dir).unwrap_err();
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

#[cfg(feature = "solutions")]
#[test]
fn reference_solutions_pass() {
    for (name, check) in GRADERS {
        let o = grade(check);
        assert!(o.is_passed(), "{name}: {o}");
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
    let direct = exercises::plug::StudentDirect(correct::estimate_direct);
    for seed in 0..12u64 {
        let r = compare_with_seed(&EX11_CORNELL, &variant, 100 + seed);
        assert!(r.is_ok(), "seed {seed}: {r:?}");
        let r = compare_with_seed(&EX12_CORNELL_DIRECT, &direct, 300 + seed);
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
    for which in [path, StudentRender::Direct] {
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
        let e = stats
            .check("zero variance", Color::splat(0.4), |_| None)
            .unwrap_err();
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
    let e = constant(&[0.5])
        .check("zero variance at 0", Color::ZERO, |_| None)
        .unwrap_err();
    assert!(
        e.contains("(error +0.5000; your estimates barely vary"),
        "{e}"
    );
    // A noisy estimator keeps its |z|.
    let e = constant(&[0.3, 0.7])
        .check("noisy", Color::splat(0.4), |_| None)
        .unwrap_err();
    assert!(e.contains("standard errors of your own"), "{e}");
}
