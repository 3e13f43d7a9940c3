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
//! - a reflective model can be made **one-sided**, [`Brdf::OneSided`]:
//!   `f_r(ω_i → ω_o) = 0` unless both directions lie on the side of the
//!   shading normal (`ω_o.z > 0` and `ω_i.z > 0`), so the surface is black from
//!   behind. That is a statement about `f_r` alone — its support is the front
//!   hemisphere pair — so it fits the contract as it is: the integrator still
//!   multiplies by `|cos θ_i|`, and reciprocity holds (the condition is
//!   symmetric). Mitsuba's BSDFs are all one-sided (its `twosided` plugin is
//!   the adapter the other way round), so a scene that must match Mitsuba,
//!   `cornell`, asks for it (`sides = "front"` of a material in a scene file).
//!
//! The two-sidedness, the one-sidedness and the dropping of useless samples
//! (zero pdf, zero or non-finite value, a reflected direction on the wrong
//! side) happen in one place, the `match` of [`Brdf`]; the models only ever
//! see `ω_o` in the upper hemisphere (glass excepted). Files: one per model, [`fresnel`] for the
//! Fresnel equations and Snell's law, [`texture`] for spatially varying albedo.
//!
//! Delta lobes (mirror, glass) follow pbrt's convention: a delta has no
//! density over directions, so the sample's `pdf_w` is the probability of
//! choosing the lobe, and its `f` is the number that makes the usual Monte
//! Carlo estimate with this one draw give the delta's share of the reflected
//! radiance (exercise 6 derives it); `eval` and `pdf` of a delta lobe are zero for any given pair of
//! directions (the chance of hitting the delta direction is zero).

pub mod fresnel;
pub mod glass;
pub mod lambert;
pub mod mirror;
pub mod phong;
pub mod texture;

use crate::math::{Color, Vec2, Vec3A};

pub use fresnel::fresnel_dielectric;
pub use glass::Glass;
pub use lambert::Lambert;
pub use mirror::Mirror;
pub use phong::Phong;
pub use texture::{ImageTexture, Texture, srgb_to_linear};

/// Which quantity a path carries: radiance from the camera's side (path
/// tracing) or importance from the light's side (light tracing). Refraction is
/// not symmetric: radiance is scaled by `1/η²` across an interface, importance
/// is not (Veach's thesis, section 5.2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TransportMode {
    Radiance,
    Importance,
}

/// A sampled direction with its BRDF value and its density: what a Monte
/// Carlo estimate of the reflected radiance needs of one draw (exercise 9
/// builds that estimate).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BrdfSample {
    /// Sampled direction `ω_i`, local frame.
    pub wi: Vec3A,
    /// `f_r(ω_i → ω_o)`, per steradian (sr⁻¹). A delta lobe has no value at
    /// a direction (it is a distribution): its `f` is whatever makes the
    /// usual Monte Carlo estimate with this draw give the delta's share of
    /// the light arriving from `wi` in the reflected radiance (exercise 6).
    pub f: Color,
    /// Density of `wi` per unit solid angle (sr⁻¹). For a delta lobe, which
    /// has no density over directions: the probability (no unit) with which
    /// the lobe was chosen among the model's lobes.
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
    /// A reflective model (Lambert, Phong, mirror) seen only from the front:
    /// zero unless `ω_o` and `ω_i` both lie above the surface (see the
    /// module doc). Made by [`Brdf::one_sided`].
    OneSided(Box<Brdf>),
}

/// The direction mirrored through the surface plane (`z → −z`): how the
/// two-sided models see a direction from below.
#[inline]
pub fn flip_z(w: Vec3A) -> Vec3A {
    Vec3A::new(w.x, w.y, -w.z)
}

impl Brdf {
    /// This model, black from behind (see [`Brdf::OneSided`]). Glass has two
    /// sides by nature (in and out) and is returned as it is; a one-sided
    /// model stays one-sided.
    pub fn one_sided(self) -> Brdf {
        match self {
            Brdf::Glass(_) | Brdf::OneSided(_) => self,
            other => Brdf::OneSided(Box::new(other)),
        }
    }

    /// Whether the model is black from behind.
    #[inline]
    pub fn is_one_sided(&self) -> bool {
        matches!(self, Brdf::OneSided(_))
    }

    /// `f_r(ω_i → ω_o)` at the surface point with texture coordinates `uv`,
    /// without the cosine. Zero for delta lobes, and for reflective models when
    /// `wo` and `wi` lie on different sides (they do not transmit).
    #[inline]
    pub fn eval(&self, wo: Vec3A, wi: Vec3A, uv: Vec2) -> Color {
        let (model, one_sided) = self.model();
        if one_sided && !(wo.z > 0.0 && wi.z > 0.0) {
            return Color::ZERO;
        }
        match model {
            Brdf::Lambert(m) => two_sided(wo, wi, Color::ZERO, |wo, wi| m.eval(wo, wi, uv)),
            Brdf::Phong(m) => two_sided(wo, wi, Color::ZERO, |wo, wi| m.eval(wo, wi)),
            Brdf::Mirror(_) | Brdf::Glass(_) | Brdf::OneSided(_) => Color::ZERO,
        }
    }

