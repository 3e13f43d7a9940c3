//! Exercise 13 — the MIS weight of BRDF sampling and light sampling.
//!
//! Slides: "Multiple importance sampling" ("Multiple importance sampling"),
//! "Next event estimation" ("Next event estimation").
//!
//! Direct light can be found twice: by sampling a light (exercise 12) and
//! by a BRDF sample that happens to hit it (exercise 11). Counting both
//! counts it twice. Multiple importance sampling gives each sample a weight:
//! the weights of the two strategies for the same direction sum to one, and
//! the strategy with the larger density gets the larger weight. Of the
//! weights that do this (Veach's thesis, chapter 9) the slide and the
//! renderer use the power heuristic with exponent 2, and this exercise asks
//! for exactly that one. (The balance heuristic, exponent 1, is valid too:
//! the grader recognises it and asks for the power heuristic.)
//!
//! Task: the power-heuristic weight (exponent 2) for one sample of each of
//! two strategies: the weight of a direction drawn by the strategy with
//! density `pdf_this`, when the other strategy would have drawn the same
//! direction with density `pdf_other`. If `pdf_other` is 0 (the other
//! strategy cannot find it) the weight is 1; if `pdf_this` is 0 it is 0; if
//! both are 0 return 0 (no strategy makes that sample).
//!
//! Receives: two densities per unit solid angle, ≥ 0. Returns: the weight in
//! [0, 1].

/// The power-heuristic weight of a sample of the strategy with `pdf_this`.
pub fn mis_weight(pdf_this: f32, pdf_other: f32) -> f32 {
    // TODO: each strategy counts with a power of its density.
    todo!()
}
