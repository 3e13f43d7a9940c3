//! Chi-square tests of sampling routines.
//!
//! Lecture topic: Monte Carlo integration — an estimator `f(x)/p(x)` is only
//! unbiased if the samples really have the density `p` that the code divides
//! by. This module tests exactly that, as pbrt-v4 and Mitsuba do for their
//! BSDFs: draw `N` directions from a sampler, histogram them over cells of
//! the sphere, integrate the claimed pdf over each cell to get the expected
//! counts `E_k = N ∫_cell p dω`, and compare with Pearson's statistic
//! `χ² = Σ_k (O_k − E_k)²/E_k`. If the sampler follows the pdf, `χ²` follows
//! (for large counts) a chi-square distribution with `cells − 1` degrees of
//! freedom, and a `p`-value below the significance level rejects it.
//!
//! Details:
//! - **Cells.** Equal-area cells in `(cos θ, φ)` about an axis (`dω = d(cos θ) dφ`,
//!   so the quadrature needs no Jacobian). For a narrow lobe the cells may
//!   cover only a cap `cos θ ≥ cos_theta_min` about the lobe's axis; the rest
//!   of the sphere is one more cell. A last cell counts the samples the
//!   sampler refused (`None`): its expected count is `N (1 − ∫_{S²} p dω)`, so
//!   a sampler that rejects (Phong below the horizon) is tested completely,
//!   including how often it rejects.
//! - **Quadrature.** Each cell's integral is a tensor Simpson rule on a
//!   sub-grid, refined (16, 32, … up to 256 intervals per side) until two
//!   successive grids agree to `0.01 √E` counts, far below the counting noise
//!   `√E`; sharp lobes get fine grids, smooth ones stay cheap.
//! - **Pooling.** Cells with an expected count below 5 (where the chi-square
//!   approximation fails) are merged into one cell. A sample in a cell whose
//!   pdf integral is zero fails at once (beyond `N·1e-5` of them).
//! - **Significance.** `α = 0.01` for a whole family of tests by default: a
//!   correct sampler fails with probability 1%. With `m` tests in the family,
//!   each test uses Šidák's level `1 − (1 − α)^{1/m}`, so the family still
//!   fails a correct sampler with probability exactly α (for independent tests).
//!   The seed is fixed, so a given sampler passes or fails deterministically;
//!   α is the chance that a correct sampler (or any seed) lands on a failure.
//!   A false failure costs a correct student points and costs us an hour of
//!   searching for a bug that is not there, so α must be small; but a
//!   smaller α needs a larger deviation before a real bug is caught. With
//!   `N ≈ 10⁶` samples even 1–2% errors in a lobe give χ² in the thousands,
//!   so α = 0.01 (or lower) loses little power.
//!
//! The uniform numbers come from [`Sampler`] with a fixed seed: sample `i`
//! takes `u = next_2d()` and then `u_lobe = next_1d()` from
//! `Sampler::new(seed, i, 0)` (see [`uniforms`]).

use std::cell::Cell;

use crate::frame::Frame;
use crate::math::{Vec2, Vec3A};
use crate::sampling::Sampler;

/// Default significance level of a family of tests.
pub const DEFAULT_SIGNIFICANCE: f64 = 0.01;

/// Settings of a chi-square test of a direction sampler.
#[derive(Clone, Debug)]
pub struct Chi2Test {
    /// Number of cells in `cos θ` (rows) over `[cos_theta_min, 1]`.
    pub cos_theta_res: usize,
    /// Number of cells in `φ` (columns) over `[0, 2π)`.
    pub phi_res: usize,
    /// Number of samples `N`.
    pub samples: u64,
    /// Seed of the [`Sampler`] that provides the uniform numbers.
    pub seed: u64,
    /// Pole of the cells (`θ` is measured from it); need not be unit.
    pub axis: Vec3A,
    /// Lower end of the cells in `cos θ` (−1: the whole sphere). The
    /// directions below form one extra cell.
    pub cos_theta_min: f32,
    /// Significance level α of the whole family of tests.
    pub significance: f64,
    /// Number of tests in the family (for the Šidák correction).
    pub tests: usize,
}

