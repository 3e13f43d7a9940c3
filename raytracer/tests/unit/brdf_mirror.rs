//! Unit tests of `brdf/mirror.rs`.

use super::brdf_testing::directional_albedo;
use raytracer::brdf::mirror::*;
use raytracer::brdf::{Brdf, TransportMode};
use raytracer::math::{Color, Vec3A};
use raytracer::math::{Vec2, reflect};

#[test]
fn reflects_about_the_normal_from_either_side() {
    let m = Brdf::Mirror(Mirror {
        reflectance: Color::new(0.9, 0.8, 0.7),
    });
    for wo in [
        Vec3A::new(0.3, 0.4, 0.866).normalize(),
        Vec3A::new(-0.7, 0.1, -0.2).normalize(),
        Vec3A::Z,
    ] {
        let s = m
            .sample(
                wo,
                Vec2::ZERO,
                0.3,
                Vec2::new(0.1, 0.2),
                TransportMode::Radiance,
            )
            .unwrap();
        let n = Vec3A::new(0.0, 0.0, wo.z.signum());
        assert!((s.wi - reflect(wo, n)).length() < 1e-6, "{wo} -> {}", s.wi);
        assert!(s.is_delta && s.pdf_w == 1.0 && s.eta == 1.0);
        let weight = s.f * s.wi.z.abs() / s.pdf_w;
        assert!((weight - Color::new(0.9, 0.8, 0.7)).abs().max_element() < 1e-6);
        assert_eq!(m.eval(wo, s.wi, Vec2::ZERO), Color::ZERO);
        assert_eq!(m.pdf(wo, s.wi, Vec2::ZERO), 0.0);
    }
    assert!(m.is_delta());
    // Grazing: no reflection can be formed.
    assert!(
        m.sample(
            Vec3A::X,
            Vec2::ZERO,
            0.3,
            Vec2::ZERO,
            TransportMode::Radiance
        )
        .is_none()
    );
}

#[test]
fn albedo_is_the_reflectance() {
    let r = Color::new(1.0, 0.5, 0.25);
    let m = Brdf::Mirror(Mirror { reflectance: r });
    for theta in [0.0f32, 45.0, 89.0] {
        let t = theta.to_radians();
        let wo = Vec3A::new(t.sin(), 0.0, t.cos());
        let (mean, _) = directional_albedo(wo, 256, 1, |wo, ul, u| {
            m.sample(wo, Vec2::ZERO, ul, u, TransportMode::Radiance)
        });
        assert!((mean - r).abs().max_element() < 1e-5, "{theta}: {mean}");
    }
}
