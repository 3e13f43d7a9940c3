//! Path vertices: the shared machinery of light tracing and bidirectional path
//! tracing (subpath generation, connections, MIS weights).
//!
//! Lecture topic: "Light tracing" and "Bidirectional path tracing". A path is
//! a sequence of points `x̄ = x_0 x_1 … x_k` whose first point lies on the lens
//! and whose last lies on a light. Its contribution to pixel `j` is Veach's
//! measurement contribution function (thesis, eq. 8.7)
//!
//! ```text
//!   f_j(x̄) = L_e(x_k → x_{k−1}) G(x_k, x_{k−1}) Π_{i=1}^{k−1} f_r(x_{i+1} → x_i → x_{i−1}) G(x_i, x_{i−1})
//!            · W_e^{(j)}(x_1 → x_0),
//!   G(x, y) = V(x, y) |cos θ_x| |cos θ_y| / ‖x − y‖²,
//! ```
//!
//! and the pixel value is `I_j = ∫ f_j(x̄) dμ(x̄)` over paths of every length
//! (area measure at every vertex). Path, light and bidirectional tracing differ
//! only in how they *generate* `x̄`: a bidirectional estimator builds a camera
//! subpath `z_0 … z_{t−1}` (from the lens) and a light subpath `y_0 … y_{s−1}`
//! (from a light) and joins `y_{s−1}` to `z_{t−1}` — the strategy `(s, t)`
//! generates a path of `s + t` vertices with density
//! `p_{s,t}(x̄) = Π_{i<s} p(y_i) · Π_{j<t} p(z_j)` (area measure).
//!
//! **Densities.** A direction sampled with solid-angle density `p_ω` at `x`
//! that reaches `y` gives `y` the area density (thesis, eq. 8.10)
//! `p_A(y) = p_ω · |cos θ_y| / ‖x − y‖²` ([`convert_density`]). Every vertex
//! stores two of them, as in pbrt-v4: `pdf_fwd`, the density with which its own
//! subpath generated it, and `pdf_rev`, the density with which the *other*
//! subpath would have generated it (the same walk run backwards).
//!
//! **MIS** ([`mis_weight`]): the power heuristic (β = 2, thesis eq. 9.13) over
//! all strategies that could have produced the same path,
//! `w_{s,t} = p_s² / Σ_i p_i²` with `p_i` short for `p_{i, s+t−i}`. Only ratios
//! are needed (thesis, eq. 10.9): moving the connection one vertex along the
//! path changes a single factor, `p_{i+1}/p_i = p_rev(x_i) / p_fwd(x_i)`, so
//! `w_{s,t} = 1 / (1 + Σ_{i≠s} (p_i/p_s)²)` is computed from the stored pairs
//! by running products. This is pbrt-v4's `MISWeight` (with the power
//! heuristic instead of the balance heuristic); SmallVCM's running `dVCM/dVC`
//! quantities compute the same sums incrementally.
//!
//! **Deltas.** A mirror or glass vertex cannot be connected to (its `f_r` is a
//! delta): a strategy that would connect at it, or next to it, has density 0
//! and is skipped in the sum; its zero pdfs are remapped to 1 so that the
//! running products stay finite. A point light is a delta in position: no path
//! can hit it, so the strategy `s = 0` is skipped for it.
//!
//! **Depth.** Mitsuba's `max_depth = D` allows at most `D − 1` scattering
//! vertices, i.e. `s + t − 2 ≤ D − 1`: paths of at most `D + 1` vertices.
//!
//! Not handled (documented limits): pbrt's correction factor for shading
//! normals in importance transport (our shapes shade with their geometric
//! normal except smooth meshes), and environment lights on the light side
//! (light subpaths that start at the environment are dropped; bidirectional
//! tracing counts the environment through camera paths that escape, `s = 0`,
//! the only strategy that can then produce such paths, with weight 1).

use crate::brdf::TransportMode;
use crate::camera::CameraSample;
use crate::frame::Frame;
use crate::light::Light;
use crate::math::{Color, Ray, UVec2, Vec2, Vec3A};
use crate::sampling::Sampler;
use crate::scene::{Interaction, Scene};

/// Capacity of a subpath buffer (vertices). With unlimited depth Russian
/// roulette ends paths long before: a path of 64 vertices has survived 63
/// bounces (probability below 0.95^58 ≈ 0.05 even at the roulette's cap, and
/// far less at realistic albedos); the truncation drops that tail.
pub const MAX_VERTICES: usize = 64;