impl Default for Chi2Test {
    fn default() -> Self {
        Chi2Test {
            cos_theta_res: 10,
            phi_res: 20,
            samples: 1 << 20,
            seed: 0,
            axis: Vec3A::Z,
            cos_theta_min: -1.0,
            significance: DEFAULT_SIGNIFICANCE,
            tests: 1,
        }
    }
}

/// The outcome of a passed chi-square test.
#[derive(Clone, Debug, PartialEq)]
pub struct Chi2Report {
    /// Pearson's statistic `Σ (O − E)²/E` over the cells after pooling.
    pub statistic: f64,
    /// Degrees of freedom: cells after pooling minus one.
    pub dof: usize,
    /// Probability of a statistic at least this large for a correct sampler.
    pub p_value: f64,
    /// Significance level of this single test (after the Šidák correction).
    pub threshold: f64,
    /// Number of cells after pooling.
    pub cells: usize,
    /// Number of cells merged into the pooled cell.
    pub pooled: usize,
    /// Number of samples drawn.
    pub samples: u64,
    /// Number of samples the sampler refused (`None`).
    pub no_sample: u64,
}

/// The uniform numbers `(u, u_lobe)` of sample `i`.
#[inline]
pub fn uniforms(seed: u64, i: u64) -> (Vec2, f32) {
    let mut s = Sampler::new(seed, i, 0);
    let u = s.next_2d();
    (u, s.next_1d())
}

/// Šidák's per-test level: `m` independent tests at this level fail together
/// with probability `alpha`, `1 − (1 − α)^{1/m}`.
pub fn sidak(alpha: f64, tests: usize) -> f64 {
    -((-alpha).ln_1p() / tests.max(1) as f64).exp_m1()
}

/// `ln Γ(x)` for `x > 0`, by Lanczos' approximation (g = 7, 9 terms;
/// relative error below 1e-14), with the reflection formula below 1/2.
pub fn ln_gamma(x: f64) -> f64 {
    const G: f64 = 7.0;
    const C: [f64; 9] = [
        0.999_999_999_999_809_9,
        676.520_368_121_885_1,
        -1_259.139_216_722_402_8,
        771.323_428_777_653_1,
        -176.615_029_162_140_6,
        12.507_343_278_686_905,
        -0.138_571_095_265_720_12,
        9.984_369_578_019_572e-6,
        1.505_632_735_149_311_6e-7,
    ];
    if x < 0.5 {
        // Γ(x) Γ(1 − x) = π / sin(πx).
        let pi = std::f64::consts::PI;
        return (pi / (pi * x).sin()).ln() - ln_gamma(1.0 - x);
    }
    let x = x - 1.0;
    let mut a = C[0];
    for (k, c) in C.iter().enumerate().skip(1) {
        a += c / (x + k as f64);
    }
    let t = x + G + 0.5;
    0.5 * (2.0 * std::f64::consts::PI).ln() + (x + 0.5) * t.ln() - t + a.ln()
}

