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
//! - **report densities** for MIS: [`Light::pdf_li`] is the pdf `sample_li`
//!   would have had for a direction that a BRDF sample happened to send into
//!   the light;
//! - **emit** a ray: [`Light::sample_le`] starts a light path (an [`Emission`]
//!   with its position pdf per unit area and direction pdf per unit solid
//!   angle, kept apart for bidirectional MIS).

pub mod area;
pub mod environment;
pub mod point;

use crate::math::{Color, Ray, Vec3A};

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
