//! Grader of exercise 3 (textured Lambert): exact values and the directional
//! albedo by a deterministic quadrature.

use raytracer::brdf::Texture;
use raytracer::math::{Color, PI, Vec2, Vec3A};
use raytracer::sampling::warp::cosine_hemisphere;

use crate::stats::{close3, fmt3, ratio_near};

/// The signature of exercise 3.
pub type LambertFn = fn(&Texture, Vec2, Vec3A, Vec3A) -> Color;

/// The directional albedo `∫ f_r cos θ dω` of `f` for a white texture and
/// `wo`, by cosine-weighted quadrature on a stratified 64×64 grid
/// (`f cos θ / (cos θ/π) = π f`): exactly 1 for a correct Lambert, and no
/// noise at all (the integrand is constant).
pub fn quadrature_albedo(f: LambertFn, wo: Vec3A) -> f32 {
    let white = Texture::Constant(Color::ONE);
    let n = 64;
    let mut sum = 0.0f64;
    for j in 0..n {
        for i in 0..n {
            let u = Vec2::new((i as f32 + 0.5) / n as f32, (j as f32 + 0.5) / n as f32);
            let wi = cosine_hemisphere(u);
            sum += (PI * f(&white, Vec2::ZERO, wo, wi).x) as f64;
        }
    }
    (sum / (n * n) as f64) as f32
}

pub fn check(f: LambertFn) -> Result<(), String> {
    let wo = Vec3A::new(0.3, 0.2, 0.93).normalize();
    let albedo = quadrature_albedo(f, wo);
    if (albedo - 1.0).abs() >= 1e-3 {
        let r = albedo as f64;
        let why = if ratio_near(r, PI as f64) {
            crate::tr!("ex03.pi")
        } else if ratio_near(r, 2.0 / 3.0) {
            crate::tr!("ex03.cos_twice")
        } else if ratio_near(r, 1.0 / PI as f64) {
            crate::tr!("ex03.pi_twice")
        } else if ratio_near(r, 0.5) {
            crate::tr!("ex03.half")
        } else if albedo > 1.0 {
            crate::tr!("ex03.brighter", albedo)
        } else {
            crate::tr!("ex03.darker", albedo)
        };
        return Err(crate::tr!("ex03.albedo", albedo, why));
    }
    // The texture is looked up at uv.
    let a = Color::new(0.9, 0.1, 0.1);
    let b = Color::new(0.1, 0.5, 0.9);
    let checker = Texture::Checker { a, b, scale: 4.0 };
    let wi = Vec3A::new(-0.5, 0.1, 0.86).normalize();
    for (uv, c) in [
        (Vec2::new(0.1, 0.1), a),
        (Vec2::new(0.3, 0.1), b),
        (Vec2::new(0.3, 0.3), a),
    ] {
        let got = f(&checker, uv, wo, wi);
        if !close3(got, c / PI, 1e-4) {
            let other = if c == a { b } else { a };
            let why = if close3(got, f(&checker, Vec2::ZERO, wo, wi), 1e-4)
                && close3(got, checker.eval(Vec2::ZERO) / PI, 1e-4)
            {
                crate::tr!("ex03.uv_zero")
            } else if close3(got, other / PI, 1e-4) {
                crate::tr!("ex03.other_square")
            } else {
                crate::tr!("ex03.not_texture")
            };
            return Err(crate::tr!(
                "ex03.checker",
                uv,
                colour = fmt3(c),
                got = fmt3(got),
                why
            ));
        }
    }
    // Nothing below the surface.
    let below = Vec3A::new(0.3, 0.0, -0.95).normalize();
    for (o, i) in [(wo, below), (below, wi)] {
        let got = f(&Texture::Constant(Color::ONE), Vec2::ZERO, o, i);
        if got != Color::ZERO {
            return Err(crate::tr!(
                "ex03.below",
                wo = fmt3(o),
                wi = fmt3(i),
                got = fmt3(got)
            ));
        }
    }
    Ok(())
}
