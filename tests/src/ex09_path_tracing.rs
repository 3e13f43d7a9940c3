//! Grader of exercise 9 (the path tracing loop): furnaces with and without
//! roulette (z-tests with the student's own variance), then the Cornell box
//! against the renderer's BRDF-sampling path tracer, tile by tile.

use exercises::plug::StudentPathTracer;
use raytracer::math::Color;

use crate::compare::{EX09_CORNELL, compare};
use crate::ex08_naive_recursive::{camera_estimates, small_scene};

/// The signature of exercise 9.
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
        stats.check(
            &format!("emitting furnace (L_e = 0.5, ρ = 0.5), max_depth {d}, no roulette: L = L_e(1 + … + ρ^(D−1))"),
            Color::splat(1.0 - 0.5f32.powi(d as i32)),
            |r| {
                Some(if r > 1.0 {
                    "too bright: is β multiplied by f·|cos θ_i|/pdf_w (not added)? does the path stop after max_depth − 1 bounces?"
                } else {
                    "too dark: add β·L_e at EVERY hit, and make max_depth − 1 bounces"
                }
                .to_string())
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
                "too dark: did you divide β by the survival probability q after roulette?"
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
    // The Cornell box against the renderer (BRDF sampling only, as the exercise).
    let student = StudentPathTracer {
        path_radiance: f,
        max_depth: Some(5),
        rr_depth: 3,
    };
    compare(&EX09_CORNELL, &student)
}
