//! Path vertices and their densities: the shared machinery of light tracing
//! and bidirectional path tracing.
//!
//! Lecture topic: "Paths", "Light tracing" and "Bidirectional path tracing".
//! A path is a sequence of points `x̄ = x_0 x_1 … x_k` whose first point lies
//! on the lens and whose last lies on a light. Its contribution to pixel `j`
//! is Veach's measurement contribution function (thesis, eq. 8.7)
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
//! that reaches `y` gives `y` an area density `p_A(y)`: the same probability
//! per unit area instead of per unit solid angle, the change of measure of
//! the lecture's `dω = cos θ_y dA / r²` (thesis, eq. 8.10; exercise 12
//! derives it, [`pdf_w_to_a`] computes it). Every vertex
//! stores two of them, as in pbrt-v4: `pdf_fwd_a`, the density with which its
//! own subpath generated it, and `pdf_rev_a`, the density with which the
//! *other* subpath would have generated it (the same walk run backwards).
//! Density names end in their measure, as in SmallVCM: `_w` per unit solid
//! angle, `_a` per unit area.
//!
//! **Deltas.** A mirror or glass vertex cannot be connected to (its `f_r` is a
//! delta, [`Vertex::is_connectible`]); a point light is a delta in position
//! ([`Vertex::is_delta_light`]): no path can hit it.
//!
//! The other parts of the machinery, one file each: [`super::subpath`] (the
//! random walks that grow camera and light subpaths), [`super::camera_connection`]
//! (the `t = 1` connection of a light vertex to the lens) and [`super::mis_weight`]
//! (the MIS weight of a strategy).
//!
//! Shading normals: light-subpath vertices scatter with the adjoint BRDF
//! ([`super::shading_normals`]); densities are those of the BRDF's sampling.

use std::cell::RefCell;

use super::shading_normals::importance_correction;
use crate::frame::Frame;
use crate::geometry::Interaction;
use crate::math::{Color, Ray, RayEnd, Vec2, Vec3A};
use crate::scene::Scene;

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
    pub pdf_fwd_a: f32,
    /// Area density with which the other subpath would generate it.
    pub pdf_rev_a: f32,
    /// Whether the scattering at this vertex was sampled from a delta lobe.
    pub delta: bool,
}

/// A placeholder vertex (the constructors fill in what they know).
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
        p_error: Vec3A::ZERO,
    },
    light: NO_LIGHT,
    beta: Color::ZERO,
    pdf_fwd_a: 0.0,
    pdf_rev_a: 0.0,
    delta: false,
};

/// A subpath: its vertices from the lens or the light on, as many as the
/// walk made (no fixed capacity: the max depth is the only limit, as for
/// the path tracer).
pub type Subpath = Vec<Vertex>;

thread_local! {
    /// Subpath buffers of this thread, kept between samples.
    static SUBPATHS: RefCell<Vec<Subpath>> = const { RefCell::new(Vec::new()) };
}

/// Runs `f` with two subpath buffers of this thread (a camera and a light
/// subpath): they keep their capacity from sample to sample, so a render
/// allocates them once per thread, not once per sample. Their contents are
/// whatever the last user left (the walks clear them).
pub fn with_subpaths<R>(f: impl FnOnce(&mut Subpath, &mut Subpath) -> R) -> R {
    let take = || SUBPATHS.with(|s| s.borrow_mut().pop().unwrap_or_default());
    let (mut a, mut b) = (take(), take());
    let result = f(&mut a, &mut b);
    SUBPATHS.with(|s| s.borrow_mut().extend([a, b]));
    result
}

/// The number of vertices a subpath may hold for Mitsuba's max depth `D`
/// (paths of at most `D + 1` vertices); unlimited for `None`.
#[inline]
pub fn path_vertices(max_depth: Option<u32>) -> usize {
    max_depth.map_or(usize::MAX, |d| d as usize + 1)
}

