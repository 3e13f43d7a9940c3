//! Grader of exercise 11 (the path tracing loop): furnaces with and without
//! roulette, and a grey sphere under a sky, where the sky is reached with a
//! throughput of ρ (z-tests with the student's own variance; a failing mean
//! is compared with what the usual mistakes converge to), then the Cornell
//! box against the renderer's path tracer, tile by tile.
//!
//! Tolerances: |z| ≤ 5.5 per channel in 5 closed-form cases (false failure
//! < 6e-7), and the image comparison at family-wise α = 1e-4
//! ([`crate::compare`]).

use exercises::plug::StudentPathTracer;
use raytracer::math::Color;

use crate::compare::{EX11_CORNELL, compare};
use crate::ex10_naive_recursive::{
    GREY, LE, RHO, camera_estimates, depth_message, grey_sphere, near, series,
    signed_cosine_message, sky_symptom, small_scene,
};

/// The signature of exercise 11.
pub use exercises::plug::PathRadianceFn as PathFn;

/// Paths per furnace case.
pub const ESTIMATES: u64 = 4000;

pub fn check(f: PathFn) -> Result<(), String> {
    let furnace = small_scene("furnace")?;
    // The grey sphere under a sky, first: it tells apart mistakes that give
    // the same mean in the emitting furnace (L_e without β, and a missing
    // cosine, both D·L_e there). Roulette only after 2 bounces: its paths
    // escape after one.
    let grey = grey_sphere()?;
    let grey_stats = camera_estimates(&grey, 97, ESTIMATES, |ray, s| f(&grey, ray, None, 2, s));
    // A missing cosine gives 2ρ = 1 there with weights ρ/cos θ_i, which vary;
    // the sky added without β gives 1 with no variance at all.
    let no_cosine_on_grey = near(&grey_stats, 2.0 * GREY, 0.1) && grey_stats.std_error()[0] > 1e-3;
    // Depth-limited, no roulette: 1 − 0.5^D.
    for d in [1u32, 3] {
        let stats = camera_estimates(&furnace, 90 + d as u64, ESTIMATES, |ray, s| {
            f(&furnace, ray, Some(d), 1000, s)
        });
        let unweighted = if no_cosine_on_grey {
            crate::tr!("ex11.no_cosine", d)
        } else {
            crate::tr!("ex11.unweighted", d)
        };
        let mut named = vec![
            (series(d, -RHO), signed_cosine_message(d)),
            (series(d, 1.0), unweighted),
            (series(d + 1, RHO), depth_message(d, true)),
        ];
        if d > 1 {
            named.push((series(d - 1, RHO), depth_message(d, false)));
            named.push((LE, crate::tr!("ex11.first_only")));
        }
        let advice = named
            .into_iter()
            .find(|(v, _)| {
                stats.matches(Color::splat(*v as f32)) || (d > 1 && near(&stats, *v, 0.03))
            })
            .map(|(_, why)| why);
        stats.check(
            &crate::tr!("ex11.furnace_depth", d),
            Color::splat(series(d, RHO) as f32),
            |r| {
                advice.clone().or_else(|| {
                    Some(if r > 1.0 {
                        crate::tr!("ex11.brighter", r, d)
                    } else {
                        crate::tr!("ex11.darker", r, d)
                    })
                })
            },
        )?;
    }
    // Unlimited depth, roulette from the first bounce: L_e / (1 − ρ) = 1.
    let stats = camera_estimates(&furnace, 95, ESTIMATES, |ray, s| {
        f(&furnace, ray, None, 1, s)
    });
    stats.check(&crate::tr!("ex11.furnace_roulette"), Color::ONE, |r| {
        Some(if r < 1.0 {
            crate::tr!("ex11.roulette_dark", r)
        } else {
            crate::tr!("ex11.roulette_bright", r)
        })
    })?;
    grey_stats.check(&crate::tr!("ex11.grey"), Color::splat(GREY as f32), |r| {
        // The furnaces passed, so the cosine is there.
        Some(if near(&grey_stats, 1.0, 0.03) {
            crate::tr!("ex11.sky_unweighted")
        } else {
            sky_symptom(r, grey_stats.mean()[0])
        })
    })?;
    let white = small_scene("white-furnace")?;
    let stats = camera_estimates(&white, 96, ESTIMATES, |ray, s| f(&white, ray, None, 2, s));
    stats.check(&crate::tr!("ex11.white"), Color::ONE, |r| {
        Some(sky_symptom(r, stats.mean()[0]))
    })?;
    // The Cornell box against the renderer (same expected value).
    let student = StudentPathTracer {
        path_radiance: f,
        max_depth: Some(5),
        rr_depth: 3,
    };
    compare(&EX11_CORNELL, &student)
}