/// No light at this vertex.
pub const NO_LIGHT: u32 = u32::MAX;

/// What a vertex is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VertexKind {
    /// `z_0`, the lens point.
    Camera,
    /// `y_0`, the point on a light.
    Light,
    /// A scattering point on a surface.
    Surface,
}

/// A vertex of a camera or light subpath.
#[derive(Clone, Copy, Debug)]
pub struct Vertex {
    pub kind: VertexKind,
    /// Position, geometric normal (zero for a point light and a pinhole:
    /// no surface), shading frame, `ω_o` = unit direction towards the
    /// previous vertex of the same subpath.
    pub it: Interaction,
    /// The light at this vertex: its index for a `Light` vertex, the area
    /// light of an emitting surface, or [`NO_LIGHT`].
    pub light: u32,
    /// Throughput of the subpath up to and including this vertex: for a camera
    /// subpath `W_e Π f_r |cos| / p` (radiance weight), for a light subpath
    /// `L_e Π f_r |cos| / p` (a flux estimate), the last factor excluded (it
    /// depends on where the path goes next).
    pub beta: Color,
    /// Area density with which this vertex's own subpath generated it.
    pub pdf_fwd: f32,
    /// Area density with which the other subpath would generate it.
    pub pdf_rev: f32,
    /// Whether the scattering at this vertex was sampled from a delta lobe.
    pub delta: bool,
}

/// A placeholder vertex for buffers (overwritten before use).
pub const EMPTY_VERTEX: Vertex = Vertex {
    kind: VertexKind::Surface,
    it: Interaction {
        p: Vec3A::ZERO,
        ng: Vec3A::ZERO,
        frame: Frame {
            s: Vec3A::X,
            t: Vec3A::Y,
            n: Vec3A::Z,
        },
        uv: Vec2::ZERO,
        wo: Vec3A::ZERO,
        t: 0.0,
        shape: u32::MAX,
    },
    light: NO_LIGHT,
    beta: Color::ZERO,
    pdf_fwd: 0.0,
    pdf_rev: 0.0,
    delta: false,
};

/// A subpath buffer, allocated once per sample on the stack.
pub type Subpath = [Vertex; MAX_VERTICES];

/// The number of vertices a subpath buffer may hold for Mitsuba's max depth
/// `D` (paths of at most `D + 1` vertices), capped by [`MAX_VERTICES`].
#[inline]
pub fn path_vertices(max_depth: Option<u32>) -> usize {
    max_depth.map_or(MAX_VERTICES, |d| (d as usize + 1).min(MAX_VERTICES))
}

/// `p_A(y) = p_ω · |cos θ_y| / ‖x − y‖²` (thesis eq. 8.10): a solid-angle
/// density at `from` turned into an area density at `to` (no cosine if `to`
/// is not on a surface: a point light or a pinhole).
#[inline]
pub fn convert_density(pdf_w: f32, from: &Vertex, to: &Vertex) -> f32 {
    let d = to.it.p - from.it.p;
    let d2 = d.length_squared();
    if d2 == 0.0 {
        return 0.0;
    }
    let mut pdf = pdf_w / d2;
    if to.is_on_surface() {
        pdf *= to.it.ng.dot(d).abs() / d2.sqrt();
    }
    pdf
}

/// An interaction for a point that is not a ray hit (lens or light point).
#[inline]
fn point_interaction(p: Vec3A, n: Vec3A) -> Interaction {
    let frame = if n == Vec3A::ZERO {
        Frame::from_normal(Vec3A::Z)
    } else {
        Frame::from_normal(n)
    };
    Interaction {
        p,
        ng: n,
        frame,
        uv: Vec2::ZERO,
        wo: Vec3A::ZERO,
        t: 0.0,
        shape: u32::MAX,
    }
}

/// `L_e` leaving light `light` at a point with normal `n` in direction `w`;
/// for a point light its intensity `I` (W/sr), which plays the same role.
#[inline]
pub fn emitted(scene: &Scene, light: u32, n: Vec3A, w: Vec3A) -> Color {
    match &scene.lights[light as usize] {
        Light::Point(l) => l.intensity,
        l => l.le(n, w),
    }
}

