//! Reference solution of exercise 12 (see `src/ex12_nee.rs` for the task).

use raytracer::light::Light;
use raytracer::math::{Color, Vec3A};
use raytracer::sampling::Sampler;
use raytracer::scene::{Interaction, LightChoice, Scene};

/// `p_ω = p_A · ‖x − y‖² / |cos θ_y|`.
pub fn area_pdf_to_solid_angle(pdf_area: f32, x: Vec3A, y: Vec3A, n_y: Vec3A) -> f32 {
    let d = x - y;
    let dist2 = d.length_squared();
    let cos_y = n_y.dot(d).abs() / dist2.sqrt();
    if cos_y == 0.0 {
        return 0.0;
    }
    pdf_area * dist2 / cos_y
}

/// One next-event estimate of the direct light at `it`.
pub fn estimate_direct(scene: &Scene, it: &Interaction, sampler: &mut Sampler) -> Color {
    let u_choice = sampler.next_1d();
    let u = sampler.next_2d();
    let Some(LightChoice { light, pmf, .. }) = scene.choose_light(u_choice) else {
        return Color::ZERO;
    };
    let (wi, le, pdf_w, shadow) = match light {
        Light::Area(a) => {
            let (y, n_y) = a.shape.sample_area(u);
            let wi = (y - it.p).normalize();
            let pdf_w = area_pdf_to_solid_angle(1.0 / a.shape.area(), it.p, y, n_y);
            (wi, a.le(n_y, -wi), pdf_w, it.spawn_ray_to(y, n_y))
        }
        other => {
            let Some(ls) = other.sample_li(it.p, u) else {
                return Color::ZERO;
            };
            let shadow = if ls.dist.is_finite() {
                it.spawn_ray_to(ls.p, ls.n)
            } else {
                it.spawn_ray(ls.wi)
            };
            (ls.wi, ls.li, ls.pdf_w, shadow)
        }
    };
    if pdf_w.is_nan() || pdf_w <= 0.0 || le == Color::ZERO {
        return Color::ZERO;
    }
    let wo_l = it.frame.to_local(it.wo);
    let wi_l = it.frame.to_local(wi);
    let f = scene.brdf(it).eval(wo_l, wi_l, it.uv);
    if f == Color::ZERO || !scene.unoccluded(&shadow) {
        return Color::ZERO;
    }
    f * le * (wi_l.z.abs() / (pmf * pdf_w))
}
