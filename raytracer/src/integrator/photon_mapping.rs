//! Photon mapping (Jensen 1996): the `photon` integrator.
//!
//! Lecture topic: "Algorithms for Global Illumination" — the first biased
//! algorithm of the lecture's list. Two passes:
//!
//! 1. **Photon tracing** ([`super::photon`]): light paths from the lights
//!    leave photons on every non-delta surface they meet. The *caustic map*
//!    holds the photons that came through mirrors and glass only (L S+ D);
//!    the *global map* the others (with final gathering: all of them).
//! 2. **Rendering**: a camera ray is followed through mirrors and glass to a
//!    diffuse or glossy point `x` ([`super::visible_point`]), where
//!
//! ```text
//!   L(x, ω_o) = L_e                                   seen directly or through S*
//!             + L_direct     by a light sample (next event estimation)
//!             + L_caustic    from the caustic map (density estimate at x)
//!             + L_indirect   from the global map at x,
//!                            or by final gathering: N BRDF rays from x, each
//!                            reading the global map where it lands (x′)
//! ```
//!
//! The density estimate is [`PhotonMap::radiance`]: the Epanechnikov kernel
//! over the `k` nearest photons, or over a fixed radius. Each part of a
//! path is counted by exactly one term, so where the light is uniform (the
//! furnace) the estimate has no bias at all; elsewhere the kernel's disk
//! blurs the light — bias that shrinks as the photon count grows, but that
//! no number of *camera* samples removes. Final gathering moves the blur one
//! bounce away from the camera, where it shows far less.
//!
//! **Depth.** A photon that travelled `k` segments, read at a point the
//! camera reached in `t`, makes a path of `t + k` segments; only those with
//! `t + k ≤ D` are counted, so a depth limit holds exactly.
//!
//! Random numbers of a pixel sample: the visible point's, then (below the
//! maximum depth) a light sample, then for each gather ray a continuation
//! and the continuations of its delta bounces. The photons draw from their
//! own stream (see [`super::photon`]).
//!
//! Not handled (documented limits): the environment sends no photons (as
//! for light tracing), so with an environment light only its direct light
//! and what reaches `x` through S* are rendered.

use std::sync::atomic::AtomicBool;
use std::time::{Duration, Instant};

use super::continuation::sample_continuation;
use super::photon::{Photon, PhotonTracing, trace_photons};
use super::photon_map::{PhotonMap, Search, radius_for};
use super::visible_point::{follow_delta_chain, lit_visible_point};
use super::{Integrator, stop};
use crate::brdf::TransportMode;
use crate::film::Splat;
use crate::math::{Color, UVec2};
use crate::sampling::Sampler;
use crate::scene::Scene;

/// The options of photon mapping.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PhotonSettings {
    /// Light paths traced (each leaves a photon at every non-delta surface).
    pub photons: u64,
    /// Density estimation: `k` nearest photons, unless `radius` is given.
    pub k: usize,
    /// A fixed search radius instead of the `k` nearest.
    pub radius: Option<f32>,
    /// Final gathering: this many BRDF rays per visible point (0: read the
    /// global map at the visible point itself).
    pub final_gather: u32,
    pub max_depth: Option<u32>,
    pub rr_depth: u32,
    pub seed: u64,
}

impl Default for PhotonSettings {
    fn default() -> Self {
        PhotonSettings {
            photons: 200_000,
            k: 50,
            radius: None,
            final_gather: 0,
            max_depth: None,
            rr_depth: 5,
            seed: 0,
        }
    }
}

impl PhotonSettings {
    /// One line naming what is wrong, if anything is.
    pub fn check(&self) -> Result<(), String> {
        if self.photons == 0 {
            return Err("--photons must be at least 1 (light paths to trace)".into());
        }
        match self.radius {
            Some(r) if !(r.is_finite() && r > 0.0) => {
                Err(format!("--radius must be a positive distance, got {r}"))
            }
            None if self.k == 0 => {
                Err("--k must be at least 1 (the nearest photons to use)".into())
            }
            _ => Ok(()),
        }
    }
}

/// What building the maps cost.
#[derive(Clone, Debug, PartialEq)]
pub struct PhotonStats {
    /// Light paths traced (fewer than asked if interrupted).
    pub paths: u64,
    pub caustic_photons: usize,
    pub global_photons: usize,
    /// Bytes of both maps (photons of 40 bytes and their grids).
    pub bytes: usize,
    /// Time to trace the photons and to build the maps.
    pub tracing: Duration,
    pub building: Duration,
    pub interrupted: bool,
}

/// Photon mapping with its two maps built.
#[derive(Clone, Debug)]
pub struct PhotonMapping {
    pub settings: PhotonSettings,
    caustic: PhotonMap,
    caustic_search: Search,
    global: PhotonMap,
    global_search: Search,
    pub stats: PhotonStats,
}

