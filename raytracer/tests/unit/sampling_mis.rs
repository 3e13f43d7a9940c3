//! Unit tests of `sampling/mis.rs`.

use raytracer::sampling::mis::*;

#[test]
fn weights_sum_to_one() {
    for &(a, b) in &[(0.3f32, 2.0f32), (1.0, 1.0), (5.0, 1e-3), (1e-6, 1e3)] {
        let s = power_heuristic(1.0, a, 1.0, b) + power_heuristic(1.0, b, 1.0, a);
        assert!((s - 1.0).abs() < 1e-6);
        let s = balance_heuristic(2.0, a, 1.0, b) + balance_heuristic(1.0, b, 2.0, a);
        assert!((s - 1.0).abs() < 1e-6);
    }
    assert_eq!(power_heuristic(1.0, 0.0, 1.0, 0.0), 0.0);
    assert_eq!(power_heuristic(1.0, f32::INFINITY, 1.0, 3.0), 1.0);
}
