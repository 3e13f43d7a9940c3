//! Grader of exercise 18 (one step of Metropolis light transport): the
//! acceptance probability and the expected-value splat exactly, over a grid
//! of luminances with the edge cases the task specifies (the usual mistakes
//! named), then a whole Metropolis chain built from the student's two
//! functions, which must render a small 1D image with a known answer.
//!
//! The chain: primary sample space `[0, 1)`, `f(u) = 0.2 + u²`, an image of
//! [`BINS`] pixels, pixel `j` receiving `f(u)` from the `u` in its bin, so
//! pixel `j` is exactly `∫_bin f du`. Large steps (probability 0.3, a fresh
//! `u`) and small ones (`u + 0.05·(2v − 1)` wrapped: symmetric); each chain
//! starts at a `u` drawn in proportion to `f` (by rejection) and is scaled by
//! the exact `b = ∫ f = 0.2 + 1/3`, so every chain's image is unbiased from
//! its first step. [`CHAINS`] independent chains give each pixel its mean
//! and standard error; a correct solution stays within |t| ≤ 6 with 31
//! degrees of freedom (`P(|t₃₁| > 6) ≈ 1.2e-6` per pixel, < 1e-5 for the
//! eight).
//!
//! Tolerances: exact values to 1e-5 relative (f32 rounding of another
//! correct order of operations).

use raytracer::render::metropolis::SplatWeights;
use raytracer::sampling::Sampler;

use crate::stats::{Mistake, recognise};

/// The signatures of exercise 18.
pub type AcceptanceFn = fn(f32, f32) -> f32;
pub type SplatFn = fn(f32, f32) -> SplatWeights;

/// Luminances of the grid (f(x), f(y) each; (0, 0) is an edge case apart).
pub const LUMINANCES: [f32; 8] = [0.0, 1e-3, 0.1, 0.5, 1.0, 2.0, 10.0, 1e3];
/// Pixels of the chain's 1D image.
pub const BINS: usize = 8;
/// Independent chains, and the steps of each.
pub const CHAINS: u64 = 32;
pub const STEPS: u64 = 4000;
/// Largest |t| of a pixel (see the module doc).
pub const T_MAX: f64 = 6.0;

/// The grader's acceptance probability, in f64.
pub fn expected_acceptance(fx: f32, fy: f32) -> f32 {
    if fx > 0.0 {
        (fy as f64 / fx as f64).min(1.0) as f32
    } else {
        1.0
    }
}

/// The grader's expected-value weights, in f64.
pub fn expected_splat(fx: f32, fy: f32) -> SplatWeights {
    let a = expected_acceptance(fx, fy) as f64;
    let over = |w: f64, f: f32| if f > 0.0 { (w / f as f64) as f32 } else { 0.0 };
    SplatWeights {
        current: over(1.0 - a, fx),
        proposed: over(a, fy),
    }
}

fn same(g: f32, e: f32) -> bool {
    (g - e).abs() <= 1e-5 * e.abs().max(1e-3)
}

/// The grid of cases, (0, 0) left out.
fn cases() -> Vec<(f32, f32)> {
    let mut cases = Vec::new();
    for fx in LUMINANCES {
        for fy in LUMINANCES {
            if fx != 0.0 || fy != 0.0 {
                cases.push((fx, fy));
            }
        }
    }
    cases
}

pub fn check(acceptance: AcceptanceFn, splat: SplatFn) -> Result<(), String> {
    check_acceptance(acceptance)?;
    check_splat(splat)?;
    check_chain(acceptance, splat)
}

