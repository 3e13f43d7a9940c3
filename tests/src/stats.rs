//! Statistics and output shared by the graders: running mean and variance of
//! a student's estimates, the z-test of a mean against an exact value, and
//! where failing images go.
//!
//! Tolerances (the false-failure probability of each is stated where it is
//! used): a mean of `M ≥ 1000` independent estimates is tested with
//! `z = (mean − exact) / (s/√M)` against [`Z_MAX`] = 5.5, where `s` is the
//! *student's own* sample standard deviation; for a correct estimator `z`
//! is close to standard normal, and `P(|z| > 5.5) ≈ 4e-8` per channel.
//! Differences below `1e-4` (relative) pass regardless: f32 rounding of a
//! zero-variance estimator (Lambert under cosine sampling) is not an error.

use std::path::PathBuf;

use raytracer::math::{Color, Vec3A};

/// Largest `|z|` a correct estimator may show: two-sided normal tail
/// `P(|z| > 5.5) ≈ 3.8e-8` per test (with M ≥ 1000 estimates the sample
/// variance is accurate enough that the t-distribution's tail is < 1e-7).
pub const Z_MAX: f64 = 5.5;

/// Running mean and variance (Welford) per channel, in `f64`.
#[derive(Clone, Copy, Debug, Default)]
pub struct MeanVar {
    n: u64,
    mean: [f64; 3],
    m2: [f64; 3],
    nonfinite: u64,
}

impl MeanVar {
    pub fn add(&mut self, c: Color) {
        if !c.is_finite() {
            self.nonfinite += 1;
            return;
        }
        self.n += 1;
        for k in 0..3 {
            let x = c[k] as f64;
            let d = x - self.mean[k];
            self.mean[k] += d / self.n as f64;
            self.m2[k] += d * (x - self.mean[k]);
        }
    }

    pub fn count(&self) -> u64 {
        self.n
    }

    pub fn mean(&self) -> [f64; 3] {
        self.mean
    }

    /// The standard error of the mean per channel, `s/√n`.
    pub fn std_error(&self) -> [f64; 3] {
        let n = self.n.max(2) as f64;
        self.m2.map(|m2| (m2 / (n - 1.0) / n).sqrt())
    }

    /// Checks the mean against `exact` (see the module doc). `what` names the
    /// case in the failure message; `advice(ratio)` may add a likely cause
    /// from the ratio mean/exact of the worst channel.
    pub fn check(
        &self,
        what: &str,
        exact: Color,
        advice: impl Fn(f64) -> Option<String>,
    ) -> Result<(), String> {
        if self.nonfinite > 0 {
            return Err(format!(
                "{what}: {} of your estimates are NaN or infinite (a division by a zero pdf?)",
                self.nonfinite
            ));
        }
        let se = self.std_error();
        for k in 0..3 {
            let (m, e) = (self.mean[k], exact[k] as f64);
            let d = (m - e).abs();
            // Differences within f32 rounding (1e-4 relative) always pass:
            // an estimator with (nearly) zero variance must be exact up to it.
            let bad = d > 1e-4 * e.abs().max(1.0) && d > Z_MAX * se[k];
            if bad {
                let z = if se[k] > 0.0 {
                    d / se[k]
                } else {
                    f64::INFINITY
                };
                let mut msg = format!(
                    "{what}: your mean is {m:.4} ± {:.4} (channel {k}), expected {e:.4} (|z| = {z:.1} > {Z_MAX})",
                    se[k]
                );
                if e != 0.0
                    && let Some(a) = advice(m / e)
                {
                    msg.push_str(" — ");
                    msg.push_str(&a);
                }
                return Err(msg);
            }
        }
        Ok(())
    }
}

/// `|a − b| ≤ tol · max(1, |b|)` in every component.
pub fn close3(a: Vec3A, b: Vec3A, tol: f32) -> bool {
    (a - b)
        .abs()
        .cmple(Vec3A::splat(tol) * b.abs().max(Vec3A::ONE))
        .all()
}

/// `|a − b| ≤ tol · max(1e-6, |b|)`: relative closeness of scalars.
pub fn close(a: f32, b: f32, tol: f32) -> bool {
    (a - b).abs() <= tol * b.abs().max(1e-6)
}

/// `a / b` near `r` within 2%.
pub fn ratio_near(ratio: f64, r: f64) -> bool {
    (ratio / r - 1.0).abs() < 0.02
}

/// Where the grader writes the images of failed image-based checks:
/// `target/grading/` (`$CARGO_TARGET_DIR/grading/` if set).
pub fn output_dir() -> PathBuf {
    let target = std::env::var_os("CARGO_TARGET_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../target")));
    target.join("grading")
}

/// A colour for messages, 4 decimals.
pub fn fmt3(c: Vec3A) -> String {
    format!("({:.4}, {:.4}, {:.4})", c.x, c.y, c.z)
}