/// A solid-angle density at `from` turned into an area density at `to`
/// (thesis eq. 8.10: the change of measure `dω = |cos θ_y| dA / r²`; no
/// cosine if `to` is not on a surface: a point light or a pinhole).
#[inline]
pub fn pdf_w_to_a(pdf_w: f32, from: &Vertex, to: &Vertex) -> f32 {
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
        p_error: RayEnd::estimated(p, n).error,
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
    /// light) with throughput `beta` and forward density `pdf_fwd_a`.
    pub fn light(light: u32, p: Vec3A, n: Vec3A, beta: Color, pdf_fwd_a: f32) -> Vertex {
        Vertex {
            kind: VertexKind::Light,
            it: point_interaction(p, n),
            light,
            beta,
            pdf_fwd_a,
            ..EMPTY_VERTEX
        }
    }

    /// A surface point found by a ray.
    pub fn surface(scene: &Scene, it: Interaction, beta: Color) -> Vertex {
        Vertex {
            kind: VertexKind::Surface,
            it,
            light: scene.area_light(&it).unwrap_or(NO_LIGHT),
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
            VertexKind::Light => scene.emitted_by(self.light, self.it.ng, w),
            VertexKind::Camera => Color::ZERO,
        }
    }

    /// [`Vertex::f`] of a light-subpath vertex, which scatters importance:
    /// at a surface the BRDF times the adjoint correction for shading
    /// normals ([`importance_correction`], `ω_o` towards the previous light
    /// vertex, `w` onwards); at a light `L_e` as in `f`.
    #[inline]
    pub fn f_importance(&self, scene: &Scene, w: Vec3A) -> Color {
        let f = self.f(scene, w);
        match self.kind {
            VertexKind::Surface => f * importance_correction(&self.it, self.it.wo, w),
            _ => f,
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
        scene.emitted_by(self.light, self.it.ng, w)
    }

    /// Area density at `next` of sampling it from this vertex, having arrived
    /// from `prev`: the BRDF's `p_ω(ω_o → ω_i)` at a surface, the camera's
    /// direction density at the lens, the emission's direction density at a
    /// light — each converted to area measure at `next`.
    pub fn pdf_a(&self, scene: &Scene, prev: Option<&Vertex>, next: &Vertex) -> f32 {
        let w = (next.p() - self.p()).normalize_or_zero();
        let pdf_w = match self.kind {
            VertexKind::Camera => scene.camera.pdf_we(&Ray::new(self.p(), w)).pdf_w,
            VertexKind::Light => return self.pdf_light_a(scene, next),
            VertexKind::Surface => {
                let Some(prev) = prev else { return 0.0 };
                let wo = (prev.p() - self.p()).normalize_or_zero();
                let fr = &self.it.frame;
                scene
                    .brdf(&self.it)
                    .pdf(fr.to_local(wo), fr.to_local(w), self.it.uv)
            }
        };
        pdf_w_to_a(pdf_w, self, next)
    }

    /// Area density at `next` of a light path that starts at this (light or
    /// emitting surface) vertex and leaves towards `next`: the emission's
    /// `p_ω` converted to area measure.
    pub fn pdf_light_a(&self, scene: &Scene, next: &Vertex) -> f32 {
        if self.light == NO_LIGHT {
            return 0.0;
        }
        let w = (next.p() - self.p()).normalize_or_zero();
        let emission = scene.lights[self.light as usize].pdf_le(self.p(), self.it.ng, w);
        pdf_w_to_a(emission.pdf_w, self, next)
    }

    /// Area density of this point as the origin of a light path:
    /// `P(light) · p_A` of `sample_le`.
    pub fn pdf_light_origin_a(&self, scene: &Scene) -> f32 {
        if self.light == NO_LIGHT {
            return 0.0;
        }
        let light = &scene.lights[self.light as usize];
        let emission = light.pdf_le(self.p(), self.it.ng, self.it.ng);
        scene.light_pmf(self.light) * emission.pdf_a
    }

    /// Area density with which next event estimation at `from` picks this
    /// (light or emitting surface) point — the strategy `s = 1` of
    /// bidirectional tracing: the light's choice probability times the
    /// density of [`crate::light::Light::pdf_li_w`], changed from solid angle
    /// to area. For a quad that is the
    /// origin density `P(light)/A`; for a sphere seen from outside, the
    /// cone's density (zero off the cap `from` sees); for a point light the
    /// origin density (the point is fixed).
    pub fn pdf_light_point_a(&self, scene: &Scene, from: &Vertex) -> f32 {
        if self.light == NO_LIGHT {
            return 0.0;
        }
        let light = &scene.lights[self.light as usize];
        if light.is_delta() {
            return self.pdf_light_origin_a(scene);
        }
        let d = self.p() - from.p();
        let d2 = d.length_squared();
        if d2 == 0.0 {
            return 0.0;
        }
        let wi = d / d2.sqrt();
        let pdf_w = light.pdf_li_w(from.p(), self.p(), self.it.ng, wi);
        scene.light_pmf(self.light) * pdf_w * self.it.ng.dot(wi).abs() / d2
    }
}

/// Whether nothing blocks the segment between vertices `a` and `b`.
#[inline]
pub fn visible(scene: &Scene, a: &Vertex, b: &Vertex) -> bool {
    scene.unoccluded(&Ray::spawn_between(a.it.ray_end(), b.it.ray_end()))
}
