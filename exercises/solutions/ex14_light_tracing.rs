//! Reference solution of exercise 14 (see `src/ex14_light_tracing.rs` for the task).

use raytracer::brdf::TransportMode;
use raytracer::film::Splat;
use raytracer::math::{Color, Ray, Vec2, Vec3A};
use raytracer::sampling::Sampler;
use raytracer::scene::Scene;

use crate::plug::sample_lens;

/// The splat of one light-path vertex at `p` (geometric normal `ng` for the
/// shadow ray, `cos_p` = `|cos θ|` between its normal and the direction to
/// the lens), which sends `value(ω)` towards the lens along `ω` (`L_e` at the
/// light, `β f_r` at a surface): the slide's `C = β f_r G W_e / p_A(lens)`.
fn connect(
    scene: &Scene,
    p: Vec3A,
    ng: Vec3A,
    cos_p: impl Fn(Vec3A) -> f32,
    value: impl Fn(Vec3A) -> Color,
    u_lens: Vec2,
    splats: &mut Vec<Splat>,
) {
    let camera = &scene.camera;
    let lens = sample_lens(camera, u_lens);
    // Where the camera sees p through that lens point; None: behind the
    // camera or off the film, it contributes nothing.
    let Some(raster) = camera.raster_of(p, lens.p) else {
        return;
    };
    let to_lens = lens.p - p;
    let d2 = to_lens.length_squared();
    if d2 == 0.0 {
        return;
    }
    let w = to_lens / d2.sqrt();
    // W_e of the ray lens → p (zero off the film).
    let we = camera.we(&Ray::new(lens.p, -w));
    let cos_lens = (-w).dot(camera.forward());
    if we == 0.0 || cos_lens <= 0.0 {
        return;
    }
    // G(p ↔ lens) = |cos θ_p| cos θ_lens / d²: the change from the lens's
    // area to the solid angle at p.
    let g = cos_p(w) * cos_lens / d2;
    let c = value(w) * (g * we / lens.pdf_a);
    if c == Color::ZERO {
        return;
    }
    if !scene.unoccluded(&Ray::spawn_to(p, ng, lens.p, Vec3A::ZERO)) {
        return;
    }
    splats.push(Splat { raster, value: c });
}

/// One light path and its connections to the lens, pushed onto `splats`.
pub fn trace_light_path(
    scene: &Scene,
    sampler: &mut Sampler,
    max_depth: Option<u32>,
    rr_depth: u32,
    splats: &mut Vec<Splat>,
) {
    // D counts segments: a light vertex after k bounces joined to the lens is
    // a path of k + 1 segments, so the light path keeps at most D vertices.
    let max_vertices = max_depth.unwrap_or(u32::MAX);
    if max_vertices == 0 {
        return;
    }
    // y_0: a light chosen with P(light), a point with p_A and a direction
    // with p_ω (per unit solid angle).
    let Some(choice) = scene.choose_light(sampler.next_1d()) else {
        return;
    };
    let (u_pos, u_dir) = (sampler.next_2d(), sampler.next_2d());
    if choice.light.is_environment() {
        return;
    }
    let Some(e) = choice.light.sample_le(u_pos, u_dir) else {
        return;
    };
    if e.pdf_a <= 0.0 || e.pdf_w <= 0.0 {
        return;
    }
    let pdf_origin = choice.pmf * e.pdf_a;
    // |cos θ| at the light (a point light has no surface: 1).
    let cos_light = |w: Vec3A| {
        if e.is_delta_position {
            1.0
        } else {
            e.n.dot(w).abs()
        }
    };
    // The light seen directly: y_0 joined to the lens, L_e in place of β f_r.
    connect(
        scene,
        e.p,
        e.n,
        cos_light,
        |w| scene.emitted_by(choice.index, e.n, w) / pdf_origin,
        sampler.next_2d(),
        splats,
    );
    // β_1 = L_e cos θ_0 / (P(light) p_A p_ω).
    let mut beta = e.le * (cos_light(e.ray.d) / (pdf_origin * e.pdf_w));
    // The walk's own throughput Π f|cos|/p, for the roulette.
    let mut walk = Color::ONE;
    let mut ray = e.ray;
    let mut vertices = 1u32;
    let mut bounces = 0u32;
    while vertices < max_vertices {
        let Some(it) = scene.intersect(&ray) else {
            break;
        };
        vertices += 1;
        let brdf = scene.brdf(&it);
        // ω_i: towards where the light came from; the BRDF is importance's
        // f_r(ω_o = towards the lens, ω_i).
        let wi_local = it.frame.to_local(it.wo);
        if !brdf.is_delta() {
            connect(
                scene,
                it.p,
                it.ng,
                |w| it.frame.n.dot(w).abs(),
                |w| beta * brdf.eval(it.frame.to_local(w), wi_local, it.uv),
                sampler.next_2d(),
                splats,
            );
        }
        if vertices >= max_vertices {
            break;
        }
        // Continue: sample the BRDF in importance mode (glass does not scale
        // importance by 1/η²).
        let (u_lobe, u) = (sampler.next_1d(), sampler.next_2d());
        let Some(bs) = brdf.sample(wi_local, it.uv, u_lobe, u, TransportMode::Importance) else {
            break;
        };
        let weight = bs.f * (bs.wi.z.abs() / bs.pdf_w);
        beta *= weight;
        walk *= weight;
        ray = it.spawn_ray(it.frame.to_world(bs.wi));
        bounces += 1;
        if bounces >= rr_depth {
            // Survive with q, divide by q: E[β′] = q · β/q = β.
            let q = walk.max_element().min(0.95);
            if q <= 0.0 || sampler.next_1d() >= q {
                break;
            }
            beta /= q;
            walk /= q;
        }
    }
}
