//! Reference solution of exercise 12 (see `src/ex12_nee.rs` for the task).

use raytracer::brdf::TransportMode;
use raytracer::light::Light;
use raytracer::math::{Color, Ray, Vec3A};
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

/// The radiance estimate of one path starting with `ray`, with next event
/// estimation at every vertex.
///
/// Exercise 11's loop, with one change of bookkeeping: the direct light of
/// every vertex comes from its light sample, so emission that a BRDF-sampled
/// ray hits is counted only where no light sample could have found it — the
/// camera ray, and a ray that left a delta lobe (where `f_r` of any other
/// direction is zero, so the light sample there found nothing). Counting it
/// everywhere would count the direct light twice.
pub fn path_radiance_nee(
    scene: &Scene,
    mut ray: Ray,
    max_depth: Option<u32>,
    rr_depth: u32,
    sampler: &mut Sampler,
) -> Color {
    let max_depth = max_depth.unwrap_or(u32::MAX);
    let mut l = Color::ZERO;
    let mut beta = Color::ONE;
    let mut bounces = 0u32;
    // Whether the emitter this ray may hit is not already counted by a light sample.
    let mut count_emission = true;
    if max_depth == 0 {
        return l;
    }
    loop {
        let Some(it) = scene.intersect(&ray) else {
            if count_emission {
                l += beta * scene.escaped_radiance(ray.d);
            }
            break;
        };
        if count_emission {
            l += beta * scene.emitted(&it);
        }
        // A light sample adds a segment, as a bounce does: both need room.
        if bounces + 1 >= max_depth {
            break;
        }
        let brdf = scene.brdf(&it);
        if !brdf.is_delta() {
            l += beta * estimate_direct(scene, &it, sampler);
        }
        let wo = it.frame.to_local(it.wo);
        let (u_lobe, u) = (sampler.next_1d(), sampler.next_2d());
        let Some(bs) = brdf.sample(wo, it.uv, u_lobe, u, TransportMode::Radiance) else {
            break;
        };
        count_emission = bs.is_delta;
        beta *= bs.f * (bs.wi.z.abs() / bs.pdf_w);
        ray = it.spawn_ray(it.frame.to_world(bs.wi));
        bounces += 1;
        if bounces >= rr_depth {
            let q = beta.max_element().min(0.95);
            if q <= 0.0 || sampler.next_1d() >= q {
                break;
            }
            beta /= q;
        }
    }
    l
}
