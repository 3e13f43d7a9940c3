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
//! Both the two-sidedness and the dropping of useless samples (zero pdf, zero
//! or non-finite value, a reflected direction on the wrong side) happen in one
//! place, the `match` of [`Brdf`]; the models only ever see `ω_o` in the upper
//! hemisphere (glass excepted). Files: one per model, [`fresnel`] for the
//! Fresnel equations and Snell's law, [`texture`] for spatially varying albedo.
//!
//! Delta lobes (mirror, glass) follow pbrt's convention: the sample's `f` is
//! already divided by `|cos θ_i|` and its pdf is the probability of choosing
//! the lobe, so the usual estimator `f · |cos θ_i| / pdf` gives the right
//! weight; `eval` and `pdf` of a delta lobe are zero for any given pair of
//! directions (the chance of hitting the delta direction is zero).

pub mod fresnel;
pub mod glass;
pub mod lambert;
pub mod mirror;
pub mod phong;
#[cfg(test)]
mod testing;
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

/// The direction mirrored through the surface plane (`z → −z`): how the
/// two-sided models see a direction from below.
#[inline]
fn flip_z(w: Vec3A) -> Vec3A {
    Vec3A::new(w.x, w.y, -w.z)
}

impl Brdf {
    /// `f_r(ω_i → ω_o)` at the surface point with texture coordinates `uv`,
    /// without the cosine. Zero for delta lobes, and for reflective models when
    /// `wo` and `wi` lie on different sides (they do not transmit).
    #[inline]
    pub fn eval(&self, wo: Vec3A, wi: Vec3A, uv: Vec2) -> Color {
        match self {
            Brdf::Lambert(m) => two_sided(wo, wi, Color::ZERO, |wo, wi| m.eval(wo, wi, uv)),
            Brdf::Phong(m) => two_sided(wo, wi, Color::ZERO, |wo, wi| m.eval(wo, wi)),
            Brdf::Mirror(_) | Brdf::Glass(_) => Color::ZERO,
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
        let s = match self {
            Brdf::Lambert(m) => sample_two_sided(wo, |wo| m.sample(wo, uv, u)),
            Brdf::Phong(m) => sample_two_sided(wo, |wo| m.sample(wo, u)),
            Brdf::Mirror(m) => sample_two_sided(wo, |wo| m.sample(wo)),
            Brdf::Glass(m) => m.sample(wo, u_lobe, mode).filter(|s| s.wi.z != 0.0),
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
    #[inline]
    pub fn pdf(&self, wo: Vec3A, wi: Vec3A, _uv: Vec2) -> f32 {
        match self {
            Brdf::Lambert(m) => two_sided(wo, wi, 0.0, |wo, wi| m.pdf(wo, wi)),
            Brdf::Phong(m) => two_sided(wo, wi, 0.0, |wo, wi| m.pdf(wo, wi)),
            Brdf::Mirror(_) | Brdf::Glass(_) => 0.0,
        }
    }

    /// Whether every lobe is a delta (mirror, glass): then `eval` and `pdf`
    /// are zero and light can only be gathered by sampling, so next event
    /// estimation is pointless at this surface.
    #[inline]
    pub fn is_delta(&self) -> bool {
        matches!(self, Brdf::Mirror(_) | Brdf::Glass(_))
    }

    /// Whether the model transmits light to the other side (glass).
    #[inline]
    pub fn has_transmission(&self) -> bool {
        matches!(self, Brdf::Glass(_))
    }

    /// A rough reflectance in `[0, 1]³`, for Russian roulette and previews:
    /// the albedo at normal incidence (Lambert ρ, Phong ρ_s, mirror
    /// reflectance, glass tint, which is the total of reflection and
    /// transmission).
    #[inline]
    pub fn albedo_hint(&self, uv: Vec2) -> Color {
        match self {
            Brdf::Lambert(m) => m.albedo.eval(uv),
            Brdf::Phong(m) => m.albedo,
            Brdf::Mirror(m) => m.reflectance,
            Brdf::Glass(m) => m.tint,
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
