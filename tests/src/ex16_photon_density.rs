//! Grader of exercise 16 (photon mapping's density estimate): the estimate
//! exactly over hand-made sets of photons (the usual mistakes named by
//! comparing all cases at once), and its lack of bias where the photon
//! density is uniform: the k nearest of 400 photons spread uniformly over
//! the unit disk around x, each carrying 1, estimate the density 400/π
//! exactly in expectation (the k-th nearest, at r, weighs 0; the k − 1 inside
//! are uniform in the disk of radius r; π r² is the k-th of 400 uniform
//! numbers times π, and E[1/U_(k)] = 400/(k − 1)).
//!
//! Tolerances: exact values to 1e-4 relative; the uniform density |z| ≤ 5.5
//! with the student's own standard error (false failure < 4e-8 per channel).

use raytracer::math::{Color, PI};
use raytracer::sampling::Sampler;
use raytracer::sampling::warp::concentric_disk;

use crate::stats::{MeanVar, Mistake, recognise};

/// The signature of exercise 16.
pub type DensityFn = fn(&[(f32, Color)], usize, f32) -> Color;

/// Trials of the uniform-density estimate, photons per trial, k.
pub const TRIALS: u64 = 2_000;
pub const PHOTONS: u64 = 400;
pub const K: usize = 20;

/// A case: the photons, k and the squared largest radius.
type Case = (Vec<(f32, Color)>, usize, f32);

/// The kernel-weighted sum with r² given, kernel `kernel(d², r²)`.
fn weighted(photons: &[(f32, Color)], r2: f32, kernel: impl Fn(f32, f32) -> f32) -> Color {
    if r2 <= 0.0 {
        return Color::ZERO;
    }
    photons
        .iter()
        .filter(|p| p.0 < r2)
        .map(|&(d2, fp)| fp * kernel(d2, r2))
        .sum()
}

/// r² of the k nearest: the k-th smallest d², or `max_r2` with fewer photons.
fn radius2(photons: &[(f32, Color)], k: usize, max_r2: f32) -> f32 {
    if photons.len() < k {
        return max_r2;
    }
    let mut d2: Vec<f32> = photons.iter().map(|p| p.0).collect();
    d2.sort_by(f32::total_cmp);
    d2[k - 1]
}

fn epanechnikov(d2: f32, r2: f32) -> f32 {
    2.0 / (PI * r2) * (1.0 - d2 / r2)
}

/// The grader's estimate.
pub fn expected((photons, k, max_r2): &Case) -> Color {
    weighted(photons, radius2(photons, *k, *max_r2), epanechnikov)
}

fn cases() -> Vec<Case> {
    let c = Color::new;
    vec![
        (
            vec![
                (0.04, c(1.0, 0.5, 0.25)),
                (0.01, c(0.2, 0.4, 0.6)),
                (0.09, c(3.0, 1.0, 0.0)),
                (0.0025, c(0.5, 0.5, 0.5)),
                (0.16, c(1.0, 2.0, 3.0)),
            ],
            3,
            0.25,
        ),
        (
            vec![
                (0.3, c(0.1, 0.2, 0.3)),
                (0.05, c(1.0, 1.0, 1.0)),
                (0.5, c(2.0, 0.0, 1.0)),
                (0.12, c(0.7, 0.3, 0.9)),
                (0.02, c(0.4, 0.8, 0.1)),
                (0.45, c(1.5, 1.5, 0.5)),
                (0.2, c(0.3, 0.6, 0.2)),
                (0.08, c(0.9, 0.1, 0.4)),
            ],
            4,
            0.6,
        ),
        // Fewer photons than k: all of them, over the largest disk.
        (
            vec![
                (0.02, c(1.0, 0.0, 0.0)),
                (0.11, c(0.0, 1.0, 0.0)),
                (0.06, c(0.0, 0.0, 1.0)),
            ],
            5,
            0.16,
        ),
        // Exactly k: the farthest sets r and weighs 0.
        (
            vec![
                (0.36, c(4.0, 4.0, 4.0)),
                (0.09, c(1.0, 2.0, 1.0)),
                (0.16, c(0.5, 0.5, 2.0)),
                (0.01, c(0.2, 0.1, 0.3)),
            ],
            4,
            1.0,
        ),
    ]
}

