//! Exercise 16 — Metropolis light transport in primary sample space: the
//! whole chain.
//!
//! Slides: "Metropolis light transport" ("Metropolis light transport"),
//! "Metropolis light transport: its noise" ("Metropolis light transport: шумът").
//!
//! A path is the image of the uniform numbers an integrator draws: a point
//! `u` of primary sample space `[0, 1)^D` (Kelemen et al. 2002). The
//! library turns a vector `u` into its path: `path(&u)` returns a
//! [`PathSample`], the path's contributions `g_j(u)` to the pixels `j` and
//! its scalar contribution `f(u)` (`PathSample::f`, the sum of their
//! luminances). You write the Markov chain over such vectors that renders
//! `I_j = ∫ g_j(u) du` for every pixel at once, as on the slide:
//!
//! 1. **The bootstrap.** Draw `settings.bootstrap` independent vectors
//!    (`settings.dimensions` fresh numbers each, from `rng`) and evaluate
//!    them. Their mean scalar contribution estimates the normalization
//!    `b = ∫ f(u) du`. The chain starts at one of these vectors, chosen in
//!    proportion to its `f`: then the chain is in equilibrium from its first
//!    step, with no start-up bias (`raytracer::sampling::Distribution1D`
//!    picks an index in proportion to weights). If no path found light,
//!    `b̂ = 0`: leave the image black.
//! 2. **`settings.mutations` steps**, `N`. Each proposes `y` from the
//!    current `x`: with probability `settings.large_step_probability` a
//!    large step (fresh uniform numbers), else a small step (every number
//!    of `x` moved by a small random offset of size about
//!    `settings.mutation_size`, symmetric, and wrapped around so that it
//!    stays in `[0, 1)`: primary sample space is a torus here). Evaluate `y`
//!    and accept it with the probability you derive from the slide's
//!    detailed balance: the largest acceptance with which a chain that
//!    visits vectors in proportion to `f` keeps doing so.
//! 3. **The splats of both states.** The slide's identity
//!    `I_j = b · E_{f/b}[g_j / f]` says what a state visited in proportion
//!    to `f` is worth, and the `N` steps share it. Every step adds to the
//!    image, instead of the state the chain moves to, that state's expected
//!    value over the accept coin: derive each state's weight from these two
//!    facts (the factor `W·H` of the pixels is the renderer's, not yours).
//!    Splat a state with [`ChainImage::splat`]`(&state, weight)`.
//! 4. **The move**: keep `y` with its acceptance probability, else stay at
//!    `x`.
//!
//! Receives: `path`, the library's map from a vector of numbers (length
//! `settings.dimensions`, every number in `[0, 1)`) to its path; `settings`;
//! `rng`, the chain's own random numbers (`rng.next_1d()`, each uniform in
//! `[0, 1)`); `image`, all black. Returns nothing: the chain's estimate is
//! in `image`. Edge cases: paths with `f = 0` (a proposal that finds no
//! light) bring nothing and must not make a NaN.
//!
//! `exercises::plug::run_chains` runs many independent chains of yours
//! over bidirectional path tracing (`lesson11 render --integrator mlt
//! --student`), beside the renderer's own Metropolis.

use raytracer::render::metropolis::chain::PathSample;
use raytracer::sampling::Sampler;

use crate::plug::{ChainImage, ChainSettings};

/// One Metropolis chain: the bootstrap, then `settings.mutations` steps,
/// splatted into `image`.
pub fn metropolis_chain(
    path: &dyn Fn(&[f32]) -> PathSample,
    settings: &ChainSettings,
    rng: &mut Sampler,
    image: &mut ChainImage,
) {
    // TODO: the bootstrap (b̂ and the start), then the steps: propose, accept, splat both, move.
    todo!()
}