impl Vertex {
    /// The lens point `z_0` with throughput `beta`.
    pub fn camera(p: Vec3A, beta: Color) -> Vertex {
        Vertex {
            kind: VertexKind::Camera,
            it: point_interaction(p, Vec3A::ZERO),
            beta,
            ..EMPTY_VERTEX
        }
    }

    /// The light point `y_0` on light `light` (normal `n`, zero for a point
    /// light) with throughput `beta` and forward density `pdf_fwd`.
    pub fn light(light: u32, p: Vec3A, n: Vec3A, beta: Color, pdf_fwd: f32) -> Vertex {
        Vertex {
            kind: VertexKind::Light,
            it: point_interaction(p, n),
            light,
            beta,
            pdf_fwd,
            ..EMPTY_VERTEX
        }
    }

    /// A surface point found by a ray.
    pub fn surface(scene: &Scene, it: Interaction, beta: Color) -> Vertex {
        Vertex {
            kind: VertexKind::Surface,
            it,
            light: scene.area_light(&it).map_or(NO_LIGHT, |(i, _)| i),
            beta,
            ..EMPTY_VERTEX
        }
    }

    #[inline]
    pub fn p(&self) -> Vec3A {
        self.it.p
    }

    /// Whether the vertex lies on a surface (area measure with a cosine).
    #[inline]
    pub fn is_on_surface(&self) -> bool {
        self.it.ng != Vec3A::ZERO
    }

    /// Whether a deterministic connection may end here: not at a mirror or
    /// glass surface (its `f_r` is a delta, zero for every given direction).
    #[inline]
    pub fn is_connectible(&self, scene: &Scene) -> bool {
        match self.kind {
            VertexKind::Surface => !scene.brdf(&self.it).is_delta(),
            VertexKind::Light | VertexKind::Camera => true,
        }
    }

    /// Whether this is a point-light vertex (a delta in position).
    #[inline]
    pub fn is_delta_light(&self, scene: &Scene) -> bool {
        self.kind == VertexKind::Light && scene.lights[self.light as usize].is_delta()
    }

    /// The scattering function towards the unit world direction `w`:
    /// `f_r(ω_o, w)` at a surface, `L_e(w)` at a light vertex.
    #[inline]
    pub fn f(&self, scene: &Scene, w: Vec3A) -> Color {
        match self.kind {
            VertexKind::Surface => {
                let fr = &self.it.frame;
                scene
                    .brdf(&self.it)
                    .eval(fr.to_local(self.it.wo), fr.to_local(w), self.it.uv)
            }
            VertexKind::Light => emitted(scene, self.light, self.it.ng, w),
            VertexKind::Camera => Color::ZERO,
        }
    }

    /// `|cos θ|` of the unit direction `w` at this vertex: with the shading
    /// normal at a surface, the light's normal at an area light, 1 where there
    /// is no surface (point light).
    #[inline]
    pub fn abs_cos(&self, w: Vec3A) -> f32 {
        match self.kind {
            VertexKind::Surface => self.it.frame.n.dot(w).abs(),
            _ if self.is_on_surface() => self.it.ng.dot(w).abs(),
            _ => 1.0,
        }
    }

    /// `L_e` this (emitting surface or light) vertex sends towards `to`.
    #[inline]
    pub fn le_towards(&self, scene: &Scene, to: &Vertex) -> Color {
        if self.light == NO_LIGHT {
            return Color::ZERO;
        }
        let w = (to.p() - self.p()).normalize_or_zero();
        emitted(scene, self.light, self.it.ng, w)
    }

    /// Area density at `next` of sampling it from this vertex, having arrived
    /// from `prev`: the BRDF's `p_ω(ω_o → ω_i)` at a surface, the camera's
    /// direction density at the lens, the emission's direction density at a
    /// light — each converted to area measure at `next`.
    pub fn pdf(&self, scene: &Scene, prev: Option<&Vertex>, next: &Vertex) -> f32 {
        let w = (next.p() - self.p()).normalize_or_zero();
        let pdf_w = match self.kind {
            VertexKind::Camera => scene.camera.pdf_we(&Ray::new(self.p(), w)).1,
            VertexKind::Light => return self.pdf_light(scene, next),
            VertexKind::Surface => {
                let Some(prev) = prev else { return 0.0 };
                let wo = (prev.p() - self.p()).normalize_or_zero();
                let fr = &self.it.frame;
                scene
                    .brdf(&self.it)
                    .pdf(fr.to_local(wo), fr.to_local(w), self.it.uv)
            }
        };
        convert_density(pdf_w, self, next)
    }

