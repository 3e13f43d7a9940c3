//! Exercise 11 — the MIS weight of BRDF sampling and light sampling.
//!
//! Slide: "Path tracing (II)" (direct light found twice: by sampling a light
//! and by a BRDF sample that happens to hit it). Counting both would count
//! the light twice; multiple importance sampling weighs each sample by how
//! well its strategy suits it: `w_f + w_g = 1` for every direction, and the
//! strategy with the larger pdf gets the larger weight.
//!
//! Task: the power heuristic (Veach, exponent β = 2) for one sample from
//! each of two strategies: the weight of a sample drawn by the strategy whose
//! pdf is `pdf_this`, when the other strategy would have drawn the same
//! direction with density `pdf_other`:
//! `w = pdf_this² / (pdf_this² + pdf_other²)`.
//! When `pdf_other` is 0 (the other strategy could not have found it), the
//! weight is 1.
//!
//! Receives: two densities per unit solid angle (≥ 0, not both 0).
//! Returns: the weight in `[0, 1]`.

/// The power-heuristic weight of a sample of the strategy with `pdf_this`.
pub fn mis_weight(pdf_this: f32, pdf_other: f32) -> f32 {
    // TODO
    todo!()
}
