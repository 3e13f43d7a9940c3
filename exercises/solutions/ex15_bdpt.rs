//! Reference solution of exercise 15 (see `src/ex15_bdpt.rs` for the task).
//!
//! A path `x̄ = x_0 … x_{n−1}` (lens first) is made by strategy `(s, t)`,
//! `s + t = n`, from the camera subpath `z_0 … z_{t−1} = x_0 … x_{t−1}` and the
//! light subpath `y_0 … y_{s−1} = x_{n−1} … x_t`, joined by one edge. Its
//! contribution is the path's measurement contribution divided by the
//! strategy's density, both in the area measure: the subpaths' throughputs
//! hold everything on their own side, the edge brings the two scattering
//! functions at its ends and its geometry term.

use raytracer::integrator::vertex::{NO_LIGHT, Vertex, visible};
use raytracer::math::{Color, Vec3A};
use raytracer::sampling::Sampler;
use raytracer::scene::Scene;

use crate::plug::BdptConnection;

/// The geometry term `G(x ↔ y)`.
pub fn geometry_term(x: Vec3A, nx: Vec3A, y: Vec3A, ny: Vec3A) -> f32 {
    // |cos θ_x| dω_x = |cos θ_x| |cos θ_y| dA_y / ‖x − y‖²: one cosine at
    // each end (with the unit edge direction), the distance squared.
    let d = y - x;
    let dist2 = d.length_squared();
    if dist2 == 0.0 {
        return 0.0;
    }
    let w = d / dist2.sqrt();
    nx.dot(w).abs() * ny.dot(w).abs() / dist2
}

/// The unweighted contribution of strategy `(s, t)`.
pub fn connect(
    scene: &Scene,
    light: &[Vertex],
    camera: &[Vertex],
    s: usize,
    t: usize,
    sampler: &mut Sampler,
) -> Option<BdptConnection> {
    let found = |value: Color| {
        (value != Color::ZERO).then_some(BdptConnection {
            value,
            raster: None,
            lens: None,
        })
    };
    if s == 0 {
        // The camera subpath hit an emitter by itself: its throughput times
        // the radiance the emitter sends back along the last segment.
        if t < 2 {
            return None;
        }
        let z = &camera[t - 1];
        return found(z.beta * z.le_towards(scene, &camera[t - 2]));
    }
    let y = &light[s - 1];
    if !y.is_connectible(scene) {
        return None;
    }
    if t == 1 {
        // Light tracing: y_{s−1} joined to a point of the lens. The lens
        // point's density per unit solid angle at y is what
        // `Camera::sample_wi` returns, so the edge's geometry term is already
        // inside it, except for the cosine at y.
        let cs = scene.camera.sample_wi(y.p(), sampler.next_2d())?;
        let value = y.beta * y.f_importance(scene, cs.wi) * (y.abs_cos(cs.wi) * cs.we / cs.pdf_w);
        if value == Color::ZERO {
            return None;
        }
        let lens = Vertex::camera(cs.p_lens, Color::ZERO);
        return visible(scene, y, &lens).then_some(BdptConnection {
            value,
            raster: Some(cs.raster),
            lens: Some(lens),
        });
    }
    let z = &camera[t - 1];
    if !z.is_connectible(scene) {
        return None;
    }
    // The edge y → z: L_e (s = 1) or the adjoint BRDF at y towards z, the
    // BRDF at z from y towards z_{t−2}, and G with the cosines each vertex
    // uses (shading normal on a surface, none at a point light).
    let d = z.p() - y.p();
    let dist2 = d.length_squared();
    if dist2 == 0.0 {
        return None;
    }
    let w = d / dist2.sqrt();
    let g = y.abs_cos(w) * z.abs_cos(w) / dist2;
    let value = y.beta * y.f_importance(scene, w) * g * z.f(scene, -w) * z.beta;
    if value == Color::ZERO || !visible(scene, y, z) {
        return None;
    }
    found(value)
}

