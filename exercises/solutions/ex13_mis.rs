//! Reference solution of exercise 13 (see `src/ex13_mis.rs` for the task).

/// The power-heuristic weight of a sample of the strategy with `pdf_this`.
pub fn mis_weight(pdf_this: f32, pdf_other: f32) -> f32 {
    let (a, b) = (pdf_this * pdf_this, pdf_other * pdf_other);
    if a + b == 0.0 { 0.0 } else { a / (a + b) }
}
