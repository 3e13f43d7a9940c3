//! Instant radiosity (Keller 1997): the `vpl` integrator.
//!
//! Lecture topic: "Algorithms for Global Illumination" — instant radiosity
//! is the third biased algorithm of the lecture's list. Light paths are
//! traced from the lights once, as for photon mapping, and every vertex
//! `y_k` (`k ≥ 1`) on a non-delta surface becomes a *virtual point light*
//! (VPL) with flux `Φ = β_k / N`. A camera point `x` then gathers the light
//! of every VPL, each with a shadow ray:
//!
//! ```text
//!   L_VPL(x, ω_o) = Σ_y f_r(x; ω_xy, ω_o) · G(x, y) · f_r(y; ω_in, ω_yx) · Φ_y · V(x, y),
//!   G(x, y) = |cos θ_x| |cos θ_y| / ‖x − y‖²
//! ```
//!
//! with `ω_in` the direction the light path arrived from at `y`. The VPL is
//! a vertex of a light path, so on a smooth mesh its `f_r(y; …)` is the
//! adjoint BRDF: times Veach's correction
//! [`importance_correction`](super::shading_normals::importance_correction)
//! `|ω_in·n_s| |ω_yx·n_g| / (|ω_in·n_g| |ω_yx·n_s|)`, as in BDPT's
//! connection (without it a low-poly smooth ball's VPLs lit the floor beside
//! it a quarter too dark; `tests/shading_normals.rs`). Direct
//! light is estimated by a light sample, as in the path tracer; the VPLs
//! carry everything that bounced at least once. Averaged over the choice of
//! light paths this is unbiased: the same paths weighted as the path
//! tracer weighs them. But every pixel sees the *same* few hundred VPLs, and
//! where `x` comes close to one, `G` grows as `1/‖x − y‖²`: bright splotches
//! near corners. **Clamping** `G` at a bound `g_max` removes them, and with
//! them light that was really there: a smooth image, too dark where surfaces
//! meet. That is the lecture's "smooth, but wrong": the bias, not the noise,
//! is what one sees.
//!
//! **Depth.** A VPL of `k` segments seen from a point the camera reached in
//! `t` makes a path of `t + 1 + k` segments; only paths within `D` count.
//!
//! Not handled (documented limits): a VPL on a mirror or glass cannot light
//! anything (its `f_r` is a delta), so light that reaches `x` last through
//! a delta bounce (caustics) is missing; the environment sends no light
//! paths.
//!
//! Random numbers of a pixel sample: the visible point's, then (below the
//! maximum depth) a light sample. The light paths draw from their own stream.

use std::sync::atomic::AtomicBool;
use std::time::{Duration, Instant};

use super::photon::{PhotonTracing, trace_light_vertices};
use super::shading_normals::importance_correction;
use super::visible_point::lit_visible_point;
use super::{Integrator, stop};
use crate::film::Splat;
use crate::geometry::Interaction;
use crate::math::{Color, Ray, UVec2};
use crate::sampling::Sampler;
use crate::scene::Scene;

/// The options of instant radiosity.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VplSettings {
    /// Light paths traced; each leaves a VPL at every non-delta surface.
    pub paths: u64,
    /// The bound `g_max` on the geometry term (per unit area); 0: no clamping.
    pub clamp: f32,
    pub max_depth: Option<u32>,
    pub rr_depth: u32,
    pub seed: u64,
}

impl Default for VplSettings {
    fn default() -> Self {
        VplSettings {
            paths: 256,
            clamp: 0.0,
            max_depth: None,
            rr_depth: 5,
            seed: 0,
        }
    }
}

impl VplSettings {
    /// One line naming what is wrong, if anything is.
    pub fn check(&self) -> Result<(), String> {
        if self.paths == 0 {
            return Err("--vpl-paths must be at least 1 (light paths to trace)".into());
        }
        if !(self.clamp.is_finite() && self.clamp >= 0.0) {
            return Err(format!(
                "--clamp must be a bound ≥ 0 on the geometry term (0: no clamping), got {}",
                self.clamp
            ));
        }
        Ok(())
    }
}

/// A virtual point light: a light-path vertex and the flux it carries.
#[derive(Clone, Copy, Debug)]
pub struct Vpl {
    /// The point `y`, its frame and `ω_in` (as `wo`: back along the light path).
    pub it: Interaction,
    /// `Φ = β_k / N`.
    pub power: Color,
    /// Segments from the light (`k`).
    pub segments: u32,
}

/// The geometry term `G(x, y)` of a connection from the cosines at its two
/// ends (`cos_x`, `cos_y`, taken as magnitudes) and the squared distance
/// `d2`, clamped at `clamp` (0: not clamped).
#[inline]
pub fn clamped_geometry(cos_x: f32, cos_y: f32, d2: f32, clamp: f32) -> f32 {
    let g = cos_x.abs() * cos_y.abs() / d2;
    if clamp > 0.0 { g.min(clamp) } else { g }
}

