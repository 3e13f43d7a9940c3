//! Unit tests of `integrator/photon_map.rs`.

use raytracer::brdf::Brdf;
use raytracer::brdf::{Lambert, Texture};
use raytracer::frame::Frame;
use raytracer::geometry::Interaction;
use raytracer::integrator::photon::Photon;
use raytracer::integrator::photon_map::*;
use raytracer::math::{Color, PI, Vec3A};
use raytracer::math::{Vec2, Vec3};

/// The kernel integrates to one over its disk (midpoint rule in rings).
#[test]
fn the_kernel_is_normalised() {
    let r = 0.3f32;
    let n = 10_000;
    let sum: f64 = (0..n)
        .map(|i| {
            let d = (i as f32 + 0.5) / n as f32 * r;
            (epanechnikov(d * d, r * r) * 2.0 * PI * d * r / n as f32) as f64
        })
        .sum();
    assert!((sum - 1.0).abs() < 1e-4, "{sum}");
    assert_eq!(epanechnikov(0.1, 0.1), 0.0);
}

/// Photons spread uniformly (density λ per unit area, irradiance E = λΦ)
/// on a white Lambert plane give L_r = ρE/π by k nearest and by radius:
/// the mean over 400 points within 3% (each estimate averages about k
/// photons; 400 of them put the relative standard error near 1%).
#[test]
fn uniform_photons_give_the_lambert_radiance() {
    let (n, side) = (200_000, 4.0f32);
    // Independent uniform points (a Poisson process: the kernel's
    // unbiasedness holds for it, not for an evenly spread lattice).
    let uniform = |seed: u64, i: u32| raytracer::sampling::chi2::uniforms(seed, i as u64).0;
    let photons: Vec<Photon> = (0..n)
        .map(|i| {
            let u = uniform(9, i);
            Photon {
                p: Vec3::new((u.x - 0.5) * side, 0.0, (u.y - 0.5) * side),
                wi: Vec3::new(0.3, 0.9, 0.1).normalize(),
                power: Vec3::splat(1.0 / n as f32),
                segments: 2,
            }
        })
        .collect();
    let e = 1.0 / (side * side);
    let rho = 0.6;
    let brdf = Brdf::Lambert(Lambert {
        albedo: Texture::Constant(Color::splat(rho)),
    });
    let map = PhotonMap::build(photons.clone(), 0.2);
    for search in [
        Search::Nearest {
            k: 50,
            max_radius: 0.2,
        },
        Search::Radius(0.05),
    ] {
        let mut sum = 0.0;
        for i in 0..400 {
            let u = uniform(10, i);
            let it = Interaction {
                p: Vec3A::new((u.x - 0.5) * 3.0, 0.0, (u.y - 0.5) * 3.0),
                ng: Vec3A::Y,
                frame: Frame::from_normal(Vec3A::Y),
                uv: Vec2::ZERO,
                wo: Vec3A::new(0.0, 1.0, 0.0),
                t: 1.0,
                shape: 0,
                p_error: Vec3A::ZERO,
            };
            sum += map.radiance(&it, &brdf, search, |_| true).x;
        }
        let got = sum / 400.0;
        let want = rho * e / PI;
        assert!(
            (got / want - 1.0).abs() < 0.03,
            "{search:?}: {got} vs {want}"
        );
    }
    assert!(radius_for(&photons, 50, 1.0) > 0.01);
}
