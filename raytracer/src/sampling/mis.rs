//! Multiple importance sampling (Veach and Guibas 1995): weights that combine
//! several estimators of one integral so that each is trusted where its pdf is
//! large. For a sample drawn from technique `a` with `n_a` samples:
//! balance heuristic `w_a = n_a p_a / Σ_k n_k p_k`, power heuristic (β = 2)
//! `w_a = (n_a p_a)² / Σ_k (n_k p_k)²`. The weights of all techniques sum to
//! one for every sample, which keeps the combination unbiased.

/// Balance heuristic for two techniques with `nf` and `ng` samples.
#[inline]
pub fn balance_heuristic(nf: f32, pdf_f: f32, ng: f32, pdf_g: f32) -> f32 {
    let (f, g) = (nf * pdf_f, ng * pdf_g);
    if f == 0.0 { 0.0 } else { f / (f + g) }
}

/// Power heuristic (β = 2) for two techniques with `nf` and `ng` samples.
/// An infinite `pdf_f` (a delta technique) gets weight 1.
#[inline]
pub fn power_heuristic(nf: f32, pdf_f: f32, ng: f32, pdf_g: f32) -> f32 {
    let (f, g) = (nf * pdf_f, ng * pdf_g);
    if f.is_infinite() {
        return 1.0;
    }
    if f == 0.0 {
        0.0
    } else {
        (f * f) / (f * f + g * g)
    }
}