/// Instant radiosity with its VPLs traced.
#[derive(Clone, Debug)]
pub struct InstantRadiosity {
    pub settings: VplSettings,
    vpls: Vec<Vpl>,
    /// Light paths traced (fewer than asked if interrupted).
    pub paths: u64,
    pub tracing: Duration,
    pub interrupted: bool,
}

impl InstantRadiosity {
    /// Traces the light paths and keeps their VPLs (on rayon's pool; the
    /// VPLs do not depend on the number of threads). `stop` ends the tracing
    /// early, keeping the VPLs of the batches already traced.
    pub fn build(
        scene: &Scene,
        settings: VplSettings,
        stop: &AtomicBool,
    ) -> Result<InstantRadiosity, String> {
        settings.check()?;
        let start = Instant::now();
        let traced = trace_light_vertices(
            scene,
            &PhotonTracing {
                paths: settings.paths,
                // A VPL k segments from the light is reached by a camera path
                // of at least one segment and the connection: k + 2 ≤ D. The
                // tracing keeps k ≤ its depth − 1, so it is given D − 1 (the
                // vertices beyond were traced, stored and never gathered).
                max_depth: settings.max_depth.map(|d| d.saturating_sub(1)),
                rr_depth: settings.rr_depth,
                seed: settings.seed,
                stream: super::dimensions::VPL_STREAM,
            },
            stop,
            |v| {
                Some(Vpl {
                    it: v.vertex.it,
                    power: v.vertex.beta,
                    segments: v.segments,
                })
            },
        );
        let scale = 1.0 / traced.paths.max(1) as f32;
        let vpls = traced
            .items
            .into_iter()
            .map(|v| Vpl {
                power: v.power * scale,
                ..v
            })
            .collect();
        Ok(InstantRadiosity {
            settings,
            vpls,
            paths: traced.paths,
            tracing: start.elapsed(),
            interrupted: traced.interrupted,
        })
    }

    pub fn vpls(&self) -> &[Vpl] {
        &self.vpls
    }

    /// Bytes the VPLs hold.
    pub fn bytes(&self) -> usize {
        self.vpls.len() * std::mem::size_of::<Vpl>()
    }

    /// One line on the VPLs: count, bytes, time.
    pub fn summary(&self) -> String {
        format!(
            "instant radiosity: {} light paths, {} VPLs × {} bytes = {:.2} MiB (traced in {:.2} s){}",
            self.paths,
            self.vpls.len(),
            std::mem::size_of::<Vpl>(),
            self.bytes() as f64 / (1 << 20) as f64,
            self.tracing.as_secs_f64(),
            if self.interrupted {
                ", INTERRUPTED"
            } else {
                ""
            }
        )
    }

    /// The light of every VPL at `x` (the module doc's sum), for paths whose
    /// camera part has `t` segments.
    pub fn gather(&self, scene: &Scene, x: &Interaction, t: u32) -> Color {
        let d = super::max_segments(self.settings.max_depth);
        let brdf = scene.brdf(x);
        let wo = x.frame.to_local(x.wo);
        let mut l = Color::ZERO;
        for (i, v) in self.vpls.iter().enumerate() {
            // Millions of VPLs make one sample take seconds.
            if i % 64 == 63 && stop::stop_requested() {
                return Color::ZERO;
            }
            if t.saturating_add(1 + v.segments) > d {
                continue;
            }
            let to_y = v.it.p - x.p;
            let d2 = to_y.length_squared();
            if d2 == 0.0 {
                continue;
            }
            let w = to_y / d2.sqrt();
            let f_x = brdf.eval(wo, x.frame.to_local(w), x.uv);
            if f_x == Color::ZERO {
                continue;
            }
            let f_y = scene.brdf(&v.it).eval(
                v.it.frame.to_local(v.it.wo),
                v.it.frame.to_local(-w),
                v.it.uv,
            );
            if f_y == Color::ZERO {
                continue;
            }
            let g = clamped_geometry(
                x.frame.n.dot(w),
                v.it.frame.n.dot(w),
                d2,
                self.settings.clamp,
            );
            if !scene.unoccluded(&Ray::spawn_between(x.ray_end(), v.it.ray_end())) {
                continue;
            }
            // The VPL is a light-path vertex: it scatters importance, with
            // the adjoint BRDF on a smooth mesh (as BDPT's connection).
            let adjoint = importance_correction(&v.it, v.it.wo, -w);
            l += f_x * f_y * v.power * (g * adjoint);
        }
        l
    }
}

impl Integrator for InstantRadiosity {
    fn name(&self) -> &'static str {
        "vpl"
    }

    fn sample(
        &self,
        scene: &Scene,
        pixel: UVec2,
        sampler: &mut Sampler,
        _splats: &mut Vec<Splat>,
    ) -> Color {
        let (l, point) = lit_visible_point(scene, pixel, sampler, self.settings.max_depth);
        let Some(x) = point else {
            return l;
        };
        l + x.beta * self.gather(scene, &x.it, x.depth)
    }
}
