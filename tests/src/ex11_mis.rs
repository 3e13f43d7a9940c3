//! Grader of exercise 11 (two-strategy MIS weight): the properties every
//! MIS weight needs (a partition of unity that favours the larger pdf), and
//! the unbiasedness of the combined estimator of [`crate::cone`]'s integral.
//! Any correct heuristic passes (power or balance).

use raytracer::math::Color;
use raytracer::sampling::Sampler;

use crate::cone::{Strategy, exact, g};
use crate::stats::MeanVar;

/// The signature of exercise 11.
pub type MisFn = fn(f32, f32) -> f32;

/// Estimates of the combined estimator.
pub const ESTIMATES: u64 = 20_000;

const PDFS: [f32; 9] = [0.0, 1e-3, 0.1, 0.5, 1.0, 2.0, 10.0, 1e3, 1e5];

pub fn check(w: MisFn) -> Result<(), String> {
    for a in PDFS {
        for b in PDFS {
            if a == 0.0 && b == 0.0 {
                continue;
            }
            let (wa, wb) = (w(a, b), w(b, a));
            if !(wa.is_finite() && (0.0..=1.0).contains(&wa)) {
                return Err(format!(
                    "mis_weight({a}, {b}) is {wa}: a weight must be finite and in [0, 1]"
                ));
            }
            if (wa + wb - 1.0).abs() > 1e-4 {
                return Err(format!(
                    "mis_weight({a}, {b}) + mis_weight({b}, {a}) = {} — the MIS weights of the two strategies must sum to one, or light is counted twice or lost (check the parentheses)",
                    wa + wb
                ));
            }
            if a > b && wa < 0.5 {
                return Err(format!(
                    "mis_weight({a}, {b}) is {wa}: the strategy with the larger pdf must get the larger weight (are the arguments swapped?)"
                ));
            }
            if b == 0.0 && (wa - 1.0).abs() > 1e-6 {
                return Err(format!(
                    "mis_weight({a}, 0) is {wa}: when the other strategy cannot produce the sample, this one takes all of it (weight 1)"
                ));
            }
        }
    }
    // One sample from each of cosine and cone sampling, combined.
    let (f, h) = (Strategy::Cosine, Strategy::Cone);
    let mut stats = MeanVar::default();
    for i in 0..ESTIMATES {
        let mut s = Sampler::new(11, i, 0);
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
