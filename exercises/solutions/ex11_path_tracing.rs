//! Reference solution of exercise 11 (see `src/ex11_path_tracing.rs` for the task).

use raytracer::brdf::TransportMode;
use raytracer::math::{Color, Ray};
use raytracer::sampling::Sampler;
use raytracer::scene::Scene;

/// The radiance estimate of one path starting with `ray`.
pub fn path_radiance(
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
    if max_depth == 0 {
        return l;
    }
    loop {
        let Some(it) = scene.intersect(&ray) else {
            l += beta * scene.escaped_radiance(ray.d);
            break;
        };
        l += beta * scene.emitted(&it);
        if bounces + 1 >= max_depth {
            break;
        }
        let wo = it.frame.to_local(it.wo);
        let (u_lobe, u) = (sampler.next_1d(), sampler.next_2d());
        let Some(bs) = scene
            .brdf(&it)
            .sample(wo, it.uv, u_lobe, u, TransportMode::Radiance)
        else {
            break;
        };
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
