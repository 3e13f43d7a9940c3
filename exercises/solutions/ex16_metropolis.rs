//! Reference solution of exercise 16 (see `src/ex16_metropolis.rs` for the task).
//!
//! The chain of Kelemen et al. (2002) in primary sample space, with
//! Veach's expected-value splats. Its image estimates, for every pixel j,
//! `∫ g_j(u) du` over `[0, 1)^D`: a chain in equilibrium visits `u` with
//! density `f(u) / b`, `b = ∫ f`, so `∫ g_j = b · E_{f/b}[g_j / f]`, and every
//! step adds its share `b / N` of that expectation.

use raytracer::render::metropolis::chain::PathSample;
use raytracer::sampling::{Distribution1D, Sampler};

use crate::plug::{ChainImage, ChainSettings};

/// `D` fresh uniform numbers: a large step, or a bootstrap path.
fn fresh(dimensions: usize, rng: &mut Sampler) -> Vec<f32> {
    (0..dimensions).map(|_| rng.next_1d()).collect()
}

/// `x` wrapped around the unit interval, into `[0, 1)` (a torus: moving by
/// `+δ` from `x` lands where moving by `−δ` from there comes back, so the
/// small step is symmetric).
fn wrap(x: f32) -> f32 {
    let w = x - x.floor();
    // A tiny negative x: 1 − tiny rounds to 1, which is 0 on the torus.
    if w < 1.0 { w } else { 0.0 }
}

/// One Metropolis chain: the bootstrap, then `settings.mutations` steps,
/// splatted into `image`.
pub fn metropolis_chain(
    path: &dyn Fn(&[f32]) -> PathSample,
    settings: &ChainSettings,
    rng: &mut Sampler,
    image: &mut ChainImage,
) {
    let d = settings.dimensions;
    // The bootstrap: n independent paths. Their mean f estimates
    // b = ∫ f(u) du (the zeros count: they are part of the integral).
    let n = settings.bootstrap;
    let mut candidates = Vec::with_capacity(n);
    let mut f = Vec::with_capacity(n);
    for _ in 0..n {
        let u = fresh(d, rng);
        let p = path(&u);
        f.push(p.f);
        candidates.push((u, p));
    }
    let b = f.iter().map(|&v| v as f64).sum::<f64>() / n as f64;
    if b <= 0.0 {
        // No path brought light: b̂ = 0 and the image stays black.
        return;
    }
    // The start: path i with probability f_i / Σ f. With b̂ from the same
    // paths, E[b̂ · φ(x₀)] = ∫ f φ: the chain is in equilibrium at once,
    // no start-up bias and no burn-in.
    let (i, _) = Distribution1D::new(&f).sample_discrete(rng.next_1d());
    let (mut x, mut current) = candidates.swap_remove(i);
    // Each step splats b/N in all (shared by the two states).
    let scale = b / settings.mutations as f64;
    for _ in 0..settings.mutations {
        // Propose y: a large step (an independent path) with probability
        // p_large, else a small step (every number moved by a symmetric
        // offset, wrapped). Both are symmetric: T(x → y) = T(y → x).
        let y: Vec<f32> = if rng.next_1d() < settings.large_step_probability {
            fresh(d, rng)
        } else {
            x.iter()
                .map(|&v| wrap(v + settings.mutation_size * (2.0 * rng.next_1d() - 1.0)))
                .collect()
        };
        let proposed = path(&y);
        let (fx, fy) = (current.f as f64, proposed.f as f64);
        // Metropolis: a = min(1, f(y) / f(x)) (f(x) > 0 after the bootstrap).
        let a = if fx > 0.0 { (fy / fx).min(1.0) } else { 1.0 };
        // The expected value of what the next state splats: x with
        // probability 1 − a, y with a, each as g / f times b / N.
        if fx > 0.0 {
            image.splat(&current, (1.0 - a) * scale / fx);
        }
        if fy > 0.0 {
            image.splat(&proposed, a * scale / fy);
        }
        if (rng.next_1d() as f64) < a {
            x = y;
            current = proposed;
        }
    }
}