/// The search of `settings` over `photons`: the fixed radius, or the `k`
/// nearest within twice the radius that would hold `k` photons if they
/// were spread evenly.
fn search_for(settings: &PhotonSettings, photons: &[Photon]) -> Search {
    match settings.radius {
        Some(r) => Search::Radius(r),
        None => Search::Nearest {
            k: settings.k,
            max_radius: radius_for(photons, settings.k, 2.0),
        },
    }
}

impl PhotonMapping {
    /// Traces the photons and builds the maps (on rayon's pool; the maps do
    /// not depend on the number of threads). `stop` ends the tracing early,
    /// keeping the photons of the batches already traced.
    pub fn build(
        scene: &Scene,
        settings: PhotonSettings,
        stop: &AtomicBool,
    ) -> Result<PhotonMapping, String> {
        settings.check()?;
        let start = Instant::now();
        let traced = trace_photons(
            scene,
            &PhotonTracing {
                paths: settings.photons,
                max_depth: settings.max_depth,
                rr_depth: settings.rr_depth,
                seed: settings.seed,
                stream: super::dimensions::PHOTON_MAPPING_STREAM,
            },
            stop,
        );
        let tracing = start.elapsed();
        let start = Instant::now();
        let global_photons = if settings.final_gather > 0 {
            let mut all = traced.direct;
            all.extend(&traced.caustic);
            all.extend(traced.indirect);
            all
        } else {
            traced.indirect
        };
        let (caustic_search, global_search) = (
            search_for(&settings, &traced.caustic),
            search_for(&settings, &global_photons),
        );
        let caustic = PhotonMap::build(traced.caustic, caustic_search.max_radius());
        let global = PhotonMap::build(global_photons, global_search.max_radius());
        let stats = PhotonStats {
            paths: traced.paths,
            caustic_photons: caustic.len(),
            global_photons: global.len(),
            bytes: caustic.bytes() + global.bytes(),
            tracing,
            building: start.elapsed(),
            interrupted: traced.interrupted,
        };
        Ok(PhotonMapping {
            settings,
            caustic,
            caustic_search,
            global,
            global_search,
            stats,
        })
    }

    /// The maps' searches: (caustic, global).
    pub fn searches(&self) -> (Search, Search) {
        (self.caustic_search, self.global_search)
    }

    /// One line on the maps: photons, bytes, times.
    pub fn summary(&self) -> String {
        let s = &self.stats;
        format!(
            "photon maps: {} light paths, {} caustic + {} global photons × {} bytes = {:.1} MiB \
             (traced in {:.2} s, built in {:.2} s){}",
            s.paths,
            s.caustic_photons,
            s.global_photons,
            std::mem::size_of::<Photon>(),
            s.bytes as f64 / (1 << 20) as f64,
            s.tracing.as_secs_f64(),
            s.building.as_secs_f64(),
            if s.interrupted { ", INTERRUPTED" } else { "" }
        )
    }
}

impl Integrator for PhotonMapping {
    fn name(&self) -> &'static str {
        "photon"
    }

    fn sample(
        &self,
        scene: &Scene,
        pixel: UVec2,
        sampler: &mut Sampler,
        _splats: &mut Vec<Splat>,
    ) -> Color {
        let max_depth = self.settings.max_depth;
        let d = super::max_segments(max_depth);
        let (mut l, point) = lit_visible_point(scene, pixel, sampler, max_depth);
        let Some(vp) = point else {
            return l;
        };
        let it = vp.it;
        let brdf = scene.brdf(&it);
        let fits = |t: u32| move |ph: &Photon| t + ph.segments <= d;
        l += vp.beta
            * self
                .caustic
                .radiance(&it, brdf, self.caustic_search, fits(vp.depth));
        let gathers = self.settings.final_gather;
        if gathers == 0 {
            l += vp.beta
                * self
                    .global
                    .radiance(&it, brdf, self.global_search, fits(vp.depth));
            return l;
        }
        // Final gathering: where each BRDF ray lands (through S*), the
        // global map gives the light leaving that point towards x.
        let mut gathered = Color::ZERO;
        for _ in 0..gathers {
            // Millions of gather rays make one sample take seconds.
            if stop::stop_requested() {
                return Color::ZERO;
            }
            let Some(c) = sample_continuation(&it, brdf, TransportMode::Radiance, sampler) else {
                continue;
            };
            let g = follow_delta_chain(
                scene,
                c.ray,
                c.weight,
                vp.depth + 1,
                sampler,
                max_depth,
                false,
            );
            if let Some(x2) = g.hit {
                let brdf2 = scene.brdf(&x2);
                gathered += g.beta
                    * self
                        .global
                        .radiance(&x2, brdf2, self.global_search, fits(g.depth));
            }
        }
        l + vp.beta * gathered / gathers as f32
    }
}
