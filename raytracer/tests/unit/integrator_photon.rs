//! Unit tests of `integrator/photon.rs`.

use raytracer::integrator::photon::*;
use raytracer::scene::Scene;
use std::sync::atomic::AtomicBool;

fn tracing(paths: u64, seed: u64) -> PhotonTracing {
    PhotonTracing {
        paths,
        max_depth: Some(6),
        rr_depth: 100,
        seed,
        stream: 0,
    }
}

/// The same photons on one thread or several, in the same order; a
/// stop request keeps whole batches.
#[test]
fn photons_do_not_depend_on_the_threads() {
    let scene = Scene::builtin("cornell").unwrap();
    let run = |threads| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| trace_photons(&scene, &tracing(5000, 3), &AtomicBool::new(false)))
    };
    let (a, b) = (run(1), run(3));
    assert_eq!(a.paths, 5000);
    assert!(a.len() > 5000);
    assert_eq!(a.indirect, b.indirect);
    assert_eq!(a.direct, b.direct);
    let stopped = trace_photons(&scene, &tracing(5000, 3), &AtomicBool::new(true));
    assert!(stopped.interrupted && stopped.paths == 0 && stopped.is_empty());
}

/// In the closed furnace (L_e = 0.5, ρ = 0.5 on a sphere of area 4π,
/// emitting inwards: Φ = π L_e A = 2π² W), the photons of depth k carry
/// on average Φ ρ^(k−1): 40 000 paths, each depth's total within 4% (its
/// relative standard error is below 0.6%: false failure < 1e-9).
#[test]
fn photon_power_in_the_furnace_is_the_emitted_flux_times_the_albedo() {
    let scene = Scene::builtin("furnace").unwrap();
    let t = trace_photons(&scene, &tracing(40_000, 5), &AtomicBool::new(false));
    let phi = 2.0 * std::f32::consts::PI * std::f32::consts::PI;
    assert!(t.caustic.is_empty());
    let total = |k: u32| -> f32 {
        t.direct
            .iter()
            .chain(&t.indirect)
            .filter(|p| p.segments == k)
            .map(|p| p.power.x)
            .sum()
    };
    for k in 1..=5 {
        let expected = phi * 0.5f32.powi(k as i32 - 1);
        assert!(
            (total(k) / expected - 1.0).abs() < 0.04,
            "k = {k}: {}",
            total(k)
        );
    }
    assert_eq!(
        total(6),
        0.0,
        "D = 6 leaves one camera segment: photons of ≤ 5 segments"
    );
    assert!(t.direct.iter().all(|p| p.segments == 1));
}