    /// Area density at `next` of a light path that starts at this (light or
    /// emitting surface) vertex and leaves towards `next`: the emission's
    /// `p_ω` converted to area measure.
    pub fn pdf_light(&self, scene: &Scene, next: &Vertex) -> f32 {
        if self.light == NO_LIGHT {
            return 0.0;
        }
        let w = (next.p() - self.p()).normalize_or_zero();
        let (_, pdf_w) = scene.lights[self.light as usize].pdf_le(self.p(), self.it.ng, w);
        convert_density(pdf_w, self, next)
    }

    /// Area density of this point as the origin of a light path:
    /// `P(light) · p_A` of `sample_le`.
    pub fn pdf_light_origin(&self, scene: &Scene) -> f32 {
        if self.light == NO_LIGHT {
            return 0.0;
        }
        let light = &scene.lights[self.light as usize];
        let (pdf_a, _) = light.pdf_le(self.p(), self.it.ng, self.it.ng);
        scene.light_pmf(self.light) * pdf_a
    }
}

/// How a random walk ended.
#[derive(Clone, Copy, Debug)]
pub struct WalkEnd {
    /// Number of vertices in the buffer (the start vertex included).
    pub vertices: usize,
    /// Throughput and direction of a ray that left the scene (camera
    /// subpaths only: it sees the environment).
    pub escaped: Option<(Color, Vec3A)>,
}

/// Extends the subpath whose last vertex is `path[0..start+1]` by a random
/// walk: `ray` leaves `path[start]` with solid-angle density `pdf_w`, and
/// `beta` is the throughput the first new vertex gets. At every surface the
/// BRDF is sampled in transport mode `mode`; each new vertex records
/// `pdf_fwd`, and its predecessor `pdf_rev` (the reverse walk's density, the
/// BRDF's `pdf(ω_i → ω_o)`). Stops at `max_vertices`, at a failed sample or by
/// Russian roulette after `rr_depth` scattering events (which divides the
/// survivors' throughput by their probability `q`).
#[allow(clippy::too_many_arguments)]
pub fn random_walk(
    scene: &Scene,
    path: &mut Subpath,
    start: usize,
    mut ray: Ray,
    mut beta: Color,
    mut pdf_w: f32,
    mode: TransportMode,
    max_vertices: usize,
    rr_depth: u32,
    sampler: &mut Sampler,
) -> WalkEnd {
    let max_vertices = max_vertices.min(MAX_VERTICES);
    let mut n = start + 1;
    // The walk's own throughput Π f |cos| / p (without the start's L_e or
    // W_e), for Russian roulette; `eta_scale` undoes glass's 1/η² on radiance.
    let mut walk = Color::ONE;
    let mut eta_scale = 1.0f32;
    let mut scatterings = 0u32;
    while n < max_vertices {
        let Some(it) = scene.intersect(&ray) else {
            let escaped = (mode == TransportMode::Radiance).then_some((beta, ray.d));
            return WalkEnd {
                vertices: n,
                escaped,
            };
        };
        let mut v = Vertex::surface(scene, it, beta);
        v.pdf_fwd = convert_density(pdf_w, &path[n - 1], &v);
        path[n] = v;
        n += 1;
        if n >= max_vertices {
            break;
        }
        let brdf = scene.brdf(&it);
        let wo = it.frame.to_local(it.wo);
        let (u_lobe, u) = (sampler.next_1d(), sampler.next_2d());
        let Some(bs) = brdf.sample(wo, it.uv, u_lobe, u, mode) else {
            break;
        };
        pdf_w = bs.pdf_w;
        // The reverse walk would sample ω_o from ω_i.
        let mut pdf_rev = brdf.pdf(bs.wi, wo, it.uv);
        if bs.is_delta {
            path[n - 1].delta = true;
            pdf_w = 0.0;
            pdf_rev = 0.0;
        }
        let factor = bs.f * (bs.wi.z.abs() / bs.pdf_w);
        beta *= factor;
        walk *= factor;
        if mode == TransportMode::Radiance {
            eta_scale *= bs.eta * bs.eta;
        }
        let (cur, prev) = (path[n - 1], path[n - 2]);
        path[n - 2].pdf_rev = convert_density(pdf_rev, &cur, &prev);
        ray = it.spawn_ray(it.frame.to_world(bs.wi));
        scatterings += 1;
        if scatterings >= rr_depth {
            let q = (walk.max_element() * eta_scale).min(0.95);
            if q <= 0.0 || sampler.next_1d() >= q {
                break;
            }
            beta /= q;
            walk /= q;
        }
    }
    WalkEnd {
        vertices: n,
        escaped: None,
    }
}

