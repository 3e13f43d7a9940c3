//! The BRDF tab: a BRDF chosen with sliders, its lobe in the plane of
//! incidence, its directional albedo `a(ω_o) = ∫ f_r(ω_i → ω_o) cos θ_i dω_i`
//! with the verdict of energy conservation (`a ≤ 1` for every `ω_o`), and a
//! ball made of it, path traced.
//!
//! The albedo is a midpoint rule in the BRDF's own sampling coordinates: with
//! `ω_i = sample(u)` of density `p`, `a = ∫_{[0,1]²} f cos θ_i / p du`, and
//! the grid's `N²` cell centres stand for `u`. Where `f cos θ_i / p` is
//! constant (Lambert, the mirror, glass) the rule is exact; for Phong it is
//! `ρ (n+2)/(n+1) · max(0, cos θ_i)`, smooth but for the horizon's kink, and
//! the grid of 96² gives the albedo to about 1e-3 (tested at normal
//! incidence, where it is exactly ρ). No random numbers: the same sliders
//! always print the same digits.
//!
//! "Original Phong" is the lecture's unnormalized `ρ cos^n α`: it is the
//! normalized model with `ρ` scaled by `2π/(n+2)`, which is how it is
//! rendered and measured here; for small `n` it reflects more than it receives.

use raytracer::brdf::{Brdf, Glass, Lambert, Mirror, Phong, Texture, TransportMode};
use raytracer::integrator::{DirectStrategy, PathTracer};
use raytracer::math::{Color, Vec2, Vec3A};
use raytracer::scene::{Scene, SceneOrigin, load_str};
use serde::Serialize;

use super::job::JobSpec;
use super::query::Query;
use super::settings::MAX_SPP;
use crate::integrators::IntegratorPlan;

/// The parameters of a BRDF.
pub const BRDF_PARAMS: &[&str] = &["model", "albedo", "exponent", "phong", "ior", "theta"];

/// The grid of the midpoint rule: `ALBEDO_GRID²` directions per angle.
const ALBEDO_GRID: u32 = 96;

/// The sphere scene of the tab.
const SPHERE_SCENE: &str = include_str!("assets/brdf-sphere.toml");

/// A BRDF from the sliders.
pub struct BrdfChoice {
    pub brdf: Brdf,
    /// The formula, e.g. `f_r = ρ (n+2)/2π cos^n α`.
    pub formula: String,
}