fn check_acceptance(a: AcceptanceFn) -> Result<(), String> {
    let cases = cases();
    let got: Vec<f32> = cases.iter().map(|&(x, y)| a(x, y)).collect();
    let Some(k) =
        (0..cases.len()).find(|&k| !same(got[k], expected_acceptance(cases[k].0, cases[k].1)))
    else {
        let both = a(0.0, 0.0);
        if !(0.0..=1.0).contains(&both) {
            return Err(format!(
                "acceptance(0, 0) is {both}: a probability in [0, 1] (from a path that brings nothing to another, either choice is fine) — not NaN from 0/0"
            ));
        }
        return Ok(());
    };
    let mistakes: [Mistake<(f32, f32), f32>; 3] = [
        (
            "the ratio is upside down: a brighter proposal must always be accepted, a darker one with probability f(y)/f(x)",
            &|&(x, y)| expected_acceptance(y, x),
        ),
        (
            "the ratio is not clamped: f(y)/f(x) exceeds 1 for a brighter proposal, and a probability cannot — take min(1, f(y)/f(x))",
            &|&(x, y)| if x > 0.0 { y / x } else { 1.0 },
        ),
        (
            "the ratio f(y)/(f(x) + f(y)) is Barker's rule: a valid chain, but it rejects more than Metropolis's min(1, f(y)/f(x)), which the slide and the renderer use",
            &|&(x, y)| if x + y > 0.0 { y / (x + y) } else { 1.0 },
        ),
    ];
    let (x, y) = cases[k];
    let why = recognise(&cases, &got, &mistakes, same).unwrap_or_else(|| {
        if !got[k].is_finite() {
            "a probability must be a finite number in [0, 1] (a division by f(x) = 0? the task says: 1 when f(x) is 0)".to_string()
        } else if x == 0.0 {
            "a chain on a path with f(x) = 0 must leave it: the task asks for 1".to_string()
        } else {
            "the Metropolis rule for a symmetric proposal takes the brighter move always, the darker one with the ratio of the luminances".to_string()
        }
    });
    Err(format!(
        "acceptance({x}, {y}) is {}, expected {} — {why}",
        got[k],
        expected_acceptance(x, y)
    ))
}

fn check_splat(splat: SplatFn) -> Result<(), String> {
    let cases = cases();
    let got: Vec<SplatWeights> = cases.iter().map(|&(x, y)| splat(x, y)).collect();
    let same_w = |g: SplatWeights, e: SplatWeights| {
        same(g.current, e.current) && same(g.proposed, e.proposed)
    };
    let Some(k) =
        (0..cases.len()).find(|&k| !same_w(got[k], expected_splat(cases[k].0, cases[k].1)))
    else {
        let both = splat(0.0, 0.0);
        if both.current != 0.0 || both.proposed != 0.0 {
            return Err(format!(
                "expected_value_splat(0, 0) is {both:?}: two paths that bring nothing weigh 0 each — not NaN from 0/0"
            ));
        }
        return Ok(());
    };
    let ea = |x: f32, y: f32| expected_acceptance(x, y);
    let mistakes: [Mistake<(f32, f32), SplatWeights>; 4] = [
        (
            "the weights are not divided by f: the chain already visits paths in proportion to f, so each path adds its contribution over its own f",
            &|&(x, y)| SplatWeights {
                current: 1.0 - ea(x, y),
                proposed: ea(x, y),
            },
        ),
        (
            "the weights are swapped: the proposal is the next state with probability a, the current path with 1 − a",
            &|&(x, y)| {
                let a = ea(x, y);
                let over = |w: f32, f: f32| if f > 0.0 { w / f } else { 0.0 };
                SplatWeights {
                    current: over(a, x),
                    proposed: over(1.0 - a, y),
                }
            },
        ),
        (
            "only the proposal is splatted: the expected value of what the next state adds counts the current path too, with its probability 1 − a of staying",
            &|&(x, y)| SplatWeights {
                current: 0.0,
                proposed: expected_splat(x, y).proposed,
            },
        ),
        (
            "each weight is divided by the other path's f: the next state adds its own contribution over its own f",
            &|&(x, y)| {
                let a = ea(x, y);
                let over = |w: f32, f: f32| if f > 0.0 { w / f } else { 0.0 };
                SplatWeights {
                    current: over(1.0 - a, y),
                    proposed: over(a, x),
                }
            },
        ),
    ];
    let (x, y) = cases[k];
    let why = recognise(&cases, &got, &mistakes, same_w).unwrap_or_else(|| {
        let w = got[k];
        if !(w.current.is_finite() && w.proposed.is_finite()) {
            "the weights must be finite: a path with f = 0 brings nothing and weighs 0 (not a division by zero)".to_string()
        } else if w.current < 0.0 || w.proposed < 0.0 {
            "a weight cannot be negative: probabilities over luminances".to_string()
        } else {
            let unit = w.current as f64 * x as f64 + w.proposed as f64 * y as f64;
            format!(
                "every step adds one unit of luminance in all (current·f(x) + proposed·f(y) = 1 when f(x) > 0), yours adds {unit:.4}"
            )
        }
    });
    Err(format!(
        "expected_value_splat({x}, {y}) is {:?}, expected {:?} — {why}",
        got[k],
        expected_splat(x, y)
    ))
}