/// The MIS weight (power heuristic) of strategy `(s, t)`.
pub fn mis_weight(
    scene: &Scene,
    light: &[Vertex],
    camera: &[Vertex],
    s: usize,
    t: usize,
    lens: Option<Vertex>,
) -> f32 {
    // The path's vertices as this strategy made them (a copy: the densities
    // across the edge are about to change). A t = 1 connection chose its own
    // lens point.
    let mut z: Vec<Vertex> = camera[..t].to_vec();
    let mut y: Vec<Vertex> = light[..s].to_vec();
    if let Some(l) = lens {
        z[0] = l;
    }
    // A strategy that cannot make the path: s = 0 needs an emitter at the
    // end; no other strategy connects at a delta BRDF.
    if s == 0 && z[t - 1].light == NO_LIGHT {
        return 0.0;
    }
    if s > 0 && !(z[t - 1].is_connectible(scene) && y[s - 1].is_connectible(scene)) {
        return 0.0;
    }
    // The edge's ends are joined deterministically: not deltas here.
    z[t - 1].delta = false;
    if s > 0 {
        y[s - 1].delta = false;
    }
    // Each vertex stores its density from its own side (`pdf_fwd_a`) and from
    // the other side (`pdf_rev_a`); the latter is stale for the two vertices
    // next to the edge on each side: it depends on the other subpath.
    // From the light side: z_{t−1} is reached from y_{s−1} (or is the
    // origin of a light path if s = 0), z_{t−2} from z_{t−1}.
    let z_rev = match s {
        0 => z[t - 1].pdf_light_origin_a(scene),
        _ => y[s - 1].pdf_a(scene, s.checked_sub(2).map(|i| &y[i]), &z[t - 1]),
    };
    let z_minus_rev = (t >= 2).then(|| match s {
        0 => z[t - 1].pdf_light_a(scene, &z[t - 2]),
        _ => z[t - 1].pdf_a(scene, Some(&y[s - 1]), &z[t - 2]),
    });
    // From the camera side: y_{s−1} is reached from z_{t−1}, y_{s−2} from y_{s−1}.
    let y_rev = (s >= 1).then(|| z[t - 1].pdf_a(scene, t.checked_sub(2).map(|i| &z[i]), &y[s - 1]));
    let y_minus_rev = (s >= 2).then(|| y[s - 1].pdf_a(scene, Some(&z[t - 1]), &y[s - 2]));
    z[t - 1].pdf_rev_a = z_rev;
    if let Some(p) = z_minus_rev {
        z[t - 2].pdf_rev_a = p;
    }
    if let Some(p) = y_rev {
        y[s - 1].pdf_rev_a = p;
    }
    if let Some(p) = y_minus_rev {
        y[s - 2].pdf_rev_a = p;
    }
    // p_i / p_s by running products: moving the edge one vertex towards the
    // camera hands that vertex from the camera side to the light side, so
    // the ratio gains its light-side density over its camera-side one (and
    // the other way towards the light). A delta's density (stored as 0) is
    // common to every strategy that can make the path: it counts as 1.
    let remap = |p: f32| if p != 0.0 { p } else { 1.0 };
    let mut sum = 1.0f32; // the strategy itself: (p_s / p_s)²
    let mut r = 1.0f32;
    for i in (1..t).rev() {
        // Strategy (s + t − i, i): the edge z_{i−1} — z_i.
        r *= remap(z[i].pdf_rev_a) / remap(z[i].pdf_fwd_a);
        if !z[i].delta && !z[i - 1].delta {
            sum += r * r;
        }
    }
    let mut r = 1.0f32;
    for i in (0..s).rev() {
        // Strategy (i, s + t − i): the edge y_i — y_{i−1} (no y_{−1}: the
        // camera path hits the light, impossible for a point light).
        r *= remap(y[i].pdf_rev_a) / remap(y[i].pdf_fwd_a);
        let before = if i > 0 {
            y[i - 1].delta
        } else {
            y[0].is_delta_light(scene)
        };
        if !y[i].delta && !before {
            sum += r * r;
        }
    }
    // Power heuristic: p_s² / Σ_i p_i² = 1 / Σ_i (p_i / p_s)².
    let w = 1.0 / sum;
    if w.is_finite() { w } else { 0.0 }
}