/// The BRDF the query describes (`model=phong&albedo=0.8&exponent=10`).
pub fn choose(q: &Query) -> Result<BrdfChoice, String> {
    let albedo = q.in_range("albedo", 0.8, 0.0..=1.0)?;
    let rho = Color::splat(albedo);
    let model = q.get("model").unwrap_or("phong");
    let unused = |names: &[&str]| -> Result<(), String> {
        match names.iter().find(|n| q.get(n).is_some()) {
            Some(n) => Err(format!("`{n}` is not a parameter of the {model} BRDF")),
            None => Ok(()),
        }
    };
    Ok(match model {
        "lambert" => {
            unused(&["exponent", "phong", "ior"])?;
            BrdfChoice {
                brdf: Brdf::Lambert(Lambert {
                    albedo: Texture::Constant(rho),
                }),
                formula: format!("Lambert: f_r = ρ/π, ρ = {albedo}"),
            }
        }
        "phong" => {
            unused(&["ior"])?;
            let n = q.in_range("exponent", 10.0, 0.0..=10_000.0)?;
            match q.get("phong").unwrap_or("normalized") {
                "normalized" => BrdfChoice {
                    brdf: Brdf::Phong(Phong {
                        albedo: rho,
                        exponent: n,
                    }),
                    formula: lang::pick(
                        format!(
                            "normalized Phong: f_r = ρ (n+2)/2π cos^n α, ρ = {albedo}, n = {n}"
                        ),
                        format!("нормиран Phong: f_r = ρ (n+2)/2π cos^n α, ρ = {albedo}, n = {n}"),
                    ),
                },
                "original" => BrdfChoice {
                    brdf: Brdf::Phong(Phong {
                        albedo: rho * (2.0 * std::f32::consts::PI / (n + 2.0)),
                        exponent: n,
                    }),
                    formula: lang::pick(
                        format!(
                            "original Phong: f_r = ρ cos^n α (no normalization), ρ = {albedo}, n = {n}"
                        ),
                        format!(
                            "оригинален Phong: f_r = ρ cos^n α (ненормиран), ρ = {albedo}, n = {n}"
                        ),
                    ),
                },
                other => {
                    return Err(format!(
                        "`phong` must be normalized or original, got {other:?}"
                    ));
                }
            }
        }
        "mirror" => {
            unused(&["exponent", "phong", "ior"])?;
            BrdfChoice {
                brdf: Brdf::Mirror(Mirror { reflectance: rho }),
                formula: lang::pick(
                    format!("perfect mirror: f_r = R δ(ω_i − ω_r)/cos θ_i, R = {albedo}"),
                    format!("идеално огледало: f_r = R δ(ω_i − ω_r)/cos θ_i, R = {albedo}"),
                ),
            }
        }
        "glass" => {
            unused(&["exponent", "phong"])?;
            let ior = q.in_range("ior", 1.5, 1.0..=4.0)?;
            BrdfChoice {
                brdf: Brdf::Glass(Glass { ior, tint: rho }),
                formula: lang::pick(
                    format!(
                        "smooth glass: Fresnel reflection F and refraction 1 − F, η = {ior}, tint = {albedo}"
                    ),
                    format!(
                        "гладко стъкло: отражение F и пречупване 1 − F по Fresnel, η = {ior}, оттенък = {albedo}"
                    ),
                ),
            }
        }
        other => {
            return Err(format!(
                "`model` must be lambert, phong, mirror or glass, got {other:?}"
            ));
        }
    })
}

/// The lobe and the albedo, as the page plots and prints them.
#[derive(Serialize)]
pub struct BrdfAnalysis {
    pub formula: String,
    /// The angle of the incoming light, from the normal (degrees).
    pub theta: f32,
    /// `[θ_o, f_r]` in the plane of incidence, θ_o from −90° to 90°
    /// (light arrives from the −x side, at −θ).
    pub lobe: Vec<[f32; 2]>,
    /// Delta lobes: `[direction angle from the normal, weight]` (angles
    /// beyond 90° point into the surface: refraction).
    pub deltas: Vec<[f32; 2]>,
    /// `[θ_o, a(θ_o)]` from 0° to 89°.
    pub albedo: Vec<[f32; 2]>,
    /// The albedo at the incoming angle of the plot.
    pub albedo_at_theta: f32,
    pub max_albedo: f32,
    /// Where the largest albedo is.
    pub max_at: f32,
    pub conserves_energy: bool,
    /// One sentence: the verdict with its numbers.
    pub verdict: String,
}

/// A direction in the plane of incidence (x–z), `deg` from the normal.
pub fn dir(deg: f32) -> Vec3A {
    let t = deg.to_radians();
    Vec3A::new(t.sin(), 0.0, t.cos())
}

/// `a(ω_o)` by the midpoint rule of the module doc. Glass is measured for
/// importance (energy): radiance's `1/η²` is a change of units, not a loss.
pub fn directional_albedo(brdf: &Brdf, wo: Vec3A) -> f32 {
    let n = ALBEDO_GRID;
    let mut sum = 0.0f64;
    for i in 0..n {
        for j in 0..n {
            let u = Vec2::new((i as f32 + 0.5) / n as f32, (j as f32 + 0.5) / n as f32);
            if let Some(s) = brdf.sample(wo, Vec2::ZERO, u.x, u, TransportMode::Importance) {
                sum += (s.f.x * s.wi.z.abs() / s.pdf_w) as f64;
            }
        }
    }
    (sum / (n * n) as f64) as f32
}

