//! Reference solution of exercise 17 (see `src/ex17_photon_mapping.rs` for the task).

use raytracer::brdf::{Brdf, TransportMode};
use raytracer::integrator::photon::Photon;
use raytracer::integrator::photon_map::{PhotonMap, Search};
use raytracer::math::{Color, PI, Vec3};
use raytracer::sampling::Sampler;
use raytracer::scene::{Interaction, Scene};

/// Traces light path number `i` of `paths` (its sampler given) and pushes
/// the photons it leaves onto `photons`.
pub fn trace_photon_path(
    scene: &Scene,
    paths: u64,
    rr_depth: u32,
    sampler: &mut Sampler,
    photons: &mut Vec<Photon>,
) {
    let u_choice = sampler.next_1d();
    let (u_pos, u_dir) = (sampler.next_2d(), sampler.next_2d());
    let Some(choice) = scene.choose_light(u_choice) else {
        return;
    };
    if choice.light.is_environment() {
        return;
    }
    let Some(e) = choice.light.sample_le(u_pos, u_dir) else {
        return;
    };
    if e.pdf_a <= 0.0 || e.pdf_w <= 0.0 {
        return;
    }
    // The emitted power is Φ = ∫∫ L_e cos θ dA dω (summed over the lights).
    // One sample of (light, point, direction) drawn with density
    // P(light) · p_A · p_ω estimates it as L_e cos θ / (P p_A p_ω); the N
    // paths share it, so each starts with 1/N of its estimate. A point
    // light has no surface: no cosine, and p_A = 1 stands for its delta.
    let cos0 = if e.is_delta_position {
        1.0
    } else {
        e.n.dot(e.ray.d).abs()
    };
    let mut power = e.le * (cos0 / (choice.pmf * e.pdf_a * e.pdf_w * paths as f32));
    // The walk's own throughput Π f_r |cos θ| / p (without L_e and 1/N):
    // how much of its starting flux the photon still carries, for roulette.
    let mut walk = Color::ONE;
    let mut ray = e.ray;
    let mut segments = 1u32;
    let mut bounces = 0u32;
    while let Some(it) = scene.intersect(&ray) {
        let brdf = scene.brdf(&it);
        // A photon on a diffuse or glossy surface: where it is, where it
        // came from, the flux it carries. Mirrors and glass keep nothing.
        if !brdf.is_delta() {
            photons.push(Photon {
                p: Vec3::from(it.p),
                wi: Vec3::from(it.wo),
                power: Vec3::from(power),
                segments,
            });
        }
        // Scatter: ω_i sampled from f_r in importance mode; the flux that
        // leaves along it is Φ · f_r |cos θ_i| / p(ω_i) (the adjoint walk).
        let wo = it.frame.to_local(it.wo);
        let (u_lobe, u) = (sampler.next_1d(), sampler.next_2d());
        let Some(bs) = brdf.sample(wo, it.uv, u_lobe, u, TransportMode::Importance) else {
            return;
        };
        let weight = bs.f * (bs.wi.z.abs() / bs.pdf_w);
        power *= weight;
        walk *= weight;
        ray = it.spawn_ray(it.frame.to_world(bs.wi));
        segments += 1;
        bounces += 1;
        // Russian roulette: survive with q, carry Φ/q (E[Φ′] = q · Φ/q = Φ).
        if bounces >= rr_depth {
            let q = walk.max_element().min(0.95);
            if q <= 0.0 || sampler.next_1d() >= q {
                return;
            }
            power /= q;
            walk /= q;
        }
    }
}

/// The reflected radiance at `it` estimated from the photons of `map`.
pub fn photon_radiance(map: &PhotonMap, it: &Interaction, brdf: &Brdf, search: Search) -> Color {
    // The candidates: every photon within the largest radius, with d².
    let mut near: Vec<(f32, Photon)> = Vec::new();
    map.for_each_within(
        it.p,
        search.max_radius(),
        |_| true,
        |_, ph, d2| near.push((d2, *ph)),
    );
    // r²: the fixed radius, or the k-th nearest's distance (with k or
    // fewer candidates, the whole disk of the largest radius).
    let r2 = match search {
        Search::Radius(r) => r * r,
        Search::Nearest { k, max_radius } => {
            if k > 0 && near.len() > k {
                near.select_nth_unstable_by(k - 1, |a, b| a.0.total_cmp(&b.0));
                near.truncate(k);
                near[k - 1].0
            } else {
                max_radius * max_radius
            }
        }
    };
    if r2 <= 0.0 {
        return Color::ZERO;
    }
    // L_r(x, ω_o) ≈ Σ_p f_r(x, ω_p, ω_o) Φ_p K(d_p), with Epanechnikov's
    // K(d) = c (1 − d²/r²): ∫ K dA = c ∫_0^r (1 − ρ²/r²) 2πρ dρ = c π r²/2,
    // so c = 2/(π r²). The photon's Φ is the flux that crossed the disk:
    // no cos θ_i here (it is in the change from radiance to flux already).
    let wo = it.frame.to_local(it.wo);
    let mut l = Color::ZERO;
    for (d2, ph) in &near {
        if *d2 < r2 {
            let wi = it.frame.to_local(ph.wi.into());
            let k = 2.0 / (PI * r2) * (1.0 - d2 / r2);
            l += brdf.eval(wo, wi, it.uv) * Color::from(ph.power) * k;
        }
    }
    l
}
