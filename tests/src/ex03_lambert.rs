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
            " — too bright by ×π: the constant that the integral over the hemisphere brings (a factor π) is missing".to_string()
        } else if ratio_near(r, 2.0 / 3.0) {
            " — your f_r seems to contain cos θ_i, so the cosine counts twice: the cosine belongs to the integrator, not the BRDF".to_string()
        } else if ratio_near(r, 1.0 / PI as f64) {
            " — too dark by ×1/π: divided by π twice?".to_string()
        } else if ratio_near(r, 0.5) {
            " — half the light is lost: as if the integral of the cosine over the hemisphere were 2π".to_string()
        } else if albedo > 1.0 {
            format!(
                " — too bright by ×{albedo:.3}: the surface reflects more light than it receives"
            )
        } else {
            format!(" — too dark by ×{albedo:.3}: a white surface must reflect all the light")
        };
        return Err(format!(
            "the directional albedo of your Lambert (white texture) is {albedo:.3}, expected 1{why}"
        ));
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
                "your f_r has the colour of the texture at uv = (0, 0), not at the point's uv"
            } else if close3(got, other / PI, 1e-4) {
                "your f_r has the colour of the other square of the checker: the texture is looked up at another point than uv"
            } else {
                "your f_r does not follow the texture's colour at this point (the white texture passed, so the constant is right)"
            };
            return Err(format!(
                "checker texture at uv = {uv}, whose colour there is {}: your f_r is {}, π·f_r = {} — {why}",
                fmt3(c),
                fmt3(got),
                fmt3(got * PI)
            ));
        }
    }
    // Nothing below the surface.
    let below = Vec3A::new(0.3, 0.0, -0.95).normalize();
    for (o, i) in [(wo, below), (below, wi)] {
        let got = f(&Texture::Constant(Color::ONE), Vec2::ZERO, o, i);
        if got != Color::ZERO {
            return Err(format!(
                "wo = {}, wi = {}: your f_r is {}, not black — light from below the surface, or leaving below it (z ≤ 0), is reflected by yours",
                fmt3(o),
                fmt3(i),
                fmt3(got)
            ));
        }
    }
    Ok(())
}
