//! Random walks: the camera subpath and the light subpath.
//!
//! Lecture topic: "Paths" — path tracing grows a path from the camera, light
//! tracing from a light, bidirectional tracing both. Each walk samples the
//! BRDF at every surface it meets and records, for every new vertex, its
//! forward area density and, for the vertex before, the reverse one (see
//! [`super::vertex`]).
//!
//! **Depth.** Mitsuba's `max_depth = D` allows at most `D − 1` scattering
//! vertices, i.e. `s + t − 2 ≤ D − 1`: paths of at most `D + 1` vertices.
//! That is the only limit, as for the path tracer: a subpath is a growable
//! buffer, reused from sample to sample, and unlimited depth is unlimited
//! (a fixed buffer of 64 vertices once dropped the tail that Russian
//! roulette lets through: at albedo 0.99 half the light of a furnace).
//!
//! Not handled (documented limit): environment lights on the light side.
//! Light subpaths that start at the environment are dropped; bidirectional
//! tracing counts the environment through camera paths that escape (`s = 0`,
//! the only strategy that can then produce such paths, with weight 1).

use super::continuation::sample_continuation;
use super::dimensions::{EMISSION_DIRECTION, EMISSION_POINT, LIGHT_CHOICE};
use super::roulette::russian_roulette;
use super::shading_normals::importance_correction;
use super::stop::stop_requested;
use super::vertex::{Subpath, Vertex, pdf_w_to_a};
use crate::brdf::TransportMode;
use crate::math::{Color, Ray, UVec2, Vec3A};
use crate::sampling::Sampler;
use crate::scene::{LightChoice, Scene};

/// A camera subpath's last ray, which hit nothing.
#[derive(Clone, Copy, Debug)]
pub struct EscapedRay {
    /// The throughput it carries (that a vertex at its end would have had).
    pub beta: Color,
    /// Its direction, where the environment is looked up.
    pub d: Vec3A,
}

/// Extends the subpath `path` (its last vertex is where the walk starts) by
/// a random walk: `ray` leaves that vertex with solid-angle density `pdf_w`,
/// and `beta` is the throughput the first new vertex gets. At every surface
/// the BRDF is sampled in transport mode `mode` (with the adjoint correction
/// for shading normals in importance mode); each new vertex records
/// `pdf_fwd_a`, and its predecessor `pdf_rev_a` (the reverse walk's density,
/// the BRDF's `pdf(ω_i → ω_o)`). Stops when the subpath holds `max_vertices`
/// (no other cap: the buffer grows as the walk needs), at a failed sample, or
/// by Russian roulette after `rr_depth` scattering events (which divides the
/// survivors' throughput by their probability `q`). A walk that neither
/// depth nor roulette ends (a closed white furnace without them) ends when
/// the render is asked to stop ([`super::stop`]). Draws, per surface below
/// `max_vertices`: a continuation, then (from `rr_depth` on) the roulette's
/// number.
#[allow(clippy::too_many_arguments)]
pub fn random_walk(
    scene: &Scene,
    path: &mut Subpath,
    mut ray: Ray,
    mut beta: Color,
    mut pdf_w: f32,
    mode: TransportMode,
    max_vertices: usize,
    rr_depth: u32,
    sampler: &mut Sampler,
) -> Option<EscapedRay> {
    // The walk's own throughput Π f |cos| / p (without the start's L_e or
    // W_e), for Russian roulette; `eta_scale` undoes glass's 1/η² on radiance.
    let mut walk = Color::ONE;
    let mut eta_scale = 1.0f32;
    let mut scatterings = 0u32;
    while path.len() < max_vertices {
        if scatterings % 64 == 63 && stop_requested() {
            break;
        }
        let Some(it) = scene.intersect(&ray) else {
            return (mode == TransportMode::Radiance).then_some(EscapedRay { beta, d: ray.d });
        };
        let mut v = Vertex::surface(scene, it, beta);
        v.pdf_fwd_a = pdf_w_to_a(pdf_w, path.last().expect("a walk starts at a vertex"), &v);
        path.push(v);
        let n = path.len();
        if n >= max_vertices {
            break;
        }
        let brdf = scene.brdf(&it);
        let Some(c) = sample_continuation(&it, brdf, mode, sampler) else {
            break;
        };
        let bs = c.sample;
        pdf_w = bs.pdf_w;
        // The reverse walk would sample ω_o from ω_i.
        let mut pdf_rev_w = brdf.pdf(bs.wi, c.wo, it.uv);
        if bs.is_delta {
            path[n - 1].delta = true;
            pdf_w = 0.0;
            pdf_rev_w = 0.0;
        }
        let mut weight = c.weight;
        match mode {
            TransportMode::Radiance => eta_scale *= bs.eta * bs.eta,
            // Light paths scatter with the adjoint BRDF (shading normals).
            TransportMode::Importance => weight *= importance_correction(&it, it.wo, c.wi),
        }
        beta *= weight;
        walk *= weight;
        let (cur, prev) = (path[n - 1], path[n - 2]);
        path[n - 2].pdf_rev_a = pdf_w_to_a(pdf_rev_w, &cur, &prev);
        ray = c.ray;
        scatterings += 1;
        if scatterings >= rr_depth {
            let Some(q) = russian_roulette(walk, eta_scale, sampler) else {
                break;
            };
            beta /= q;
            walk /= q;
        }
    }
    None
}

