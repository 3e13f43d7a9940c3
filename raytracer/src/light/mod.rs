//! Lights: where the emitted radiance `L_e` of the rendering equation comes from.
//!
//! Lecture topic: the `L_e` term of Kajiya's rendering equation, and the light
//! side of light tracing and bidirectional path tracing.
//!
//! Every light does three things (pbrt's and SmallVCM's interface):
//! - **illuminate** a point: [`Light::sample_li`] picks a point on the light
//!   as seen from a receiving point and returns a [`LightSample`] (direction,
//!   radiance, pdf per unit solid angle at the receiver, distance) — next event
//!   estimation;
//! - **report densities** for MIS: [`Light::pdf_li_w`] is the pdf per unit
//!   solid angle `sample_li` would have had for a direction that a BRDF
//!   sample happened to send into the light, and [`Light::pdf_le`] the
//!   densities of an emitted ray (a [`RayPdf`]);
//! - **emit** a ray: [`Light::sample_le`] starts a light path (an [`Emission`]
//!   with its position pdf per unit area and direction pdf per unit solid
//!   angle, kept apart for bidirectional MIS).
//!
//! Names of densities carry their measure, as in SmallVCM: `_w` per unit
//! solid angle, `_a` per unit area.

pub mod area;
pub mod environment;
pub mod point;

use crate::math::{Color, INV_4PI, Ray, RayPdf, Vec2, Vec3A};

pub use area::{AreaLight, AreaShape};
pub use environment::{EnvironmentLight, EnvironmentMap};
pub use point::PointLight;

/// A light sampled from a receiving point (next event estimation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightSample {
    /// Unit direction from the receiver towards the light point.
    pub wi: Vec3A,
    /// Radiance arriving at the receiver along `-wi` (unoccluded).
    pub li: Color,
    /// Density of `wi` per unit solid angle at the receiver (for a point
    /// light: 1, meaning "a delta with weight one").
    pub pdf_w: f32,
    /// Distance to the light point (`f32::INFINITY` for the environment).
    pub dist: f32,
    /// The point on the light (for a shadow ray).
    pub p: Vec3A,
    /// The light's surface normal at `p` (zero for a point light or the
    /// environment).
    pub n: Vec3A,
    /// Whether the light is a delta in position (a point light): MIS cannot
    /// hit it with a BRDF sample.
    pub is_delta: bool,
}

/// A ray leaving a light (the first vertex of a light path).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Emission {
    /// The point on the light: on its surface, where the path's vertex `y_0`
    /// lies (the ray's origin is pushed off the surface; the vertex is not).
    pub p: Vec3A,
    /// The ray that leaves `p`: its origin offset off an area light's
    /// surface (see [`crate::math::Ray::spawn`]).
    pub ray: Ray,
    /// Surface normal at the ray's origin (zero for a point light; the
    /// direction of travel for the environment).
    pub n: Vec3A,
    /// Emitted radiance along the ray (for a point light: its intensity).
    pub le: Color,
    /// Density of the origin per unit area (1 for a point light).
    pub pdf_a: f32,
    /// Density of the direction per unit solid angle.
    pub pdf_w: f32,
    /// Whether the origin is a delta in position (point light).
    pub is_delta_position: bool,
}

/// The lights of the course (an enum: a closed set, dispatched by `match`).
#[derive(Clone, Debug)]
pub enum Light {
    Area(AreaLight),
    Point(PointLight),
    Environment(EnvironmentLight),
}

impl Light {
    /// Next event estimation: samples a point (direction) on the light as
    /// seen from the receiving point `p`. `None` if the light sends nothing
    /// to `p` (behind a one-sided light) or the sample is degenerate.
    ///
    /// - quad, sphere seen from inside: a point uniform by area, its density
    ///   converted to one per unit solid angle at `p`;
    /// - sphere seen from outside: uniform in the subtended cone,
    ///   `p_ω = 1/(2π(1 − cos θ_max))`;
    /// - point: `L_i = I/r²`, `p_ω = 1`, `is_delta`;
    /// - environment: uniform sphere (constant) or by the map's brightness,
    ///   `dist = ∞`.
    #[inline]
    pub fn sample_li(&self, p: Vec3A, u: Vec2) -> Option<LightSample> {
        match self {
            Light::Area(l) => l.sample_li(p, u),
            Light::Point(l) => l.sample_li(p),
            Light::Environment(l) => l.sample_li(p, u),
        }
    }

