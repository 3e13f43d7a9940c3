//! Stochastic progressive photon mapping (Hachisuka & Jensen 2009): what
//! one pixel and one pass compute.
//!
//! Lecture topic: "Algorithms for Global Illumination" — photon mapping made
//! *consistent*: its bias falls to zero as the passes grow, while each pass
//! needs only a bounded number of photons in memory. Every pass `i`
//!
//! 1. traces one camera sample per pixel to its **visible point** `x`
//!    (through mirrors and glass, [`crate::integrator::visible_point`]) and adds the
//!    light seen there directly (emission, and a light sample at `x`);
//! 2. traces `N_p` photon paths and, for each visible point, sums over the
//!    photons of at least two segments within its radius `r`:
//!    `M` (their number) and `φ = Σ β · f_r(x; ω_p, ω_o) Φ_p`;
//! 3. shrinks the radius so that only a fraction `α` of the new photons is
//!    kept as if they had been found in the smaller disk:
//!
//! ```text
//!   N' = N + α M,    r' = r √(N' / (N + M)),    τ' = (τ + φ) · r'² / r²
//! ```
//!
//! After `P` passes the pixel is
//!
//! ```text
//!   L = (1/P) Σ_i L_direct,i  +  τ / (P N_p π r²).
//! ```
//!
//! With `α ∈ (0, 1)` (2/3 by default) the radius goes to 0 and the photon
//! count in it to infinity: the blur of photon mapping fades, and so does
//! the noise — more slowly than `1/√P` (the price of consistency). The
//! kernel is the constant one (a box over the disk: every photon in it
//! counts fully), as in the paper.
//!
//! The pass loop itself (parallel, deterministic, interruptible, with a
//! progress bar) is [`super`]'s `render_sppm`; this file holds what one
//! pixel and one pass compute. Random numbers: pass `i` of pixel `j`
//! draws its visible point and light sample from `Sampler::new(seed, j, i)`
//! (the layout of a pixel sample of photon mapping without final
//! gathering); the photons of pass `i` from their own stream `2 + i`.

use std::sync::atomic::AtomicBool;

use crate::integrator::photon::{Photon, PhotonTracing, trace_photons};
use crate::integrator::photon_map::PhotonMap;
use crate::integrator::visible_point::{GatherPoint, lit_visible_point};
use crate::math::{Color, PI, UVec2};
use crate::sampling::Sampler;
use crate::scene::Scene;

/// The options of SPPM (the number of passes is the render's `spp`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SppmSettings {
    /// Photon paths per pass.
    pub photons: u64,
    /// The initial radius `r_0` (`None`: 1% of the scene's diagonal).
    pub radius: Option<f32>,
    /// The fraction `α` of new photons kept each pass, in (0, 1).
    pub alpha: f32,
    pub max_depth: Option<u32>,
    pub rr_depth: u32,
}

impl Default for SppmSettings {
    fn default() -> Self {
        SppmSettings {
            photons: 50_000,
            radius: None,
            alpha: 2.0 / 3.0,
            max_depth: None,
            rr_depth: 5,
        }
    }
}

impl SppmSettings {
    /// One line naming what is wrong, if anything is.
    pub fn check(&self) -> Result<(), String> {
        if self.photons == 0 {
            return Err("--photons must be at least 1 (photon paths per pass)".into());
        }
        if let Some(r) = self.radius
            && !(r.is_finite() && r > 0.0)
        {
            return Err(format!("--radius must be a positive distance, got {r}"));
        }
        if !(self.alpha > 0.0 && self.alpha < 1.0) {
            return Err(format!(
                "--alpha must lie strictly between 0 and 1 (the fraction of new photons kept; 2/3 is usual), got {}",
                self.alpha
            ));
        }
        Ok(())
    }

    /// The initial radius for `scene`.
    pub fn initial_radius(&self, scene: &Scene) -> f32 {
        self.radius.unwrap_or_else(|| {
            let b = scene.geometry.bounds();
            if b.is_empty() {
                0.01
            } else {
                (0.01 * b.diagonal().length()).max(1e-4)
            }
        })
    }
}