/// The camera subpath `z_0 z_1 …` of a pixel sample, into `path` (cleared
/// first), at most `max_vertices` long: `z_0` on the lens with
/// `β = W_e cos θ / (p_A p_ω) = 1` (a pixel sample's importance is 1), then
/// a random walk in radiance mode. Returns the ray that escaped the scene,
/// if the walk ended that way (it sees the environment). Draws the camera
/// ray's numbers, then the walk's.
pub fn camera_subpath(
    scene: &Scene,
    pixel: UVec2,
    sampler: &mut Sampler,
    path: &mut Subpath,
    max_vertices: usize,
    rr_depth: u32,
) -> Option<EscapedRay> {
    path.clear();
    let ray = super::camera_ray(scene, pixel, sampler);
    path.push(Vertex::camera(ray.o, Color::ONE));
    if max_vertices < 2 {
        return None;
    }
    // p_ω of the primary ray over the whole film (see `camera::pdf_we`).
    let pdf_w = scene.camera.pdf_we(&ray).pdf_w;
    random_walk(
        scene,
        path,
        ray,
        Color::ONE,
        pdf_w,
        TransportMode::Radiance,
        max_vertices,
        rr_depth,
        sampler,
    )
}

/// The light subpath `y_0 y_1 …`: a light chosen with `P(light)`, a point
/// `y_0` with area density `p_A` and a direction with `p_ω` from
/// `sample_le`; `y_0` stores `β_0 = 1/(P(light) p_A)` (its `L_e(ω)` is
/// applied by whoever leaves it), and the walk starts, in importance mode,
/// with the throughput of the emitted ray: its radiance as a Monte Carlo
/// estimate over the choices of the light, the point and the direction
/// (exercise 14 derives it; mind the cosine at the light).
/// Returns the number of vertices (0 if no light path could start, e.g. the
/// environment was chosen: not supported on the light side). Draws
/// [`LIGHT_CHOICE`], [`EMISSION_POINT`] and [`EMISSION_DIRECTION`] (always,
/// also when no path starts), then the walk's.
pub fn light_subpath(
    scene: &Scene,
    sampler: &mut Sampler,
    path: &mut Subpath,
    max_vertices: usize,
    rr_depth: u32,
) -> usize {
    let u_choice = LIGHT_CHOICE.draw(sampler);
    let (u_pos, u_dir) = (
        EMISSION_POINT.draw(sampler),
        EMISSION_DIRECTION.draw(sampler),
    );
    path.clear();
    if max_vertices == 0 {
        return 0;
    }
    let Some(LightChoice { index, light, pmf }) = scene.choose_light(u_choice) else {
        return 0;
    };
    if light.is_environment() {
        return 0;
    }
    let Some(e) = light.sample_le(u_pos, u_dir) else {
        return 0;
    };
    if e.pdf_a <= 0.0 || e.pdf_w <= 0.0 || e.le == Color::ZERO {
        return 0;
    }
    let pdf_origin = pmf * e.pdf_a;
    // y_0 lies on the light's surface (e.p); only the ray that leaves it
    // starts off the surface. Stored at the ray's origin, the lamp seen by
    // light tracing's t = 1 connections was moved by the offset (its edge
    // rows of `cornell` differed by −0.26% and +1.7% from path tracing).
    path.push(Vertex::light(
        index,
        e.p,
        e.n,
        Color::splat(1.0 / pdf_origin),
        pdf_origin,
    ));
    if max_vertices < 2 {
        return 1;
    }
    let cos0 = path[0].abs_cos(e.ray.d);
    let beta = e.le * (cos0 / (pdf_origin * e.pdf_w));
    random_walk(
        scene,
        path,
        e.ray,
        beta,
        e.pdf_w,
        TransportMode::Importance,
        max_vertices,
        rr_depth,
        sampler,
    );
    path.len()
}
