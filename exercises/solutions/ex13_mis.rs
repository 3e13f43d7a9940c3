//! Reference solution of exercise 13 (see `src/ex13_mis.rs` for the task).

use raytracer::brdf::TransportMode;
use raytracer::math::{Color, Ray, Vec3A};
use raytracer::sampling::Sampler;
use raytracer::scene::Scene;

/// The power heuristic (exponent 2) for one sample of each of two
/// strategies: `w = p_this² / (p_this² + p_other²)`; 0 if neither could
/// make the sample.
fn power_weight(pdf_this: f32, pdf_other: f32) -> f32 {
    let (a, b) = (pdf_this * pdf_this, pdf_other * pdf_other);
    if a + b == 0.0 { 0.0 } else { a / (a + b) }
}

/// The radiance estimate of one path starting with `ray`: light sampling and
/// BRDF sampling at every vertex, combined by the power heuristic.
///
/// With both densities per unit solid angle at the vertex x,
/// `p_light(ω) = P(light) · p_ω(ω | light)` and `p_BRDF(ω)`, the light
/// sample contributes `w_light · f_r L_e |cos θ_i| / p_light` and the
/// emitter hit by the BRDF sample `w_BRDF · β L_e` (its `f_r |cos θ_i| /
/// p_BRDF` is already in β), with `w_light + w_BRDF = 1` for every
/// direction both can make: each piece of direct light is counted once in
/// expectation, by whichever strategy finds it with the larger density.
pub fn path_radiance_mis(
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
    // Where the current ray left and with what BRDF density; `None` for the
    // camera ray and after a delta lobe (no light sample competes there).
    let mut prev: Option<(Vec3A, f32)> = None;
    if max_depth == 0 {
        return l;
    }
    loop {
        let hit = scene.intersect(&ray);
        // The emitter found by the BRDF sample, weighted against the light
        // strategy's density of the same direction.
        if let Some(e) = scene.emitter_hit(&ray, hit.as_ref()) {
            let w = match prev {
                None => 1.0,
                Some((x, pdf_brdf)) => {
                    let light = &scene.lights[e.light as usize];
                    let pdf_light = scene.light_pmf(e.light) * light.pdf_li_w(x, e.p, e.n, ray.d);
                    power_weight(pdf_brdf, pdf_light)
                }
            };
            l += beta * e.le * w;
        }
        let Some(it) = hit else { break };
        if bounces + 1 >= max_depth {
            break;
        }
        let brdf = scene.brdf(&it);
        let wo = it.frame.to_local(it.wo);
        // The light sample, weighted against the BRDF's density of its direction.
        let u_choice = sampler.next_1d();
        let u_light = sampler.next_2d();
        if !brdf.is_delta() {
            if let Some(choice) = scene.choose_light(u_choice) {
                if let Some(ls) = choice.light.sample_li(it.p, u_light) {
                    let wi = it.frame.to_local(ls.wi);
                    let f = brdf.eval(wo, wi, it.uv);
                    let shadow = if ls.dist.is_finite() {
                        it.spawn_ray_to(ls.p, ls.n)
                    } else {
                        it.spawn_ray(ls.wi)
                    };
                    let pdf_light = choice.pmf * ls.pdf_w;
                    if f != Color::ZERO && pdf_light > 0.0 && scene.unoccluded(&shadow) {
                        let w = if ls.is_delta {
                            1.0
                        } else {
                            power_weight(pdf_light, brdf.pdf(wo, wi, it.uv))
                        };
                        l += beta * f * ls.li * (wi.z.abs() * w / pdf_light);
                    }
                }
            }
        }
        // Continue with a BRDF sample, as in exercise 11.
        let (u_lobe, u) = (sampler.next_1d(), sampler.next_2d());
        let Some(bs) = brdf.sample(wo, it.uv, u_lobe, u, TransportMode::Radiance) else {
            break;
        };
        prev = (!bs.is_delta).then_some((it.p, bs.pdf_w));
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
