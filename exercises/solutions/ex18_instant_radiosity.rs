//! Reference solution of exercise 18 (see `src/ex18_instant_radiosity.rs` for the task).

use raytracer::brdf::TransportMode;
use raytracer::math::{Color, Ray};
use raytracer::sampling::Sampler;
use raytracer::scene::{Interaction, Scene};

use crate::plug::Vpl;

/// The VPLs of `paths` light paths: one on the light where each path starts,
/// one at every later vertex on a surface that is not a mirror or glass.
pub fn generate_vpls(
    scene: &Scene,
    paths: u32,
    max_depth: Option<u32>,
    rr_depth: u32,
    sampler: &mut Sampler,
) -> Vec<Vpl> {
    let mut vpls = Vec::new();
    // A VPL of k segments lights the camera's first hit over a path of
    // k + 2 segments (camera ray, connection, the light path's k).
    let max_k = match max_depth {
        Some(d) if d < 2 => return vpls,
        Some(d) => d - 2,
        None => u32::MAX,
    };
    let n = paths.max(1) as f32;
    for _ in 0..paths {
        // y_0: a light chosen with P(light), a point with density p_A.
        let Some(choice) = scene.choose_light(sampler.next_1d()) else {
            return vpls;
        };
        let (u_pos, u_dir) = (sampler.next_2d(), sampler.next_2d());
        let Some(e) = choice.light.sample_le(u_pos, u_dir) else {
            continue;
        };
        // The VPL on the light: L_e(y_0, ω) / (P(light) p_A(y_0)), shared by N.
        let weight = 1.0 / (choice.pmf * e.pdf_a * n);
        vpls.push(Vpl::Light {
            p: e.p,
            n: e.n,
            light: choice.index,
            weight,
        });
        // β_1 = L_e |cos θ_0| / (P(light) p_A p_ω): the flux the path carries.
        let cos0 = e.n.dot(e.ray.d).abs();
        let mut beta = e.le * (cos0 / (choice.pmf * e.pdf_a * e.pdf_w));
        let mut ray = e.ray;
        // The walk's own throughput Π f_r |cos| / p, without the light's
        // flux, to choose the roulette's survival probability from.
        let mut walk = Color::ONE;
        let mut k = 1u32;
        while k <= max_k {
            let Some(it) = scene.intersect(&ray) else {
                break;
            };
            let brdf = scene.brdf(&it);
            // A delta BRDF is zero in every direction a connection could
            // take: no VPL there, but the path goes on through it.
            if !brdf.is_delta() {
                vpls.push(Vpl::Surface {
                    it,
                    power: beta / n,
                    segments: k,
                });
            }
            if k == max_k {
                break;
            }
            // Continue by sampling the BRDF in importance mode (the light
            // flows the other way than a camera path's importance).
            let wo = it.frame.to_local(it.wo);
            let (u_lobe, u) = (sampler.next_1d(), sampler.next_2d());
            let Some(bs) = brdf.sample(wo, it.uv, u_lobe, u, TransportMode::Importance) else {
                break;
            };
            let factor = bs.f * (bs.wi.z.abs() / bs.pdf_w);
            beta *= factor;
            walk *= factor;
            ray = it.spawn_ray(it.frame.to_world(bs.wi));
            // Russian roulette after rr_depth bounces: survive with q, then
            // divide by q so that the expected flux stays the same.
            if k >= rr_depth {
                let q = walk.max_element().min(0.95);
                if q <= 0.0 || sampler.next_1d() >= q {
                    break;
                }
                beta /= q;
                walk /= q;
            }
            k += 1;
        }
    }
    vpls
}

/// The light of every VPL reflected at `x` towards `x.wo`:
/// `Σ_y f_r(x; ω_xy, ω_o) G(x, y) f_y(ω_yx) Φ_y V(x, y)`, G clamped at `clamp`.
pub fn gather(scene: &Scene, x: &Interaction, vpls: &[Vpl], clamp: Option<f32>) -> Color {
    let brdf = scene.brdf(x);
    let wo = x.frame.to_local(x.wo);
    let mut l = Color::ZERO;
    for vpl in vpls {
        let (p, n, ng) = match vpl {
            Vpl::Light { p, n, .. } => (*p, *n, *n),
            Vpl::Surface { it, .. } => (it.p, it.frame.n, it.ng),
        };
        let to_y = p - x.p;
        let d2 = to_y.length_squared();
        if d2 == 0.0 {
            continue;
        }
        let w = to_y / d2.sqrt();
        // What the VPL sends back along −w: its emission times its weight,
        // or its BRDF from its incoming direction times its flux.
        let sent = match vpl {
            Vpl::Light {
                n, light, weight, ..
            } => scene.emitted_by(*light, *n, -w) * *weight,
            Vpl::Surface { it, power, .. } => {
                let f_y =
                    scene
                        .brdf(it)
                        .eval(it.frame.to_local(it.wo), it.frame.to_local(-w), it.uv);
                f_y * *power
            }
        };
        let f_x = brdf.eval(wo, x.frame.to_local(w), x.uv);
        if sent == Color::ZERO || f_x == Color::ZERO {
            continue;
        }
        // G: one cosine at each end of the connection, both unsigned, over d².
        let mut g = x.frame.n.dot(w).abs() * n.dot(w).abs() / d2;
        if let Some(c) = clamp {
            g = g.min(c);
        }
        if !scene.unoccluded(&Ray::spawn_to(x.p, x.ng, p, ng)) {
            continue;
        }
        l += f_x * g * sent;
    }
    l
}
