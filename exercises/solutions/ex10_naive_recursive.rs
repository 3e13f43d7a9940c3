//! Reference solution of exercise 10 (see `src/ex10_naive_recursive.rs` for the task).

use raytracer::brdf::TransportMode;
use raytracer::math::{Color, Ray};
use raytracer::sampling::Sampler;
use raytracer::scene::Scene;

/// The naive recursive estimate of the radiance along `ray`.
pub fn naive_radiance(
    scene: &Scene,
    ray: &Ray,
    depth: u32,
    max_depth: u32,
    branching: u32,
    sampler: &mut Sampler,
) -> Color {
    let Some(it) = scene.intersect(ray) else {
        return scene.escaped_radiance(ray.d);
    };
    let mut l = scene.emitted(&it);
    if depth + 1 >= max_depth || branching == 0 {
        return l;
    }
    let brdf = scene.brdf(&it);
    let wo = it.frame.to_local(it.wo);
    let mut sum = Color::ZERO;
    for _ in 0..branching {
        let (u_lobe, u) = (sampler.next_1d(), sampler.next_2d());
        let Some(bs) = brdf.sample(wo, it.uv, u_lobe, u, TransportMode::Radiance) else {
            continue;
        };
        let next = it.spawn_ray(it.frame.to_world(bs.wi));
        let li = naive_radiance(scene, &next, depth + 1, max_depth, branching, sampler);
        sum += bs.f * li * (bs.wi.z.abs() / bs.pdf_w);
    }
    l += sum / branching as f32;
    l
}
