//! Unit tests of `brdf/mod.rs`.

use super::brdf_testing::{check_pdfs, check_reciprocity, dir};
use glass::Glass;
use lambert::Lambert;
use mirror::Mirror;
use phong::Phong;
use raytracer::brdf::*;
use raytracer::math::{Color, Vec2};
use texture::Texture;

fn models() -> Vec<Brdf> {
    vec![
        Brdf::Lambert(Lambert {
            albedo: Texture::Constant(Color::new(0.8, 0.5, 0.2)),
        }),
        Brdf::Phong(Phong {
            albedo: Color::splat(0.7),
            exponent: 20.0,
        }),
        Brdf::Mirror(Mirror {
            reflectance: Color::ONE,
        }),
    ]
}

/// A one-sided model is its two-sided model from the front (eval, pdf
/// and samples bit for bit), and black from behind: zero `f_r` and pdf
/// for every pair with a direction below, no sample. Reciprocity holds
/// and the sampled pdfs agree with `pdf`. (Before, every model was
/// two-sided and `cornell`'s lamp reflected from its back.)
#[test]
fn one_sided_is_the_model_in_front_and_black_behind() {
    let uv = Vec2::new(0.3, 0.6);
    for two in models() {
        let one = two.clone().one_sided();
        assert!(one.is_one_sided() && !two.is_one_sided());
        assert_eq!(one.is_delta(), two.is_delta());
        assert!(one.clone().one_sided().is_one_sided(), "idempotent");
        for (k, theta_o) in [0.0f32, 40.0, 85.0].into_iter().enumerate() {
            let wo = dir(theta_o);
            let below = flip_z(wo);
            for i in 0..256u32 {
                let u = Vec2::new((i % 16) as f32 / 16.0 + 0.01, (i / 16) as f32 / 16.0 + 0.02);
                let a = one.sample(wo, uv, 0.5, u, TransportMode::Radiance);
                let b = two.sample(wo, uv, 0.5, u, TransportMode::Radiance);
                assert_eq!(a, b, "{two:?}: front sample");
                assert_eq!(one.sample(below, uv, 0.5, u, TransportMode::Radiance), None);
                let wi = dir(5.0 + 0.3 * i as f32);
                assert_eq!(one.eval(wo, wi, uv), two.eval(wo, wi, uv));
                assert_eq!(one.pdf(wo, wi, uv), two.pdf(wo, wi, uv));
                for (x, y) in [(below, wi), (wo, flip_z(wi)), (below, flip_z(wi))] {
                    assert_eq!(one.eval(x, y, uv), Color::ZERO, "{two:?} from behind");
                    assert_eq!(one.pdf(x, y, uv), 0.0);
                }
                // The two-sided model is not black from behind.
                if !two.is_delta() && k == 0 {
                    assert!(two.eval(below, flip_z(wo), uv).max_element() > 0.0);
                }
            }
            if !one.is_delta() {
                check_pdfs(&one, wo).unwrap();
            }
        }
        if !one.is_delta() {
            check_reciprocity(&one);
        }
    }
    let glass = Brdf::Glass(Glass {
        ior: 1.5,
        tint: Color::ONE,
    });
    assert!(
        !glass.one_sided().is_one_sided(),
        "glass keeps its two sides"
    );
}
