//! Grader of exercise 10 (naive recursion): furnace scenes, where the answer
//! is known in closed form, z-tested with the student's own variance; a
//! failing mean is compared with what the usual mistakes converge to.
//!
//! The emitting furnace (`furnace`): the camera inside a closed sphere of
//! albedo ρ = 0.5 emitting L_e = 0.5 inwards, so with depth limit D every
//! pixel is `L_e (1 + ρ + … + ρ^{D−1}) = 1 − 0.5^D`. The white furnace: a
//! white Lambert sphere under a sky of 1, every pixel 1 for D ≥ 2.
//!
//! Tolerance: |z| ≤ 5.5 per channel, 5 cases × 3 channels: a correct
//! solution fails with probability < 6e-7.

use raytracer::integrator::camera_ray;
use raytracer::math::{Color, Ray, UVec2};
use raytracer::sampling::Sampler;
use raytracer::scene::Scene;

use crate::stats::MeanVar;

/// The signature of exercise 10.
pub type NaiveFn = fn(&Scene, &Ray, u32, u32, u32, &mut Sampler) -> Color;

/// Camera rays per case.
pub const ESTIMATES: u64 = 1500;

/// Emission and albedo of the emitting furnace.
pub const LE: f64 = 0.5;
pub const RHO: f64 = 0.5;

/// A small built-in scene (8×8 pixels: the camera rays cover the image).
pub fn small_scene(name: &str) -> Result<Scene, String> {
    let mut s = Scene::builtin(name).map_err(|e| format!("grader: {e}"))?;
    s.set_resolution(8, 8);
    Ok(s)
}

/// Mean and variance of `estimate` over camera rays through all pixels.
pub fn camera_estimates(
    scene: &Scene,
    seed: u64,
    n: u64,
    mut estimate: impl FnMut(Ray, &mut Sampler) -> Color,
) -> MeanVar {
    let mut stats = MeanVar::default();
    let (w, h) = (scene.camera.width as u64, scene.camera.height as u64);
    for i in 0..n {
        let pixel = UVec2::new((i % w) as u32, ((i / w) % h) as u32);
        let mut sampler = Sampler::new(seed, i, 0);
        let ray = camera_ray(scene, pixel, &mut sampler);
        stats.add(estimate(ray, &mut sampler));
    }
    stats
}

/// `L_e Σ_{k<d} r^k`: the furnace's answer when every bounce multiplies by `r`.
pub fn series(d: u32, r: f64) -> f64 {
    (0..d).map(|k| LE * r.powi(k as i32)).sum()
}

/// `0.5 − 0.25 + 0.125 …`, the first `d` terms of the furnace's series with
/// the sign alternating, written out.
pub fn alternating_series_text(d: u32) -> String {
    let mut s = String::new();
    for k in 0..d {
        let term = LE * RHO.powi(k as i32);
        if k > 0 {
            s.push_str(if k % 2 == 1 { " − " } else { " + " });
        }
        s.push_str(&format!("{term}"));
    }
    s
}

/// The message for a furnace whose mean is the alternating series.
pub fn signed_cosine_message(d: u32) -> String {
    format!(
        "your mean is {:.4} = {}: the sign alternates with every bounce — a signed cos θ_i. Inside the furnace you see the wall from its back side (wo.z < 0), so the sampled wi.z < 0 too: cos θ_i is taken with the normal on the side of ω_o, |wi.z|",
        series(d, -RHO),
        alternating_series_text(d)
    )
}

/// The message for a depth off by one.
pub fn depth_message(d: u32, more: bool) -> String {
    format!(
        "your mean is that of max_depth {}: max_depth D counts the segments of a path — D = 1 shows only the emitters seen directly, D = 2 direct light, at most D − 1 bounces (stop when depth + 1 ≥ max_depth)",
        if more { d + 1 } else { d - 1 }
    )
}

/// The usual mistakes, as what each converges to in the emitting furnace at
/// max depth `d` with branching `n` (`None`: the mistake does not change the
/// answer there), with the message that names it.
fn mistakes(d: u32, n: u32) -> Vec<(Option<f64>, String)> {
    vec![
        (Some(series(d, -RHO)), signed_cosine_message(d)),
        (Some(series(d + 1, RHO)), depth_message(d, true)),
        (
            Some(series(d, n as f64 * RHO)),
            format!(
                "your mean is L_e(1 + Nρ + (Nρ)² + …): the N = {n} branches are summed — divide their sum by N"
            ),
        ),
        // One bounce too few: at D = 1 a stop at `depth + 2 ≥ max_depth`
        // still gives L_e, so the mistake is seen from D = 2 on.
        ((d > 1).then(|| series(d - 1, RHO)), depth_message(d, false)),
        (
            Some(LE),
            "your mean is L_e alone: only the camera ray's hit adds its emission — every level of the recursion adds the L_e of its own hit".to_string(),
        ),
    ]
}

/// The furnace cases: (max depth D, branching N).
const CASES: [(u32, u32); 4] = [(1, 3), (2, 3), (3, 3), (4, 2)];

pub fn check(f: NaiveFn) -> Result<(), String> {
    let furnace = small_scene("furnace")?;
    // Every case first: at D = 2 one bounce too few and emission only at the
    // camera's hit both give L_e = 0.5, and only D = 3 (0.75 against 0.5)
    // tells them apart. A mistake is named only if the means of all cases
    // agree with it (where it predicts one).
    let all: Vec<_> = CASES
        .iter()
        .map(|&(d, n)| {
            camera_estimates(&furnace, 80 + d as u64, ESTIMATES, |ray, s| {
                f(&furnace, &ray, 0, d, n, s)
            })
        })
        .collect();
    let explains = |mistake: usize| {
        CASES.iter().zip(&all).all(|(&(d, n), stats)| {
            mistakes(d, n)[mistake]
                .0
                .is_none_or(|v| stats.matches(Color::splat(v as f32)))
        })
    };
    for (&(d, n), stats) in CASES.iter().zip(&all) {
        let exact = series(d, RHO);
        let here: Vec<_> = mistakes(d, n)
            .into_iter()
            .enumerate()
            .filter(|(_, (v, _))| v.is_some_and(|v| stats.matches(Color::splat(v as f32))))
            .collect();
        // The mistake that fits every case, else the first that fits this one.
        let advice = here
            .iter()
            .find(|(i, _)| explains(*i))
            .or(here.first())
            .map(|(_, (_, why))| why.clone());
        stats.check(
            &format!("emitting furnace (L_e = 0.5, ρ = 0.5), max_depth {d}, branching {n}: L = L_e(1 + ρ + … + ρ^(D−1))"),
            Color::splat(exact as f32),
            |r| {
                advice.clone().or_else(|| {
                    Some(if d == 1 {
                        "with max_depth = 1 only the emitters seen directly count: L = L_e".to_string()
                    } else if r > 1.0 {
                        "too bright: is the sum of the branches divided by N? are the weights f·|cos θ_i|/pdf_w?".to_string()
                    } else {
                        "too dark: does every level add its emission, and does the recursion go deep enough (stop when depth + 1 >= max_depth)?".to_string()
                    })
                })
            },
        )?;
    }
    let white = small_scene("white-furnace")?;
    let stats = camera_estimates(&white, 88, ESTIMATES, |ray, s| f(&white, &ray, 0, 3, 2, s));
    stats.check(
        "white furnace (white Lambert sphere under a sky of 1), max_depth 3, branching 2",
        Color::ONE,
        |_| Some("rays that escape must return scene.escaped_radiance(ray.d)".to_string()),
    )
}
