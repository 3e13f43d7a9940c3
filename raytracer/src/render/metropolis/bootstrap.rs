//! The bootstrap of Metropolis light transport: independent paths that
//! estimate the normalization `b` and give the chains their first states.
//!
//! Lecture topic: Metropolis light transport. A chain visits paths in
//! proportion to `f`, so it knows *where* the light is but not *how much* of
//! it there is: its image must be scaled by `b = ∫ f(u) du`, the mean of `f`
//! over primary sample space. The bootstrap draws `n` independent paths (the
//! integrator on fresh numbers, exactly as a large step would) and takes
//! `b̂ = (1/n) Σ f(u_i)`, with the standard error `s / √n` from their spread.
//!
//! The same paths start the chains: each chain picks path `i` with
//! probability `f(u_i) / Σ f` (Veach's resampling, pbrt's
//! `bootstrapWeights`), so no chain has to wander in from a dark corner
//! (start-up bias), and the pair (first state, `b̂`) is *properly weighted*:
//! `E[b̂ · φ(x_0)] = ∫ f φ du` for every `φ` (see [`super`]).

use super::chain::{PathSample, evaluate};
use crate::film::Splat;
use crate::integrator::{Integrator, stop};
use crate::sampling::{Distribution1D, PrimarySample, Sampler};
use crate::scene::Scene;
use rayon::prelude::*;
use std::sync::atomic::{AtomicBool, Ordering};

/// The bootstrap's result.
#[derive(Clone, Debug)]
pub struct Bootstrap {
    /// `b̂`, the mean of `f` over the bootstrap paths.
    pub b: f64,
    /// The estimated variance of `b̂`, `s² / n`.
    pub b_variance: f64,
    /// The number of paths `n`.
    pub paths: u64,
    /// Contributions dropped as NaN, infinite or negative.
    pub nonfinite: u64,
    /// Chooses a path in proportion to its `f`.
    choice: Distribution1D,
}

impl Bootstrap {
    /// The relative standard error of `b̂` (0 if `b̂` is 0).
    pub fn relative_error(&self) -> f64 {
        if self.b > 0.0 {
            self.b_variance.sqrt() / self.b
        } else {
            0.0
        }
    }

    /// The path a chain starts from, chosen by `u` with probability
    /// `f(u_i) / Σ f` (uniformly if every `f` is 0).
    pub fn choose(&self, u: f32) -> u64 {
        self.choice.sample_discrete(u).0 as u64
    }
}

/// Evaluates bootstrap paths `0..paths`, path `i` on the point
/// `PrimarySample::new(seed, i, 0, _)` (the numbers of
/// `Sampler::new(seed, i, 0)`, read in streams), in parallel in the current rayon pool, and
/// adds them up in index order (the same `b̂` on any number of threads).
/// `None` if `stop` was set before all were evaluated; `tick` is called
/// every so many paths with their count.
pub fn bootstrap(
    scene: &Scene,
    integrator: &dyn Integrator,
    seed: u64,
    paths: u64,
    stop_flag: &AtomicBool,
    tick: &(dyn Fn(u64) + Sync),
) -> Option<Bootstrap> {
    const CHUNK: u64 = 256;
    let chunks: Vec<Option<(Vec<f32>, u64)>> = (0..paths.div_ceil(CHUNK))
        .into_par_iter()
        .map_init(
            || (PathSample::default(), Vec::<Splat>::new()),
            |(path, splats), chunk| {
                let range = chunk * CHUNK..((chunk + 1) * CHUNK).min(paths);
                let n = range.end - range.start;
                path.nonfinite = 0;
                let mut f = Vec::with_capacity(n as usize);
                let done = stop::watch(stop_flag, || {
                    for i in range {
                        if stop_flag.load(Ordering::Relaxed) {
                            return false;
                        }
                        // The very point a chain starting here begins at,
                        // read in the same streams.
                        let mut sampler = Sampler::primary(PrimarySample::new(seed, i, 0, 0.0));
                        if !evaluate(scene, integrator, &mut sampler, splats, path) {
                            return false;
                        }
                        f.push(path.f);
                    }
                    true
                });
                tick(n);
                done.then_some((f, path.nonfinite))
            },
        )
        .collect();
    let mut f = Vec::with_capacity(paths as usize);
    let mut nonfinite = 0;
    for chunk in chunks {
        let (values, bad) = chunk?;
        f.extend(values);
        nonfinite += bad;
    }
    let n = f.len().max(1) as f64;
    let (mut sum, mut sum_sq) = (0.0f64, 0.0f64);
    for &v in &f {
        sum += v as f64;
        sum_sq += v as f64 * v as f64;
    }
    let b = sum / n;
    let sample_variance = if n > 1.0 {
        ((sum_sq - sum * sum / n) / (n - 1.0)).max(0.0)
    } else {
        0.0
    };
    Some(Bootstrap {
        b,
        b_variance: sample_variance / n,
        paths,
        nonfinite,
        choice: Distribution1D::new(if f.is_empty() { &[0.0] } else { &f }),
    })
}
