//! Unit tests of `integrator/shading_normals.rs`.

use raytracer::frame::Frame;
use raytracer::geometry::Interaction;
use raytracer::integrator::shading_normals::*;
use raytracer::math::Vec2;
use raytracer::math::Vec3A;

fn interaction(ng: Vec3A, ns: Vec3A) -> Interaction {
    Interaction {
        p: Vec3A::ZERO,
        ng,
        frame: Frame::from_normal(ns),
        uv: Vec2::ZERO,
        wo: Vec3A::Y,
        t: 1.0,
        shape: 0,
        p_error: Vec3A::ZERO,
    }
}

/// 1 for a flat surface; Veach's ratio for a tilted shading normal,
/// which makes the adjoint reciprocal: `f* |·n_s|` with the correction
/// equals the radiance factor with the directions swapped, times
/// `|ω_i·n_g| / |ω_o·n_g|` — the change of the geometric cosines that
/// the path's G terms carry.
#[test]
fn one_when_flat_and_veachs_ratio_when_tilted() {
    let (wo, wi) = (
        Vec3A::new(0.3, 0.8, 0.1).normalize(),
        Vec3A::new(-0.5, 0.4, 0.2).normalize(),
    );
    assert_eq!(
        importance_correction(&interaction(Vec3A::Y, Vec3A::Y), wo, wi),
        1.0
    );
    let ns = Vec3A::new(0.2, 1.0, 0.0).normalize();
    let it = interaction(Vec3A::Y, ns);
    let c = importance_correction(&it, wo, wi);
    let expect = wo.dot(ns).abs() * wi.y.abs() / (wo.y.abs() * wi.dot(ns).abs());
    assert!((c - expect).abs() < 1e-6 && (c - 1.0).abs() > 0.05, "{c}");
    // Grazing the geometric surface: no transport.
    assert_eq!(importance_correction(&it, Vec3A::X, wi), 0.0);
}
