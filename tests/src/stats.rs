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

    /// Whether the mean of every channel is consistent with `value`: within
    /// [`Z_MAX`] standard errors or 1e-4 relative (the same rule as
    /// [`MeanVar::check`]). Used to recognise a known mistake by the value it
    /// would give.
    pub fn matches(&self, value: Color) -> bool {
        let se = self.std_error();
        self.nonfinite == 0
            && (0..3).all(|k| {
                let (m, e) = (self.mean[k], value[k] as f64);
                let d = (m - e).abs();
                d <= 1e-4 * e.abs().max(1.0) || d <= Z_MAX * se[k]
            })
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
            return Err(crate::tr!("stats.nonfinite", count = self.nonfinite, what));
        }
        let se = self.std_error();
        for k in 0..3 {
            let (m, e) = (self.mean[k], exact[k] as f64);
            let d = (m - e).abs();
            // Differences within f32 rounding (1e-4 relative) always pass:
            // an estimator with (nearly) zero variance must be exact up to it.
            let bad = d > 1e-4 * e.abs().max(1.0) && d > Z_MAX * se[k];
            if bad {
                let mut msg =
                    crate::tr!("stats.mean", deviation = deviation(m, e, se[k]), what, m, e);
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

/// How far a mean `m` with standard error `se` lies from `exact`, in words:
/// the relative error, and the number of standard errors while that number
/// means something. An estimator whose estimates barely vary (a standard
/// error below 1e-6 of the value) gets no |z|, which would be huge or
/// infinite: its difference is not noise.
pub fn deviation(m: f64, exact: f64, se: f64) -> String {
    let rel = if exact != 0.0 {
        crate::tr!(
            "stats.relative",
            percent = 100.0 * (m - exact) / exact.abs()
        )
    } else {
        crate::tr!("stats.error", difference = m - exact)
    };
    if se <= 1e-6 * exact.abs().max(m.abs()).max(1e-12) {
        crate::tr!("stats.no_noise", rel, se = format!("{se:.1e}"))
    } else {
        let z = (m - exact).abs() / se;
        crate::tr!("stats.z", rel, z, Z_MAX)
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
        .unwrap_or_else(|| {
            let tests = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
            tests.parent().unwrap_or(tests).join("target")
        });
    target.join("grading")
}

/// A colour for messages, 4 decimals.
pub fn fmt3(c: Vec3A) -> String {
    format!("({:.4}, {:.4}, {:.4})", c.x, c.y, c.z)
}

/// A known mistake for deterministic answers: what it is called in a
/// message, and what a solution that makes it answers in a case `C`.
pub type Mistake<'a, C, T> = (&'a str, &'a dyn Fn(&C) -> T);

/// The first of `mistakes` whose answers agree with the student's `got`
/// (one per case, in order) in *every* case, by `same(got, answer)`.
/// Checking all cases at once tells apart mistakes that coincide in one
/// case (one cosine missing vs. the distance not squared, where 1/cos θ
/// happens to equal r).
pub fn recognise<C, T: Copy>(
    cases: &[C],
    got: &[T],
    mistakes: &[Mistake<'_, C, T>],
    same: impl Fn(T, T) -> bool,
) -> Option<String> {
    mistakes
        .iter()
        .find(|(_, answer)| cases.iter().zip(got).all(|(c, &g)| same(g, answer(c))))
        .map(|(name, _)| name.to_string())
}
