//! Grader of exercise 10 (naive recursion): furnace scenes, where the answer
//! is known in closed form, z-tested with the student's own variance; a
//! failing mean is compared with what the usual mistakes converge to.
//!
//! The emitting furnace (`furnace`): the camera inside a closed sphere of
//! albedo ρ = 0.5 emitting L_e = 0.5 inwards, so with depth limit D every
//! pixel is `L_e (1 + ρ + … + ρ^{D−1}) = 1 − 0.5^D`. The white furnace: a
//! white Lambert sphere under a sky of 1, every pixel 1 for D ≥ 2. The grey
//! sphere ([`grey_sphere`]): a Lambert sphere of albedo 0.5 under a sky of 1
//! filling the view, every pixel 0.5 for D ≥ 2, where a cosine of the other
//! sign convention gives −0.5.
//!
//! Tolerance: |z| ≤ 5.5 per channel, 6 cases × 3 channels: a correct
//! solution fails with probability < 7e-7.

use raytracer::integrator::camera_ray;
use raytracer::math::{Color, Ray, UVec2};
use raytracer::sampling::Sampler;
use raytracer::scene::{Scene, SceneOrigin, load_str};

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

/// Albedo of the grey sphere of [`grey_sphere`].
pub const GREY: f64 = 0.5;

/// A grey Lambert sphere (albedo [`GREY`]) under a sky of radiance 1, the
/// camera so close that every camera ray hits the sphere (8×8 pixels). The
/// sphere is convex: every reflected ray escapes to the sky, so with
/// max_depth ≥ 2 every camera ray's radiance is exactly ρ·1 = 0.5 — and the
/// sky is reached with a throughput of ρ, not 1 (the white furnace cannot
/// tell the two apart), and every surface is seen from the front (a cosine
/// with the wrong sign gives −0.5).
pub fn grey_sphere() -> Result<Scene, String> {
    let text = format!(
        "[camera]\nposition = [0, 0, 1.6]\nlook_at = [0, 0, 0]\nup = [0, 1, 0]\nfov = 30\n\n\
         [render]\nwidth = 8\nheight = 8\nspp = 1\nmax_depth = -1\nrr_depth = 5\n\n\
         [materials.grey]\ntype = \"lambert\"\nalbedo = {GREY}\n\n\
         [[shapes]]\nname = \"sphere\"\ntype = \"sphere\"\ncenter = [0, 0, 0]\nradius = 1\nmaterial = \"grey\"\n\n\
         [environment]\nradiance = 1\n"
    );
    let origin = SceneOrigin::Dir {
        name: "grader:grey-sphere".into(),
        dir: Default::default(),
    };
    let parts = load_str(&text, &origin).map_err(|e| format!("grader: {e}"))?;
    Ok(Scene::build("grey-sphere", parts))
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
    crate::tr!(
        "ex10.signed_cosine",
        mean = series(d, -RHO),
        series = alternating_series_text(d)
    )
}

/// The message for a depth off by one.
pub fn depth_message(d: u32, more: bool) -> String {
    crate::tr!("ex10.depth", depth = if more { d + 1 } else { d - 1 })
}

/// The message for a cosine with the sign of the other convention, seen
/// where the BRDF is seen from the front (wo.z > 0): the mean is minus the
/// answer, `exact`.
pub fn other_sign_message(mean: f64) -> String {
    crate::tr!("ex10.other_sign", mean)
}

/// The message for a cosine left out of the weights, in the emitting
/// furnace (ρ = 0.5: every bounce then passes 2ρ = 1 of the light).
pub fn missing_cosine_message(d: u32) -> String {
    crate::tr!("ex10.no_cosine", mean = series(d, 2.0 * RHO), d)
}

/// Whether every channel of the mean lies within `tol` (relative) of
/// `value`: for estimators with heavy tails (a missing cosine gives weights
/// 1/cos θ_i), whose standard error is unreliable.
pub fn near(stats: &MeanVar, value: f64, tol: f64) -> bool {
    stats.mean().iter().all(|m| (m / value - 1.0).abs() < tol)
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
            crate::tr!("ex10.summed", n),
        ),
        // One bounce too few: at D = 1 a stop at `depth + 2 ≥ max_depth`
        // still gives L_e, so the mistake is seen from D = 2 on.
        ((d > 1).then(|| series(d - 1, RHO)), depth_message(d, false)),
        (Some(LE), crate::tr!("ex10.first_only")),
        (Some(series(d, 2.0 * RHO)), missing_cosine_message(d)),
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
            .filter(|(_, (v, _))| {
                v.is_some_and(|v| stats.matches(Color::splat(v as f32)) || near(stats, v, 0.03))
            })
            .collect();
        // The mistake that fits every case, else the first that fits this one.
        let advice = here
            .iter()
            .find(|(i, _)| explains(*i))
            .or(here.first())
            .map(|(_, (_, why))| why.clone());
        stats.check(
            &crate::tr!("ex10.furnace", d, n),
            Color::splat(exact as f32),
            |r| {
                advice.clone().or_else(|| {
                    Some(if d == 1 {
                        crate::tr!("ex10.depth_one", r)
                    } else if r > 1.0 {
                        crate::tr!("ex10.brighter", r, d)
                    } else {
                        crate::tr!("ex10.darker", r, d)
                    })
                })
            },
        )?;
    }
    let grey = grey_sphere()?;
    let stats = camera_estimates(&grey, 89, ESTIMATES, |ray, s| f(&grey, &ray, 0, 3, 2, s));
    stats.check(&crate::tr!("ex10.grey"), Color::splat(GREY as f32), |r| {
        Some(sky_symptom(r, stats.mean()[0]))
    })?;
    let white = small_scene("white-furnace")?;
    let stats = camera_estimates(&white, 88, ESTIMATES, |ray, s| f(&white, &ray, 0, 3, 2, s));
    stats.check(&crate::tr!("ex10.white"), Color::ONE, |r| {
        Some(sky_symptom(r, stats.mean()[0]))
    })
}

/// What a wrong mean under a sky of 1 shows (`r`: the mean over the exact
/// answer).
pub fn sky_symptom(r: f64, mean: f64) -> String {
    if (r + 1.0).abs() < 0.03 {
        other_sign_message(mean)
    } else if r.abs() < 0.03 {
        crate::tr!("ex10.no_sky")
    } else if r > 1.0 {
        crate::tr!("ex10.sky_bright", r)
    } else {
        crate::tr!("ex10.sky_dark", r)
    }
}