/// The target of the chain and its exact pixel values.
fn f(u: f64) -> f64 {
    0.2 + u * u
}

fn exact_pixel(j: usize) -> f64 {
    let (a, b) = (j as f64 / BINS as f64, (j + 1) as f64 / BINS as f64);
    0.2 * (b - a) + (b * b * b - a * a * a) / 3.0
}

fn bin(u: f64) -> usize {
    ((u * BINS as f64) as usize).min(BINS - 1)
}

/// One chain's image, scaled by the exact `b` (pixel `j` estimates
/// `∫_bin f`).
fn chain_image(c: u64, acceptance: AcceptanceFn, splat: SplatFn) -> [f64; BINS] {
    let b = 0.2 + 1.0 / 3.0;
    let mut s = Sampler::new(18, c, 0);
    // A start in proportion to f, by rejection under f ≤ 1.2.
    let mut x = loop {
        let (u, v) = (s.next_1d() as f64, s.next_1d() as f64);
        if v * 1.2 < f(u) {
            break u;
        }
    };
    let mut sums = [0.0f64; BINS];
    for t in 1..=STEPS {
        let mut s = Sampler::new(18, c, t);
        let y = if s.next_1d() < 0.3 {
            s.next_1d() as f64
        } else {
            (x + 0.05 * (2.0 * s.next_1d() as f64 - 1.0)).rem_euclid(1.0)
        };
        let (fx, fy) = (f(x) as f32, f(y) as f32);
        let w = splat(fx, fy);
        sums[bin(x)] += w.current as f64 * fx as f64;
        sums[bin(y)] += w.proposed as f64 * fy as f64;
        if (s.next_1d()) < acceptance(fx, fy) {
            x = y;
        }
    }
    sums.map(|v| v * b / STEPS as f64)
}

/// The chain of the module doc with the student's functions, pixel by
/// pixel against the exact image.
pub fn check_chain(acceptance: AcceptanceFn, splat: SplatFn) -> Result<(), String> {
    let images: Vec<[f64; BINS]> = (0..CHAINS)
        .map(|c| chain_image(c, acceptance, splat))
        .collect();
    let k = CHAINS as f64;
    for j in 0..BINS {
        let mean = images.iter().map(|im| im[j]).sum::<f64>() / k;
        let s2 = images.iter().map(|im| (im[j] - mean).powi(2)).sum::<f64>() / (k - 1.0);
        let se = (s2 / k).sqrt();
        let exact = exact_pixel(j);
        if !mean.is_finite() || ((mean - exact).abs() > T_MAX * se && (mean - exact).abs() > 1e-6) {
            return Err(format!(
                "a Metropolis chain with your two functions renders pixel {j} of a 1D image (f(u) = 0.2 + u², {BINS} pixels) as {mean:.5}, exactly {exact:.5} ({:+.1} %, {:.1} standard errors of {CHAINS} independent chains, more than the {T_MAX} allowed): the chain is biased",
                100.0 * (mean - exact) / exact,
                (mean - exact).abs() / se.max(1e-300)
            ));
        }
    }
    Ok(())
}
