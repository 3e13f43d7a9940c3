//! Exercise 18 — one step of Metropolis light transport: the acceptance
//! probability and the expected-value splat.
//!
//! Slides: "Metropolis light transport" ("Metropolis light transport"),
//! "Metropolis light transport: its noise" ("Metropolis light transport: шумът").
//!
//! A Markov chain over paths keeps a current path x and proposes a path y
//! (a large step: a fresh path; a small step: x's random numbers nudged).
//! Both proposals are symmetric (y is proposed from x as often as x from y),
//! so the Metropolis rule keeps the chain at paths in proportion to f, the
//! luminance a path brings. Each step then adds to the image what the next
//! state would add, averaged over the accept coin: both paths, each with its
//! probability of being the one kept, divided by its f (the chain already
//! visits paths in proportion to f). The chain's image is scaled by
//! `W·H · b / N` afterwards; that is not your job here.
//!
//! Part 1: `acceptance(f_current, f_proposed)`: the probability of accepting
//! y. A chain on a path with f = 0 (possible only at its start) must leave
//! it: return 1 when `f_current` is 0.
//!
//! Part 2: `expected_value_splat(f_current, f_proposed)`: the weights of the
//! two paths' contributions in one step, `current` for x and `proposed` for
//! y. A path with f = 0 brings nothing: its weight is 0.
//!
//! Receives: f(x) ≥ 0 and f(y) ≥ 0. Returns: a probability in [0, 1] /
//! the two weights, finite and ≥ 0. The renderer's chain
//! (`raytracer::render::metropolis`) calls functions of exactly these
//! signatures.

use raytracer::render::metropolis::SplatWeights;

/// The probability of accepting a proposal of luminance `f_proposed` from a
/// path of luminance `f_current`.
pub fn acceptance(f_current: f32, f_proposed: f32) -> f32 {
    // TODO: the Metropolis rule for a symmetric proposal.
    todo!()
}

/// The expected-value splat weights of one step from `f_current` to a
/// proposal `f_proposed`.
pub fn expected_value_splat(f_current: f32, f_proposed: f32) -> SplatWeights {
    // TODO: each path's chance of being the next state, over its f.
    todo!()
}