/// Regularized upper incomplete gamma `Q(a, x) = Γ(a, x)/Γ(a)` for `a > 0`.
///
/// For `x < a + 1` by the series of the lower function,
/// `P(a, x) = e^{−x} x^a / Γ(a+1) · Σ_k x^k / ((a+1)…(a+k))`, and `Q = 1 − P`;
/// otherwise by Legendre's continued fraction
/// `Γ(a, x) = e^{−x} x^a / (x + 1 − a − 1(1 − a)/(x + 3 − a − 2(2 − a)/(x + 5 − a − …)))`,
/// evaluated with the modified Lentz method. Both converge fast in their range.
pub fn regularized_gamma_q(a: f64, x: f64) -> f64 {
    if x <= 0.0 {
        return 1.0;
    }
    let prefactor = (-x + a * x.ln() - ln_gamma(a)).exp();
    if x < a + 1.0 {
        let mut ap = a;
        let mut term = 1.0 / a;
        let mut sum = term;
        for _ in 0..10_000 {
            ap += 1.0;
            term *= x / ap;
            sum += term;
            if term.abs() < sum.abs() * 1e-16 {
                break;
            }
        }
        (1.0 - sum * prefactor).clamp(0.0, 1.0)
    } else {
        const TINY: f64 = 1e-300;
        let mut b = x + 1.0 - a;
        let mut c = 1.0 / TINY;
        let mut d = 1.0 / b;
        let mut h = d;
        for i in 1..10_000 {
            let an = -(i as f64) * (i as f64 - a);
            b += 2.0;
            d = an * d + b;
            if d.abs() < TINY {
                d = TINY;
            }
            c = b + an / c;
            if c.abs() < TINY {
                c = TINY;
            }
            d = 1.0 / d;
            let delta = d * c;
            h *= delta;
            if (delta - 1.0).abs() < 1e-16 {
                break;
            }
        }
        (prefactor * h).clamp(0.0, 1.0)
    }
}

/// `P(χ²_k ≥ x)`: the p-value of a chi-square statistic `x` with `k` degrees
/// of freedom, `Q(k/2, x/2)`.
pub fn chi2_survival(x: f64, dof: usize) -> f64 {
    if dof == 0 {
        return if x > 0.0 { 0.0 } else { 1.0 };
    }
    regularized_gamma_q(dof as f64 / 2.0, x / 2.0)
}

