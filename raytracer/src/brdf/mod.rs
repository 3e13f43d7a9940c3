//! BRDFs: how a surface scatters light, `f_r(x, ω_i → ω_o)`.
//!
//! Lecture topic: "BRDF-и" — the bidirectional reflectance distribution
//! function, its reciprocity `f_r(ω_i→ω_o) = f_r(ω_o→ω_i)` and energy
//! conservation `∫ f_r cos θ_i dω_i ≤ 1`.
//!
//! Contract (every model obeys it; tests beside each model prove it):
//! - everything is in the local shading frame of [`crate::frame`]: the normal
//!   is `+z`, and `cos θ` of a direction is its `z`;
//! - [`Brdf::eval`] returns `f_r` alone. The cosine of the rendering equation
//!   belongs to the integrator, as on the slide `L_o = L_e + ∫ f_r L_i cos θ_i dω_i`;
//! - [`Brdf::sample`] returns a [`BrdfSample`]: the direction `wi`, the value
//!   `f`, its pdf per unit solid angle and whether the lobe is a delta;
//! - `eval`, `sample` and `pdf` agree with each other (chi-square tests);
//! - reflective models are two-sided: seen from below they behave as from
//!   above (the frame is mirrored), so meshes with any winding look right.
//!   Glass distinguishes the sides: the normal points out of the glass.
//!
//! Delta lobes (mirror, glass) follow pbrt's convention: the sample's `f` is
//! already divided by `|cos θ_i|` and its pdf is the probability of choosing
//! the lobe, so the usual estimator `f · |cos θ_i| / pdf` gives the right
//! weight; `eval` and `pdf` of a delta lobe are zero for any given pair of
//! directions (the chance of hitting the delta direction is zero).

pub mod glass;
pub mod lambert;
pub mod mirror;
pub mod phong;
pub mod texture;

use crate::math::{Color, Vec3A};

pub use glass::Glass;
pub use lambert::Lambert;
pub use mirror::Mirror;
pub use phong::Phong;
pub use texture::{ImageTexture, Texture};

/// Which quantity a path carries: radiance from the camera's side (path
/// tracing) or importance from the light's side (light tracing). Refraction is
/// not symmetric: radiance is scaled by `1/η²` across an interface, importance
/// is not (Veach's thesis, section 5.2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TransportMode {
    Radiance,
    Importance,
}

/// A sampled direction with its BRDF value and density.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BrdfSample {
    /// Sampled direction `ω_i`, local frame.
    pub wi: Vec3A,
    /// `f_r(ω_i → ω_o)` (for a delta lobe: the delta's weight divided by `|cos θ_i|`).
    pub f: Color,
    /// Density of `wi` per unit solid angle (for a delta lobe: the lobe's probability).
    pub pdf_w: f32,
    /// Whether `wi` came from a delta (specular) lobe.
    pub is_delta: bool,
    /// Relative index of refraction `η_i/η_t` crossed by `wi` (1 for reflection).
    pub eta: f32,
}

/// The BRDF models of the course (an enum: a closed set, dispatched by `match`).
#[derive(Clone, Debug)]
pub enum Brdf {
    Lambert(Lambert),
    Phong(Phong),
    Mirror(Mirror),
    Glass(Glass),
}