/// What a pixel keeps from pass to pass.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PixelState {
    /// The current radius `r`.
    pub r: f32,
    /// The photon count `N` (a real number after the α reduction).
    pub n: f32,
    /// The flux `τ`, already scaled to the current radius.
    pub tau: Color,
    /// The sum of the directly seen light over the passes.
    pub direct: Color,
}

impl PixelState {
    pub fn new(r0: f32) -> Self {
        PixelState {
            r: r0,
            n: 0.0,
            tau: Color::ZERO,
            direct: Color::ZERO,
        }
    }

    /// Step 3 of the module doc, with the `M` photons and flux `φ` this pass
    /// found within `r`.
    pub fn update(&mut self, m: u32, phi: Color, alpha: f32) {
        if m == 0 {
            return;
        }
        let m = m as f32;
        let n_new = self.n + alpha * m;
        let r_new = self.r * (n_new / (self.n + m)).sqrt();
        self.tau = (self.tau + phi) * (r_new * r_new) / (self.r * self.r);
        self.n = n_new;
        self.r = r_new;
    }

    /// The pixel after `passes` passes of `photons` paths each.
    pub fn radiance(&self, passes: u32, photons: u64) -> Color {
        if passes == 0 {
            return Color::ZERO;
        }
        let p = passes as f32;
        self.direct / p + self.tau / (p * photons as f32 * PI * self.r * self.r)
    }
}

/// Step 1 for pixel `pixel` (raster index `index`) in pass `pass`: the
/// light seen directly, and the visible point (none if the ray left the
/// scene or reached the maximum depth).
pub fn camera_pass(
    scene: &Scene,
    settings: &SppmSettings,
    seed: u64,
    pixel: UVec2,
    index: u64,
    pass: u32,
) -> (Color, Option<GatherPoint>) {
    let mut sampler = Sampler::new(seed, index, pass as u64);
    lit_visible_point(scene, pixel, &mut sampler, settings.max_depth)
}

/// The photons of pass `pass` that step 2 uses (two segments or more: the
/// direct light was sampled at the visible points), in a map for searches
/// up to `max_radius`, and the number of paths traced (0 if interrupted:
/// the pass is then dropped).
pub fn photon_pass(
    scene: &Scene,
    settings: &SppmSettings,
    seed: u64,
    pass: u32,
    max_radius: f32,
    stop: &AtomicBool,
) -> (PhotonMap, u64) {
    let traced = trace_photons(
        scene,
        &PhotonTracing {
            paths: settings.photons,
            max_depth: settings.max_depth,
            rr_depth: settings.rr_depth,
            seed,
            stream: crate::integrator::dimensions::SPPM_FIRST_STREAM + pass as u64,
        },
        stop,
    );
    if traced.interrupted {
        return (PhotonMap::build(Vec::new(), 1.0), 0);
    }
    // trace_photons divided the power by N_p; τ keeps β and divides once
    // by P N_p at the end.
    let n = traced.paths as f32;
    let photons: Vec<Photon> = traced
        .caustic
        .into_iter()
        .chain(traced.indirect)
        .map(|p| Photon {
            power: p.power * n,
            ..p
        })
        .collect();
    (PhotonMap::build(photons, max_radius), traced.paths)
}

/// Step 2 for one visible point: `(M, φ)` within radius `r`.
pub fn gather(
    scene: &Scene,
    settings: &SppmSettings,
    map: &PhotonMap,
    point: &GatherPoint,
    r: f32,
) -> (u32, Color) {
    let d = crate::integrator::max_segments(settings.max_depth);
    let it = &point.it;
    let brdf = scene.brdf(it);
    let wo = it.frame.to_local(it.wo);
    let (mut m, mut phi) = (0u32, Color::ZERO);
    map.for_each_within(
        it.p,
        r,
        |ph| point.depth + ph.segments <= d,
        |_, ph, _| {
            let f = brdf.eval(wo, it.frame.to_local(ph.wi.into()), it.uv);
            m += 1;
            phi += point.beta * f * Color::from(ph.power);
        },
    );
    (m, phi)
}