impl Chi2Test {
    /// Runs the test: `sample(u, u_lobe)` draws a direction (or refuses),
    /// `pdf(w)` is its claimed density per unit solid angle (over the whole
    /// sphere; it may integrate to less than one if the sampler refuses some
    /// samples). Returns the report, or an error that names the worst cells.
    pub fn run(
        &self,
        mut sample: impl FnMut(Vec2, f32) -> Option<Vec3A>,
        pdf: impl Fn(Vec3A) -> f32,
    ) -> Result<Chi2Report, String> {
        let (rows, cols) = (self.cos_theta_res, self.phi_res);
        if rows == 0 || cols == 0 || self.samples == 0 || self.tests == 0 {
            return Err(format!("chi-square: empty test settings {self:?}"));
        }
        if !(-1.0..1.0).contains(&self.cos_theta_min) || self.axis.length_squared() == 0.0 {
            return Err(format!("chi-square: bad cap or axis in {self:?}"));
        }
        let frame = Frame::from_normal(self.axis.normalize());
        let (outside, none) = (rows * cols, rows * cols + 1);

        // Histogram of the samples.
        let mut observed = vec![0u64; rows * cols + 2];
        for i in 0..self.samples {
            let (u, u_lobe) = uniforms(self.seed, i);
            let cell = match sample(u, u_lobe) {
                None => none,
                Some(w) => {
                    if !w.is_finite() || (w.length() - 1.0).abs() > 1e-3 {
                        return Err(format!(
                            "chi-square: sample {i} (u = {u}, u_lobe = {u_lobe}) is not a unit \
                             direction: {w}"
                        ));
                    }
                    self.cell_of(&frame, w)
                }
            };
            observed[cell] += 1;
        }

        // Expected counts: N ∫_cell p dω.
        let n = self.samples as f64;
        let bad = Cell::new(None);
        let mut expected = vec![0.0f64; rows * cols + 2];
        let z_min = self.cos_theta_min as f64;
        let tau = std::f64::consts::TAU;
        for r in 0..rows {
            let z0 = z_min + (1.0 - z_min) * r as f64 / rows as f64;
            let z1 = z_min + (1.0 - z_min) * (r + 1) as f64 / rows as f64;
            for c in 0..cols {
                let p0 = tau * c as f64 / cols as f64;
                let p1 = tau * (c + 1) as f64 / cols as f64;
                expected[r * cols + c] =
                    n * integrate_cell(&pdf, &bad, &frame, [z0, z1, p0, p1], n);
            }
        }
        if z_min > -1.0 {
            // The rest of the sphere, integrated on the same kind of grid.
            for r in 0..rows {
                let z0 = -1.0 + (z_min + 1.0) * r as f64 / rows as f64;
                let z1 = -1.0 + (z_min + 1.0) * (r + 1) as f64 / rows as f64;
                for c in 0..cols {
                    let p0 = tau * c as f64 / cols as f64;
                    let p1 = tau * (c + 1) as f64 / cols as f64;
                    expected[outside] +=
                        n * integrate_cell(&pdf, &bad, &frame, [z0, z1, p0, p1], n);
                }
            }
        }
        if let Some((w, p)) = bad.get() {
            return Err(format!("chi-square: the pdf is {p} at direction {w}"));
        }
        let total = expected.iter().sum::<f64>() / n;
        if total > 1.0 + 1e-3 {
            return Err(format!(
                "chi-square: the pdf integrates to {total:.5} over the sphere; a density of \
                 directions integrates to at most 1"
            ));
        }
        expected[none] = n * (1.0 - total).max(0.0);

        let label = |k: usize| -> String {
            if k == none {
                "no sample (None)".to_string()
            } else if k == outside {
                format!("outside the cap cos θ < {:.4}", self.cos_theta_min)
            } else {
                let (r, c) = (k / cols, k % cols);
                let z = |r: usize| z_min + (1.0 - z_min) * r as f64 / rows as f64;
                let phi = |c: usize| 360.0 * c as f64 / cols as f64;
                format!(
                    "cell (row {r}, col {c}): cos θ ∈ [{:.4}, {:.4}], φ ∈ [{:.1}°, {:.1}°]",
                    z(r),
                    z(r + 1),
                    phi(c),
                    phi(c + 1)
                )
            }
        };
        let threshold = sidak(self.significance, self.tests);
        let mut report = goodness_of_fit(&observed, &expected, threshold, &label).map_err(|e| {
            format!(
                "chi-square test of a direction sampler (axis {}, {rows}×{cols} cells, N = {}, \
                 seed {}) failed: {e}\n{}",
                self.axis,
                self.samples,
                self.seed,
                deviation_map(&observed, &expected, rows, cols)
            )
        })?;
        report.no_sample = observed[none];
        Ok(report)
    }

    /// The cell of a unit direction.
    fn cell_of(&self, frame: &Frame, w: Vec3A) -> usize {
        let (rows, cols) = (self.cos_theta_res, self.phi_res);
        let l = frame.to_local(w);
        let z = (l.z as f64).clamp(-1.0, 1.0);
        let z_min = self.cos_theta_min as f64;
        if z < z_min {
            return rows * cols;
        }
        let row = (((z - z_min) / (1.0 - z_min)) * rows as f64) as usize;
        let mut phi = (l.y as f64).atan2(l.x as f64);
        if phi < 0.0 {
            phi += std::f64::consts::TAU;
        }
        let col = (phi / std::f64::consts::TAU * cols as f64) as usize;
        row.min(rows - 1) * cols + col.min(cols - 1)
    }
}