pub fn check(density: DensityFn) -> Result<(), String> {
    let cases = cases();
    let got: Vec<Color> = cases.iter().map(|(p, k, m)| density(p, *k, *m)).collect();
    let same = |g: Color, e: Color| {
        (g - e)
            .abs()
            .cmple(1e-4 * e.abs().max(Color::splat(1e-3)))
            .all()
    };
    if let Some(i) = (0..cases.len()).find(|&i| !same(got[i], expected(&cases[i]))) {
        let r2 = |(p, k, m): &Case| radius2(p, *k, *m);
        let mistakes: [Mistake<Case, Color>; 6] = [
            (
                "that is a plain average over the disk's area (a box kernel, Σ fp / (π r²)): a valid density estimate, but biased by k/(k − 1) with the k nearest, and not the renderer's — weigh each photon with the Epanechnikov kernel 2/(π r²)·(1 − d²/r²)",
                &|c| weighted(&c.0, r2(c), |_, r2| 1.0 / (PI * r2)),
            ),
            (
                "the kernel is not normalized: (1 − d²/r²) integrates to π r²/2 over the disk, so its normalization is 2/(π r²), not 1/(π r²)",
                &|c| weighted(&c.0, r2(c), |d2, r2| (1.0 - d2 / r2) / (PI * r2)),
            ),
            (
                "the pairs hold SQUARED distances: r² is the k-th smallest of them as it is, and the disk's area is π·r², not π·(r²)²",
                &|c| weighted(&c.0, r2(c), |d2, r2| 2.0 / (PI * r2 * r2) * (1.0 - d2 / r2)),
            ),
            (
                "the kernel falls with the squared distance, 1 − d²/r², and d² is given: it is not 1 − d/r",
                &|c| {
                    weighted(&c.0, r2(c), |d2, r2| {
                        2.0 / (PI * r2) * (1.0 - (d2 / r2).sqrt())
                    })
                },
            ),
            (
                "you used every photon given: take only the k nearest, r being the distance of the k-th",
                &|c| {
                    let far = c.0.iter().map(|p| p.0).fold(0.0f32, f32::max);
                    let r2 = if c.0.len() < c.1 { c.2 } else { far };
                    weighted(&c.0, r2, epanechnikov)
                },
            ),
            (
                "with fewer than k photons, the disk is the whole search radius (r² = max_r2), not the farthest photon's",
                &|c| {
                    let r2 = if c.0.len() < c.1 {
                        c.0.iter().map(|p| p.0).fold(0.0f32, f32::max)
                    } else {
                        r2(c)
                    };
                    weighted(&c.0, r2, epanechnikov)
                },
            ),
        ];
        let (photons, k, max_r2) = &cases[i];
        let why = recognise(&cases, &got, &mistakes, same).unwrap_or_else(|| {
            "r² is the k-th smallest d² (max_r2 with fewer than k photons); L = Σ fp · 2/(π r²) · (1 − d²/r²) over the photons with d² < r²".to_string()
        });
        return Err(format!(
            "photon_radiance({} photons, k = {k}, max_r2 = {max_r2}) is {}, expected {} — {why}",
            photons.len(),
            got[i],
            expected(&cases[i])
        ));
    }
    let none = density(&[], 3, 0.25);
    if none != Color::ZERO {
        return Err(format!(
            "photon_radiance(no photons, k = 3) is {none}: with no photon near x, no light is estimated"
        ));
    }
    let mut stats = MeanVar::default();
    let mut photons = Vec::with_capacity(PHOTONS as usize);
    for t in 0..TRIALS {
        photons.clear();
        for i in 0..PHOTONS {
            let mut s = Sampler::new(16, t * PHOTONS + i, 0);
            let p = concentric_disk(s.next_2d());
            photons.push((p.length_squared(), Color::ONE));
        }
        stats.add(density(&photons, K, 1.0));
    }
    stats.check(
        "the k = 20 nearest of 400 photons spread uniformly over the unit disk (density 400/π)",
        Color::splat(PHOTONS as f32 / PI),
        |ratio| {
            ((ratio - K as f64 / (K - 1) as f64).abs() < 0.01).then(|| {
                "k/(k − 1) too bright: the k-th photon, at the edge of the disk, must weigh 0"
                    .into()
            })
        },
    )
}