/// The lobe, the albedo and the verdict for light from `theta` degrees.
pub fn analyse(choice: &BrdfChoice, theta: f32) -> BrdfAnalysis {
    let brdf = &choice.brdf;
    let wi = dir(-theta);
    let lobe = (-90..=90)
        .map(|d| {
            let d = d as f32;
            [d, brdf.eval(dir(d), wi, Vec2::ZERO).x]
        })
        .collect();
    let mut deltas = Vec::new();
    if brdf.is_delta() {
        // Where the light from ω_i goes: its sampled directions, each lobe with
        // its share (F and 1 − F for glass; u_lobe picks the lobe).
        for u_lobe in [0.0, 0.999_999] {
            if let Some(s) = brdf.sample(
                wi,
                Vec2::ZERO,
                u_lobe,
                Vec2::ZERO,
                TransportMode::Importance,
            ) {
                let angle = s.wi.x.atan2(s.wi.z).to_degrees();
                let entry = [angle, s.f.x * s.wi.z.abs()];
                if !deltas.contains(&entry) {
                    deltas.push(entry);
                }
            }
        }
    }
    let albedo: Vec<[f32; 2]> = (0..90)
        .map(|d| [d as f32, directional_albedo(brdf, dir(d as f32))])
        .collect();
    let [max_at, max_albedo] = albedo
        .iter()
        .copied()
        .fold([0.0, f32::MIN], |m, a| if a[1] > m[1] { a } else { m });
    let albedo_at_theta = directional_albedo(brdf, dir(theta));
    // 1e-3: the midpoint rule's accuracy (module doc).
    let conserves_energy = max_albedo <= 1.0 + 1e-3;
    let verdict = if conserves_energy {
        lang::pick(
            format!(
                "conserves energy: the albedo is at most {max_albedo:.3} (at θ_o = {max_at:.0}°), never above 1"
            ),
            format!(
                "запазва енергията: албедото е най-много {max_albedo:.3} (при θ_o = {max_at:.0}°), никога над 1"
            ),
        )
    } else {
        lang::pick(
            format!(
                "violates energy conservation: at θ_o = {max_at:.0}° it reflects {max_albedo:.3} times the light it receives"
            ),
            format!(
                "нарушава запазването на енергията: при θ_o = {max_at:.0}° отразява {max_albedo:.3} пъти светлината, която получава"
            ),
        )
    };
    BrdfAnalysis {
        formula: choice.formula.clone(),
        theta,
        lobe,
        deltas,
        albedo,
        albedo_at_theta,
        max_albedo,
        max_at,
        conserves_energy,
        verdict,
    }
}

/// A ball of the chosen BRDF, path traced (`spp`, `seed` from the query).
pub fn sphere_job(q: &Query, choice: &BrdfChoice) -> Result<JobSpec, String> {
    let origin = SceneOrigin::Dir {
        name: "brdf-sphere".into(),
        dir: ".".into(),
    };
    let mut parts = load_str(SPHERE_SCENE, &origin).map_err(|e| e.to_string())?;
    let sample = parts
        .brdf_names
        .iter()
        .position(|n| n == "sample")
        .ok_or("the sphere scene has no material `sample`")?;
    parts.brdfs[sample] = choice.brdf.clone();
    let scene = Scene::build("brdf-sphere", parts);
    let spp: u32 = q.number("spp", 64)?;
    if !(1..=MAX_SPP).contains(&spp) {
        return Err(format!("spp must be in [1, {MAX_SPP}], got {spp}"));
    }
    let options = raytracer::render::RenderOptions {
        spp,
        seed: q.number("seed", 0)?,
        progress: false,
        ..Default::default()
    };
    let integrator = PathTracer {
        max_depth: scene.settings.max_depth,
        rr_depth: scene.settings.rr_depth,
        strategy: DirectStrategy::Mis,
    };
    Ok(JobSpec {
        kind: "brdf",
        command: format!("(the lab's BRDF ball: {}, path traced)", choice.formula),
        eyes: vec![scene],
        build_for: None,
        plan: IntegratorPlan::Ready(Box::new(integrator)),
        options,
        student: None,
        race: None,
        wavefront: None,
    })
}