/// `∫ p dω` over the cell `[z0, z1] × [φ0, φ1]` (local coordinates of
/// `frame`), by tensor Simpson rules refined until successive results agree
/// to within 0.01 √E of the expected count `E` (out of `n` samples).
fn integrate_cell(
    pdf: &impl Fn(Vec3A) -> f32,
    bad: &Cell<Option<(Vec3A, f32)>>,
    frame: &Frame,
    [z0, z1, p0, p1]: [f64; 4],
    n: f64,
) -> f64 {
    let simpson = |m: usize| -> f64 {
        let (hz, hp) = ((z1 - z0) / m as f64, (p1 - p0) / m as f64);
        let weight = |i: usize| -> f64 {
            if i == 0 || i == m {
                1.0
            } else if i % 2 == 1 {
                4.0
            } else {
                2.0
            }
        };
        let mut sum = 0.0;
        for i in 0..=m {
            let z = z0 + i as f64 * hz;
            let s = (1.0 - z * z).max(0.0).sqrt();
            let mut row = 0.0;
            for j in 0..=m {
                let phi = p0 + j as f64 * hp;
                let local = Vec3A::new((s * phi.cos()) as f32, (s * phi.sin()) as f32, z as f32);
                let w = frame.to_world(local);
                let p = pdf(w);
                if !(p >= 0.0 && p.is_finite()) {
                    bad.set(Some((w, p)));
                    continue;
                }
                row += weight(j) * p as f64;
            }
            sum += weight(i) * row;
        }
        sum * hz * hp / 9.0
    };
    let mut m = 16;
    let mut previous = simpson(m);
    loop {
        m *= 2;
        let current = simpson(m);
        let tolerance = 0.01 * (current * n).max(1.0).sqrt();
        if (current - previous).abs() * n <= tolerance || m >= 256 {
            return current;
        }
        previous = current;
    }
}

/// Pearson's test on cells with observed and expected counts: pools the cells
/// with `E < 5`, computes the statistic and its p-value, and fails if the
/// p-value is below `threshold`, naming the cells that contribute most.
fn goodness_of_fit(
    observed: &[u64],
    expected: &[f64],
    threshold: f64,
    label: &dyn Fn(usize) -> String,
) -> Result<Chi2Report, String> {
    let n: u64 = observed.iter().sum();
    for (k, (&o, &e)) in observed.iter().zip(expected).enumerate() {
        if e <= 0.0 && o as f64 > n as f64 * 1e-5 {
            return Err(format!(
                "{o} samples fell where the pdf is zero: {}",
                label(k)
            ));
        }
    }
    // Cells in order of expected count; pool from the smallest until both
    // the cells left and the pool expect at least 5.
    let mut order: Vec<usize> = (0..observed.len())
        .filter(|&k| expected[k] > 0.0 || observed[k] > 0)
        .collect();
    order.sort_by(|&a, &b| expected[a].total_cmp(&expected[b]));
    let (mut pool_o, mut pool_e, mut pooled) = (0.0f64, 0.0f64, 0usize);
    let mut contributions: Vec<(f64, usize)> = Vec::new();
    let mut statistic = 0.0;
    let mut cells = 0usize;
    for &k in &order {
        if expected[k] < 5.0 || (pooled > 0 && pool_e < 5.0) {
            pool_o += observed[k] as f64;
            pool_e += expected[k];
            pooled += 1;
        } else {
            let d = observed[k] as f64 - expected[k];
            let c = d * d / expected[k];
            statistic += c;
            contributions.push((c, k));
            cells += 1;
        }
    }
    if pooled > 0 {
        if pool_e <= 0.0 {
            return Err(format!("{pool_o} samples fell where the pdf is zero"));
        }
        let d = pool_o - pool_e;
        statistic += d * d / pool_e;
        cells += 1;
    }
    let dof = cells.saturating_sub(1);
    let p_value = chi2_survival(statistic, dof);
    let report = Chi2Report {
        statistic,
        dof,
        p_value,
        threshold,
        cells,
        pooled,
        samples: n,
        no_sample: 0,
    };
    if p_value >= threshold {
        return Ok(report);
    }
    contributions.sort_by(|a, b| b.0.total_cmp(&a.0));
    let mut msg = format!(
        "χ² = {statistic:.1} with {dof} degrees of freedom, p = {p_value:.3e} < {threshold:.3e} \
         (pooled {pooled} cells: observed {pool_o}, expected {pool_e:.1}). Worst cells:"
    );
    for &(c, k) in contributions.iter().take(6) {
        msg += &format!(
            "\n  {}: observed {}, expected {:.1} (χ² term {c:.1})",
            label(k),
            observed[k],
            expected[k]
        );
    }
    Err(msg)
}

