//! Unit tests of `light/mod.rs`.

use area::{AreaLight, AreaShape};
use environment::{EnvironmentLight, EnvironmentMap};
use point::PointLight;
use raytracer::geometry::{Quad, Sphere};
use raytracer::light::*;
use raytracer::math::{Color, RayPdf, Vec3A};
use raytracer::sampling::Sampler;
use std::sync::Arc;

fn all_lights() -> Vec<Light> {
    let quad = Quad {
        origin: Vec3A::new(-0.5, 2.0, -0.5),
        e1: Vec3A::X,
        e2: Vec3A::Z,
    };
    let sphere = Sphere {
        center: Vec3A::new(1.0, 1.0, 0.0),
        radius: 0.25,
    };
    let mut pixels = vec![Color::splat(0.5); 16 * 8];
    pixels[3 * 16 + 2] = Color::splat(100.0);
    let map = EnvironmentMap {
        width: 16,
        height: 8,
        pixels,
    };
    vec![
        Light::Area(AreaLight {
            shape: AreaShape::Quad(quad),
            radiance: Color::ONE,
            two_sided: false,
        }),
        Light::Area(AreaLight {
            shape: AreaShape::Sphere(sphere),
            radiance: Color::ONE,
            two_sided: true,
        }),
        Light::Point(PointLight {
            position: Vec3A::new(0.0, 1.5, 0.5),
            intensity: Color::ONE,
        }),
        Light::Environment(EnvironmentLight::new(Color::ONE, None)),
        Light::Environment(EnvironmentLight::new(Color::ONE, Some(Arc::new(map)))),
    ]
}

/// Through the enum, for every light type and several receivers:
/// `pdf_li_w` of each sample's direction equals the sample's `pdf_w`
/// (relative 1e-3; point lights report 0, no BRDF sample hits them), and
/// `pdf_le` agrees with each emission.
#[test]
fn every_light_reports_the_density_it_samples() {
    let receivers = [
        Vec3A::ZERO,
        Vec3A::new(0.9, 1.1, 0.1),
        Vec3A::new(-2.0, 0.5, 3.0),
    ];
    for (k, light) in all_lights().iter().enumerate() {
        assert_eq!(light.is_delta(), matches!(light, Light::Point(_)));
        assert_eq!(
            light.is_environment(),
            matches!(light, Light::Environment(_))
        );
        for p in receivers {
            let mut got = 0;
            for i in 0..4096 {
                let Some(s) = light.sample_li(p, Sampler::new(90 + k as u64, i, 0).next_2d())
                else {
                    continue;
                };
                got += 1;
                let pdf = light.pdf_li_w(p, s.p, s.n, s.wi);
                if light.is_delta() {
                    assert!(s.is_delta && s.pdf_w == 1.0 && pdf == 0.0);
                } else {
                    assert!(
                        (pdf - s.pdf_w).abs() <= 1e-3 * s.pdf_w,
                        "light {k} from {p}: {pdf} vs {}",
                        s.pdf_w
                    );
                }
            }
            assert!(got > 0, "light {k} lights {p}");
        }
        for i in 0..4096 {
            let mut smp = Sampler::new(99, i, k as u64);
            let Some(e) = light.sample_le(smp.next_2d(), smp.next_2d()) else {
                continue;
            };
            let RayPdf { pdf_a, pdf_w } = light.pdf_le(e.p, e.n, e.ray.d);
            assert!((pdf_a - e.pdf_a).abs() <= 1e-4 * e.pdf_a, "light {k}");
            assert!((pdf_w - e.pdf_w).abs() <= 1e-3 * e.pdf_w, "light {k}");
            assert_eq!(e.is_delta_position, light.is_delta());
        }
        assert!(light.power().min_element() > 0.0);
    }
}