    /// The solid-angle density `sample_li(p, ·)` has for the direction `wi`
    /// that left `p` and hit the light at `p_light` with normal `n_light`
    /// (the environment ignores both; a point light returns 0: no direction
    /// hits it).
    #[inline]
    pub fn pdf_li_w(&self, p: Vec3A, p_light: Vec3A, n_light: Vec3A, wi: Vec3A) -> f32 {
        match self {
            Light::Area(l) => l.pdf_li_w(p, p_light, n_light, wi),
            Light::Point(_) => 0.0,
            Light::Environment(l) => l.pdf_li_w(wi),
        }
    }

    /// `L_e` leaving an area light's surface point with normal `n_light` in
    /// direction `w` (pointing away from the light, towards the viewer).
    /// Zero for a point light (no ray hits it) and for the environment (use
    /// [`Light::environment_radiance`] for escaping rays).
    #[inline]
    pub fn le(&self, n_light: Vec3A, w: Vec3A) -> Color {
        match self {
            Light::Area(l) => l.le(n_light, w),
            Light::Point(_) | Light::Environment(_) => Color::ZERO,
        }
    }

    /// Radiance a ray escaping with direction `d` sees from this light: the
    /// environment's [`EnvironmentLight::environment_radiance`], zero for
    /// the others.
    #[inline]
    pub fn environment_radiance(&self, d: Vec3A) -> Color {
        match self {
            Light::Environment(l) => l.environment_radiance(d),
            _ => Color::ZERO,
        }
    }

    /// Emits a ray (the first vertex of a light path), with its position
    /// density per unit area and direction density per unit solid angle:
    /// - area: uniform point (`1/A`), cosine-weighted direction on the
    ///   emitting side (`cos θ/π`, halved and either side if two-sided);
    /// - point: `p_A = 1`, uniform direction `1/(4π)`;
    /// - environment: direction as in `sample_li`, origin on a disk of the
    ///   scene's bounding radius `r` (`1/(π r²)`) beyond the scene.
    #[inline]
    pub fn sample_le(&self, u_pos: Vec2, u_dir: Vec2) -> Option<Emission> {
        match self {
            Light::Area(l) => l.sample_le(u_pos, u_dir),
            Light::Point(l) => Some(l.sample_le(u_dir)),
            Light::Environment(l) => l.sample_le(u_pos, u_dir),
        }
    }

    /// The densities `p_A` (origin) and `p_ω` (direction) with which
    /// `sample_le` emits from `p` (normal `n`) in direction `w` (direction of
    /// travel). Point light: `p_A = 1, p_ω = 1/(4π)`; environment: `p` and
    /// `n` are ignored.
    #[inline]
    pub fn pdf_le(&self, p: Vec3A, n: Vec3A, w: Vec3A) -> RayPdf {
        match self {
            Light::Area(l) => l.pdf_le(p, n, w),
            Light::Point(_) => RayPdf {
                pdf_a: 1.0,
                pdf_w: INV_4PI,
            },
            Light::Environment(l) => l.pdf_le(w),
        }
    }

    /// Emitted flux `Φ` (W): `π A L` per emitting side of an area light,
    /// `4π I` for a point light, `π r² ∫ L dω` for the environment (the flux
    /// through the scene's bounding disk; depends on the scene bounds).
    /// Lights are chosen in proportion to it (`Scene::choose_light`, unless
    /// `Scene::set_light_selection` asks for a uniform choice).
    #[inline]
    pub fn power(&self) -> Color {
        match self {
            Light::Area(l) => l.power(),
            Light::Point(l) => l.power(),
            Light::Environment(l) => l.power(),
        }
    }

    /// Whether the light is a delta in position (a point light).
    #[inline]
    pub fn is_delta(&self) -> bool {
        matches!(self, Light::Point(_))
    }

    /// Whether the light lies at infinity (rays that escape see it).
    #[inline]
    pub fn is_environment(&self) -> bool {
        matches!(self, Light::Environment(_))
    }
}
