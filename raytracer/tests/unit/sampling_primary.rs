//! Unit tests of `sampling/primary.rs`.

use raytracer::sampling::Sampler;
use raytracer::sampling::primary::*;

fn read(p: &mut PrimarySample, dims: u32) -> Vec<f32> {
    (0..dims).map(|d| p.coordinate(d)).collect()
}

#[test]
fn the_start_is_the_hashed_samplers_sequence() {
    let mut p = PrimarySample::new(3, 4, 5, 0.01);
    let mut s = Sampler::new(3, 4, 5);
    // Read out of order, with a gap: the values are the addresses'.
    let seven = p.coordinate(7);
    let first = read(&mut p, 10);
    let expected: Vec<f32> = (0..10).map(|_| s.next_1d()).collect();
    assert_eq!(first, expected);
    assert_eq!(seven, expected[7]);
    // Through a sampler, in the camera stream: coordinates 0, 3, 6, 9.
    let mut primary = Sampler::primary(PrimarySample::new(3, 4, 5, 0.01));
    let drawn: Vec<f32> = (0..4).map(|_| primary.next_1d()).collect();
    assert_eq!(drawn, [0, 3, 6, 9].map(|d| expected[d]));
}

#[test]
fn from_coordinates_reads_the_values_then_the_address() {
    let mut p = PrimarySample::from_coordinates(&[0.25, 0.5], 3, 4, 5);
    let mut s = Sampler::new(3, 4, 5);
    let expected: Vec<f32> = (0..4).map(|_| s.next_1d()).collect();
    assert_eq!(read(&mut p, 4), vec![0.25, 0.5, expected[2], expected[3]]);
}

#[test]
fn reject_restores_and_accept_keeps() {
    let mut p = PrimarySample::new(1, 2, 3, 0.05);
    let start = read(&mut p, 6);
    p.propose_small(9, 0, 1);
    let moved = read(&mut p, 4);
    assert!(moved.iter().zip(&start).all(|(a, b)| a != b));
    p.reject();
    assert_eq!(read(&mut p, 6), start, "reading after a reject");
    p.propose_large(9, 0, 2);
    let fresh = read(&mut p, 3);
    let mut s = Sampler::new(9, 0, 2);
    assert_eq!(fresh, (0..3).map(|_| s.next_1d()).collect::<Vec<_>>());
    p.accept();
    // The large step is the state now, also for coordinates it did not
    // read: coordinate 4 is number 4 of that step's address.
    let mut s = Sampler::new(9, 0, 2);
    let expected: Vec<f32> = (0..6).map(|_| s.next_1d()).collect();
    p.propose_small(9, 0, 3);
    p.reject();
    assert_eq!(read(&mut p, 6), expected);
}

/// Small steps are wrapped normal moves of deviation σ, σ√n for a
/// coordinate that sat out n − 1 steps. 20 000 moves each: the standard
/// error of a variance is √2/√20000 ≈ 1% of it; 6% is 6 standard errors
/// (false failure < 1e-8). The mean displacement (standard error
/// σ/141) within 6 standard errors of 0.
#[test]
fn small_steps_have_deviation_sigma_root_n() {
    let sigma = 0.02f32;
    for n in [1u64, 4] {
        let (mut sum, mut sum_sq) = (0.0f64, 0.0f64);
        let count = 20_000;
        for chain in 0..count {
            let mut p = PrimarySample::new(5, chain, 0, sigma);
            let before = p.coordinate(0);
            for k in 1..n {
                // Steps that read another coordinate only.
                p.propose_small(6, chain, k);
                p.coordinate(1);
                p.accept();
            }
            p.propose_small(6, chain, n);
            let after = p.coordinate(0);
            let mut d = (after - before) as f64;
            d -= d.round();
            sum += d;
            sum_sq += d * d;
        }
        let mean = sum / count as f64;
        let var = sum_sq / count as f64 - mean * mean;
        let expected = (sigma as f64).powi(2) * n as f64;
        let se_mean = expected.sqrt() / (count as f64).sqrt();
        assert!(mean.abs() < 6.0 * se_mean, "n = {n}: mean {mean}");
        assert!(
            (var / expected - 1.0).abs() < 0.06,
            "n = {n}: variance {var}, expected {expected}"
        );
    }
}

#[test]
fn coordinates_stay_in_the_unit_interval() {
    assert_eq!(wrap(-1e-9), ONE_MINUS_EPSILON);
    assert_eq!(wrap(1.25), 0.25);
    assert_eq!(wrap(-0.25), 0.75);
    let mut p = PrimarySample::new(0, 0, 0, 0.3);
    for t in 1..2000 {
        if t % 7 == 0 {
            p.propose_large(1, 0, t);
        } else {
            p.propose_small(2, 0, t);
        }
        for d in 0..8 {
            let v = p.coordinate(d);
            assert!((0.0..1.0).contains(&v), "{v}");
        }
        if t % 3 == 0 { p.reject() } else { p.accept() }
    }
}