/// The camera subpath `z_0 z_1 …` of a pixel sample: `z_0` on the lens with
/// `β = W_e cos θ / (p_A p_ω) = 1` (a pixel sample's importance is 1), then a
/// random walk in radiance mode. Uses the sampler's next four numbers for the
/// primary ray.
pub fn camera_subpath(
    scene: &Scene,
    pixel: UVec2,
    sampler: &mut Sampler,
    path: &mut Subpath,
    max_vertices: usize,
    rr_depth: u32,
) -> WalkEnd {
    let ray = super::camera_ray(scene, pixel, sampler);
    path[0] = Vertex::camera(ray.o, Color::ONE);
    if max_vertices < 2 {
        return WalkEnd {
            vertices: 1,
            escaped: None,
        };
    }
    // p_ω of the primary ray over the whole film (see `camera::pdf_we`).
    let (_, pdf_w) = scene.camera.pdf_we(&ray);
    random_walk(
        scene,
        path,
        0,
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
/// applied by whoever leaves it), the walk starts with
/// `β_1 = L_e(y_0, ω) |cos θ_0| / (P(light) p_A p_ω)`, in importance mode.
/// Returns the number of vertices (0 if no light path could start, e.g. the
/// environment was chosen: not supported on the light side).
pub fn light_subpath(
    scene: &Scene,
    sampler: &mut Sampler,
    path: &mut Subpath,
    max_vertices: usize,
    rr_depth: u32,
) -> usize {
    let u_choice = sampler.next_1d();
    let (u_pos, u_dir) = (sampler.next_2d(), sampler.next_2d());
    if max_vertices == 0 {
        return 0;
    }
    let Some((index, light, pmf)) = scene.choose_light(u_choice) else {
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
    path[0] = Vertex::light(
        index,
        e.ray.o,
        e.n,
        Color::splat(1.0 / pdf_origin),
        pdf_origin,
    );
    if max_vertices < 2 {
        return 1;
    }
    let cos0 = path[0].abs_cos(e.ray.d);
    let beta = e.le * (cos0 / (pdf_origin * e.pdf_w));
    random_walk(
        scene,
        path,
        0,
        e.ray,
        beta,
        e.pdf_w,
        TransportMode::Importance,
        max_vertices,
        rr_depth,
        sampler,
    )
    .vertices
}

/// Whether nothing blocks the segment between vertices `a` and `b`.
#[inline]
pub fn visible(scene: &Scene, a: &Vertex, b: &Vertex) -> bool {
    scene.unoccluded(&Ray::spawn_to(a.p(), a.it.ng, b.p(), b.it.ng))
}

/// The `t = 1` connection: light-subpath vertex `q` joined to a lens point
/// chosen by `u_lens`. Its contribution to the pixel at `CameraSample::raster`
/// is (Veach's light tracing estimate)
///
/// ```text
///   β_q · f(ω_o, ω_c) · |cos θ_q| · G-part · W_e / p_A(lens)
///     = β_q · f(ω_o, ω_c) · |cos θ_q| · W_e / p_ω(lens),
/// ```
///
/// because `G(q, lens) / p_A(lens) = |cos θ_q| |cos θ_lens| / (d² p_A)` and
/// `camera.sample_wi` returns `p_ω = d² / (cos θ_lens · A_lens)` (the lens
/// density per unit solid angle at `q`). Visibility-tested. `None` if the
/// point is off the film, behind the camera or in shadow.
pub fn connect_to_camera(scene: &Scene, q: &Vertex, u_lens: Vec2) -> Option<(CameraSample, Color)> {
    if !q.is_connectible(scene) {
        return None;
    }
    let cs = scene.camera.sample_wi(q.p(), u_lens)?;
    let l = q.beta * q.f(scene, cs.wi) * (q.abs_cos(cs.wi) * cs.we / cs.pdf_w);
    if l == Color::ZERO {
        return None;
    }
    let lens = Vertex::camera(cs.p_lens, Color::ZERO);
    visible(scene, q, &lens).then_some((cs, l))
}

/// Veach's MIS weight (power heuristic) of strategy `(s, t)` for the path
/// `light[0..s] camera[t−1..0]`. `sampled` replaces `light[0]` (if `s = 1`:
/// the resampled light point, t ≥ 2) or `camera[0]` (if `t = 1`: the lens point of
/// the connection). The connection changes four reverse densities — those of
/// the two endpoints and their predecessors, which now depend on the other
/// subpath — so they are set here and restored afterwards.
///
/// With `r_i = p_i / p_s` built by running products of
/// `p_rev(x)/p_fwd(x)` (thesis eq. 10.9), the weight is `1 / Σ_i r_i²`
/// (power heuristic, `r_s = 1`), skipping strategies whose connection would
/// touch a delta vertex (their density is zero).
pub fn mis_weight(
    scene: &Scene,
    light: &mut Subpath,
    camera: &mut Subpath,
    s: usize,
    t: usize,
    sampled: Option<Vertex>,
) -> f32 {
    debug_assert!(
        t >= 1 && s + t >= 2,
        "strategy ({s}, {t}) has no camera vertex"
    );
    // Save what we change.
    let saved_l: [Option<Vertex>; 2] = [
        s.checked_sub(1).map(|i| light[i]),
        s.checked_sub(2).map(|i| light[i]),
    ];
    let saved_c: [Option<Vertex>; 2] = [
        t.checked_sub(1).map(|i| camera[i]),
        t.checked_sub(2).map(|i| camera[i]),
    ];
    if let Some(v) = sampled {
        // (1, 1) resamples the lens point, not the light point.
        if t == 1 {
            camera[0] = v;
        } else if s == 1 {
            light[0] = v;
        }
    }
    // Endpoints are connected deterministically: not deltas for the sums.
    if s > 0 {
        light[s - 1].delta = false;
    }
    if t > 0 {
        camera[t - 1].delta = false;
    }
    let qs = (s > 0).then(|| light[s - 1]);
    let qs_minus = (s > 1).then(|| light[s - 2]);
    let pt = camera[t - 1];
    let pt_minus = (t > 1).then(|| camera[t - 2]);
    // Reverse densities across the connection.
    camera[t - 1].pdf_rev = match &qs {
        Some(q) => q.pdf(scene, qs_minus.as_ref(), &pt),
        None => pt.pdf_light_origin(scene),
    };
    if let Some(pm) = &pt_minus {
        camera[t - 2].pdf_rev = match &qs {
            Some(q) => pt.pdf(scene, Some(q), pm),
            None => pt.pdf_light(scene, pm),
        };
    }
    if let Some(q) = &qs {
        light[s - 1].pdf_rev = pt.pdf(scene, pt_minus.as_ref(), q);
        if let Some(qm) = &qs_minus {
            light[s - 2].pdf_rev = q.pdf(scene, Some(&pt), qm);
        }
    }
    #[inline]
    fn remap0(p: f32) -> f32 {
        if p != 0.0 { p } else { 1.0 }
    }
    let mut sum = 0.0f32;
    // Strategies with fewer camera vertices: (s+1, t−1), (s+2, t−2), …, down to t' = 1
    // (a light path cannot hit a pinhole: t' = 0 is never a strategy).
    let mut r = 1.0f32;
    for i in (1..t).rev() {
        r *= remap0(camera[i].pdf_rev) / remap0(camera[i].pdf_fwd);
        if !camera[i].delta && !camera[i - 1].delta {
            sum += r * r;
        }
    }
    // Strategies with fewer light vertices: (s−1, t+1), …, (0, s+t).
    let mut r = 1.0f32;
    for i in (0..s).rev() {
        r *= remap0(light[i].pdf_rev) / remap0(light[i].pdf_fwd);
        let delta_before = if i > 0 {
            light[i - 1].delta
        } else {
            light[0].is_delta_light(scene)
        };
        if !light[i].delta && !delta_before {
            sum += r * r;
        }
    }
    // Restore.
    if let Some(v) = saved_l[0] {
        light[s - 1] = v;
    }
    if let Some(v) = saved_l[1] {
        light[s - 2] = v;
    }
    if let Some(v) = saved_c[0] {
        camera[t - 1] = v;
    }
    if let Some(v) = saved_c[1] {
        camera[t - 2] = v;
    }
    let w = 1.0 / (1.0 + sum);
    if w.is_finite() { w } else { 0.0 }
}