/// A map of the deviations `(O − E)/√E` per cell, one text row per `cos θ`
/// row (top row = `cos θ` near 1): `.` within 2σ, `+`/`-` within 4σ,
/// `#`/`=` beyond (too many / too few samples).
fn deviation_map(observed: &[u64], expected: &[f64], rows: usize, cols: usize) -> String {
    let mut map =
        String::from("deviation map (rows: cos θ from 1 down; '#' too many, '=' too few):");
    for r in (0..rows).rev() {
        map.push_str("\n  ");
        for c in 0..cols {
            let k = r * cols + c;
            let (o, e) = (observed[k] as f64, expected[k]);
            let z = if e > 0.0 {
                (o - e) / e.sqrt()
            } else if o > 0.0 {
                99.0
            } else {
                0.0
            };
            map.push(match z {
                z if z > 4.0 => '#',
                z if z > 2.0 => '+',
                z if z < -4.0 => '=',
                z if z < -2.0 => '-',
                _ => '.',
            });
        }
    }
    map
}

/// A chi-square test of discrete frequencies (e.g. how often a lobe is
/// chosen): `observed[k]` outcomes of kind `k` against probabilities
/// `probabilities[k]` (summing to one), at family level `significance` over
/// `tests` tests.
pub fn chi2_frequencies(
    observed: &[u64],
    probabilities: &[f64],
    significance: f64,
    tests: usize,
) -> Result<Chi2Report, String> {
    if observed.len() != probabilities.len() || observed.is_empty() {
        return Err("chi-square: as many probabilities as outcomes are needed".to_string());
    }
    let sum: f64 = probabilities.iter().sum();
    if probabilities.iter().any(|p| p.is_nan() || *p < 0.0) || (sum - 1.0).abs() > 1e-6 {
        return Err(format!(
            "chi-square: probabilities {probabilities:?} are not a distribution"
        ));
    }
    let n: u64 = observed.iter().sum();
    let expected: Vec<f64> = probabilities.iter().map(|p| p * n as f64).collect();
    let label = |k: usize| format!("outcome {k} (probability {:.6})", probabilities[k]);
    goodness_of_fit(observed, &expected, sidak(significance, tests), &label)
        .map_err(|e| format!("chi-square test of frequencies failed: {e}"))
}

/// Checks that a sampler's own reported pdf equals the pdf function at each
/// of `samples` samples: `sample(u, u_lobe)` returns a direction and the pdf
/// it reports; they must agree within `rel_tol` (relative to the larger), and
/// the reported pdf must be positive and finite. The uniform numbers are the
/// ones of [`Chi2Test::run`] for the same seed. Returns the number of samples
/// checked (refused samples are skipped).
pub fn check_sample_pdfs(
    samples: u64,
    seed: u64,
    mut sample: impl FnMut(Vec2, f32) -> Option<(Vec3A, f32)>,
    pdf: impl Fn(Vec3A) -> f32,
    rel_tol: f32,
) -> Result<u64, String> {
    let mut checked = 0;
    let mut failures = Vec::new();
    let mut failed = 0u64;
    for i in 0..samples {
        let (u, u_lobe) = uniforms(seed, i);
        let Some((w, reported)) = sample(u, u_lobe) else {
            continue;
        };
        checked += 1;
        let p = pdf(w);
        let ok = reported > 0.0
            && reported.is_finite()
            && (reported - p).abs() <= rel_tol * reported.max(p);
        if !ok {
            failed += 1;
            if failures.len() < 5 {
                failures.push(format!(
                    "  sample {i} (u = {u}, u_lobe = {u_lobe}): direction {w}, sampled pdf \
                     {reported}, pdf function {p}"
                ));
            }
        }
    }
    if failed > 0 {
        return Err(format!(
            "{failed} of {checked} samples report a pdf that differs from the pdf function \
             (relative tolerance {rel_tol}):\n{}",
            failures.join("\n")
        ));
    }
    Ok(checked)
}
