//! Grader of exercise 13 (two-strategy MIS weight): the power heuristic
//! asked for, exactly, over a grid of densities (the balance heuristic and
//! the other usual mistakes named), the edge cases the task specifies, and
//! the unbiasedness of the combined estimator of [`crate::cone`]'s integral.
//!
//! Tolerances: exact values to 1e-5 absolute; the combined estimate |z| ≤ 5.5
//! (false failure < 4e-8 per channel).

use raytracer::math::Color;
use raytracer::sampling::Sampler;

use crate::cone::{Strategy, exact, g};
use crate::stats::{MeanVar, Mistake, recognise};

/// The signature of exercise 13.
pub type MisFn = fn(f32, f32) -> f32;

/// Estimates of the combined estimator.
pub const ESTIMATES: u64 = 20_000;

/// The densities of the grid (both zero excluded there; see the edge cases).
pub const PDFS: [f32; 9] = [0.0, 1e-3, 0.1, 0.5, 1.0, 2.0, 10.0, 1e3, 1e5];

/// The grader's power heuristic, in f64.
pub fn expected(a: f32, b: f32) -> f32 {
    let (a, b) = (a as f64 * a as f64, b as f64 * b as f64);
    if a + b == 0.0 {
        0.0
    } else {
        (a / (a + b)) as f32
    }
}

/// Names of the mistakes shared with exercise 15 (many strategies).
pub const BALANCE: &str = "that is the balance heuristic (exponent 1): a valid MIS weight, but this exercise asks for the power heuristic with exponent 2, as the slide and the renderer use — each density squared";

pub fn check(w: MisFn) -> Result<(), String> {
    let mut cases = Vec::new();
    for a in PDFS {
        for b in PDFS {
            if a != 0.0 || b != 0.0 {
                cases.push((a, b));
            }
        }
    }
    let got: Vec<f32> = cases.iter().map(|&(a, b)| w(a, b)).collect();
    let same = |g: f32, e: f32| (g - e).abs() <= 1e-5;
    if let Some(k) = (0..cases.len()).find(|&k| !same(got[k], expected(cases[k].0, cases[k].1))) {
        let mistakes: [Mistake<(f32, f32), f32>; 4] = [
            (BALANCE, &|&(a, b)| a / (a + b)),
            (
                "the arguments are swapped: the weight of the strategy with pdf_this grows with pdf_this",
                &|&(a, b)| expected(b, a),
            ),
            (
                "a parenthesis: a² / (a + b)² is not normalized — the two weights of one direction must sum to one",
                &|&(a, b)| a * a / ((a + b) * (a + b)),
            ),
            (
                "the maximum heuristic (weight 1 for the larger density, 0 for the other) is valid, but not the power heuristic asked for",
                &|&(a, b)| {
                    if a > b {
                        1.0
                    } else if a < b {
                        0.0
                    } else {
                        0.5
                    }
                },
            ),
        ];
        let (a, b) = cases[k];
        let why = recognise(&cases, &got, &mistakes, same).unwrap_or_else(|| {
            let (wa, wb) = (got[k], w(b, a));
            if !wa.is_finite() {
                "a weight must be a finite number in [0, 1]".to_string()
            } else if (wa + wb - 1.0).abs() > 1e-4 {
                format!(
                    "mis_weight({a}, {b}) + mis_weight({b}, {a}) = {}: the weights of the two strategies must sum to one, or light is counted twice or lost",
                    wa + wb
                )
            } else {
                "the power heuristic weighs each strategy by its density squared".to_string()
            }
        });
        return Err(format!(
            "mis_weight({a}, {b}) is {}, expected {} — {why}",
            got[k],
            expected(a, b)
        ));
    }
    let both_zero = w(0.0, 0.0);
    if both_zero != 0.0 {
        return Err(format!(
            "mis_weight(0, 0) is {both_zero}: when neither strategy can make the sample, return 0 (as the task says) — not NaN from 0/0"
        ));
    }
    // One sample from each of cosine and cone sampling, combined.
    let (f, h) = (Strategy::Cosine, Strategy::Cone);
    let mut stats = MeanVar::default();
    for i in 0..ESTIMATES {
        let mut s = Sampler::new(13, i, 0);
        let (x, y) = (f.sample(s.next_2d()), h.sample(s.next_2d()));
        let mut est = 0.0;
        if f.pdf(x) > 0.0 {
            est += w(f.pdf(x), h.pdf(x)) * g(x) / f.pdf(x);
        }
        if h.pdf(y) > 0.0 {
            est += w(h.pdf(y), f.pdf(y)) * g(y) / h.pdf(y);
        }
        stats.add(Color::splat(est));
    }
    stats.check(
        "MIS of cosine and cone sampling for ∫ cos θ/π over a 40° cone (= sin²40°)",
        Color::splat(exact()),
        |_| Some("the combined estimator is biased".to_string()),
    )
}