    /// The model itself and whether it is seen from the front only: the
    /// one-sided wrapper is a test before the model's own `match`, not a
    /// call of its own (its recursion kept the models' code out of line).
    #[inline(always)]
    fn model(&self) -> (&Brdf, bool) {
        match self {
            Brdf::OneSided(m) => (m, true),
            m => (m, false),
        }
    }

    /// Samples `ω_i` given `ω_o`: `u_lobe` chooses a lobe (glass: reflection
    /// or refraction), `u` the direction within it. `mode` matters only for
    /// refraction (see [`TransportMode`]). Returns `None` for a sample that
    /// carries nothing: zero pdf or value, a non-finite value, or a reflected
    /// direction on the wrong side of the surface.
    #[inline]
    pub fn sample(
        &self,
        wo: Vec3A,
        uv: Vec2,
        u_lobe: f32,
        u: Vec2,
        mode: TransportMode,
    ) -> Option<BrdfSample> {
        let (model, one_sided) = self.model();
        if one_sided && wo.z <= 0.0 {
            return None;
        }
        let s = match model {
            Brdf::Lambert(m) => sample_two_sided(wo, |wo| m.sample(wo, uv, u)),
            Brdf::Phong(m) => sample_two_sided(wo, |wo| m.sample(wo, u)),
            Brdf::Mirror(m) => sample_two_sided(wo, |wo| m.sample(wo)),
            Brdf::Glass(m) => m.sample(wo, u_lobe, mode).filter(|s| s.wi.z != 0.0),
            // `Brdf::one_sided` never wraps a one-sided model.
            Brdf::OneSided(_) => None,
        }?;
        let valid = s.pdf_w > 0.0
            && s.pdf_w.is_finite()
            && s.f.is_finite()
            && s.f.max_element() > 0.0
            && s.wi.is_finite();
        valid.then_some(s)
    }

    /// Density per solid angle with which [`Brdf::sample`] returns `wi`
    /// (zero for delta lobes and for directions the model never samples).
    /// `uv` is part of the contract (a textured model's density may depend on
    /// it); no model's density uses it today.
    #[inline]
    pub fn pdf(&self, wo: Vec3A, wi: Vec3A, _uv: Vec2) -> f32 {
        let (model, one_sided) = self.model();
        if one_sided && !(wo.z > 0.0 && wi.z > 0.0) {
            return 0.0;
        }
        match model {
            Brdf::Lambert(m) => two_sided(wo, wi, 0.0, |wo, wi| m.pdf(wo, wi)),
            Brdf::Phong(m) => two_sided(wo, wi, 0.0, |wo, wi| m.pdf(wo, wi)),
            Brdf::Mirror(_) | Brdf::Glass(_) | Brdf::OneSided(_) => 0.0,
        }
    }

    /// Whether every lobe is a delta (mirror, glass): then `eval` and `pdf`
    /// are zero and light can only be gathered by sampling, so next event
    /// estimation is pointless at this surface.
    #[inline]
    pub fn is_delta(&self) -> bool {
        match self {
            Brdf::Mirror(_) | Brdf::Glass(_) => true,
            Brdf::OneSided(m) => m.is_delta(),
            Brdf::Lambert(_) | Brdf::Phong(_) => false,
        }
    }
}

/// Two-sidedness of the reflective models, for `eval` and `pdf`: seen from
/// below, both directions are mirrored to the upper hemisphere. Directions on
/// different sides, or on the horizon, get `zero`.
#[inline]
fn two_sided<T>(wo: Vec3A, wi: Vec3A, zero: T, f: impl FnOnce(Vec3A, Vec3A) -> T) -> T {
    let (wo, wi) = if wo.z < 0.0 {
        (flip_z(wo), flip_z(wi))
    } else {
        (wo, wi)
    };
    if wo.z > 0.0 && wi.z > 0.0 {
        f(wo, wi)
    } else {
        zero
    }
}

/// Two-sidedness of the reflective models, for `sample`: the model samples
/// for `wo` in the upper hemisphere, and the result is mirrored back. A
/// sample below the horizon is dropped here, not in every model.
#[inline]
fn sample_two_sided(
    wo: Vec3A,
    sample: impl FnOnce(Vec3A) -> Option<BrdfSample>,
) -> Option<BrdfSample> {
    let below = wo.z < 0.0;
    let wo = if below { flip_z(wo) } else { wo };
    if wo.z <= 0.0 {
        return None;
    }
    let mut s = sample(wo)?;
    if s.wi.z <= 0.0 {
        return None;
    }
    if below {
        s.wi = flip_z(s.wi);
    }
    Some(s)
}
