//! Statistics shared by the Monte Carlo tests of the lights.

/// Mean and standard error of the mean of `values`.
pub fn mean_and_stderr(values: &[f64]) -> (f64, f64) {
    let n = values.len() as f64;
    let mean = values.iter().sum::<f64>() / n;
    let var = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0);
    (mean, (var / n).sqrt())
}

/// Asserts that a Monte Carlo mean matches `exact` within 5 standard
/// errors (a false failure has probability < 1e-6 under the normal
/// approximation), and that the estimate is precise enough for the test
/// to mean something (standard error below `max_rel_se` of `exact`).
/// A zero standard error (a constant estimator) leaves a relative
/// rounding slack of 1e-4.
pub fn assert_matches(what: &str, values: &[f64], exact: f64, max_rel_se: f64) {
    let (mean, se) = mean_and_stderr(values);
    assert!(
        se <= max_rel_se * exact.abs(),
        "{what}: standard error {se} too large for {exact}"
    );
    eprintln!("{what}: {mean:.6} ± {se:.6} (exact {exact:.6})");
    let tol = 5.0 * se + 1e-4 * exact.abs();
    assert!(
        (mean - exact).abs() <= tol,
        "{what}: estimate {mean} ± {se} vs exact {exact}"
    );
}
