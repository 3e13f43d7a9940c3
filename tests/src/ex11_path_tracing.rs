//! Grader of exercise 11 (the path tracing loop): furnaces with and without
//! roulette (z-tests with the student's own variance; a failing mean is
//! compared with what the usual mistakes converge to), then the Cornell box
//! against the renderer's path tracer, tile by tile.
//!
//! Tolerances: |z| ≤ 5.5 per channel in 4 furnace cases (false failure
//! < 5e-7), and the image comparison at family-wise α = 1e-4
//! ([`crate::compare`]).

use exercises::plug::StudentPathTracer;
use raytracer::math::Color;

use crate::compare::{EX11_CORNELL, compare};
use crate::ex10_naive_recursive::{
    LE, RHO, camera_estimates, depth_message, series, signed_cosine_message, small_scene,
};

/// The signature of exercise 11.
pub use exercises::plug::PathRadianceFn as PathFn;

/// Paths per furnace case.
pub const ESTIMATES: u64 = 4000;

pub fn check(f: PathFn) -> Result<(), String> {
    let furnace = small_scene("furnace")?;
    // Depth-limited, no roulette: 1 − 0.5^D.
    for d in [1u32, 3] {
        let stats = camera_estimates(&furnace, 90 + d as u64, ESTIMATES, |ray, s| {
            f(&furnace, ray, Some(d), 1000, s)
        });
        let mut named = vec![
            (series(d, -RHO), signed_cosine_message(d)),
            (
                series(d, 1.0),
                format!(
                    "your mean is {d}·L_e: every hit adds L_e unweighted — add β·L_e (L += β·L_e), the emission seen after k bounces reaches the camera through their k BRDF weights"
                ),
            ),
            (series(d + 1, RHO), depth_message(d, true)),
        ];
        if d > 1 {
            named.push((series(d - 1, RHO), depth_message(d, false)));
            named.push((
                LE,
                "your mean is L_e alone: add β·L_e at EVERY hit of the path, not only the first"
                    .to_string(),
            ));
        }
        let advice = named
            .into_iter()
            .find(|(v, _)| stats.matches(Color::splat(*v as f32)))
            .map(|(_, why)| why);
        stats.check(
            &format!("emitting furnace (L_e = 0.5, ρ = 0.5), max_depth {d}, no roulette: L = L_e(1 + … + ρ^(D−1))"),
            Color::splat(series(d, RHO) as f32),
            |r| {
                advice.clone().or_else(|| Some(if r > 1.0 {
                    "too bright: is β multiplied by f·|cos θ_i|/pdf_w (not added)? does the path stop after max_depth − 1 bounces?"
                } else {
                    "too dark: add β·L_e at every hit, and make max_depth − 1 bounces"
                }
                .to_string()))
            },
        )?;
    }
    // Unlimited depth, roulette from the first bounce: L_e / (1 − ρ) = 1.
    let stats = camera_estimates(&furnace, 95, ESTIMATES, |ray, s| {
        f(&furnace, ray, None, 1, s)
    });
    stats.check(
        "emitting furnace, unlimited depth, Russian roulette after 1 bounce: L = L_e/(1 − ρ)",
        Color::ONE,
        |r| {
            Some(if r < 1.0 {
                "too dark: did you divide β by the survival probability q after roulette? (E[L′] = q · L/q = L)"
            } else {
                "too bright: continue with probability q and divide by q, not the other way round"
            }
            .to_string())
        },
    )?;
    let white = small_scene("white-furnace")?;
    let stats = camera_estimates(&white, 96, ESTIMATES, |ray, s| f(&white, ray, None, 2, s));
    stats.check(
        "white furnace (white Lambert under a sky of 1), roulette after 2 bounces",
        Color::ONE,
        |_| Some("a path that escapes adds β · scene.escaped_radiance(ray.d)".to_string()),
    )?;
    // The Cornell box against the renderer (same expected value).
    let student = StudentPathTracer {
        path_radiance: f,
        max_depth: Some(5),
        rr_depth: 3,
    };
    compare(&EX11_CORNELL, &student)
}
