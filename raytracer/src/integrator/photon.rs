//! Photons: light paths traced from the lights, their vertices kept as
//! packets of flux.
//!
//! Lecture topic: "photon mapping" (Jensen 1996), the first of the lecture's
//! biased algorithms, and its progressive form. A photon is a light-subpath
//! vertex `y_k` (`k ≥ 1`) on a surface that is not a mirror or glass, kept
//! with the direction it came from and its flux `Φ`: the path's throughput
//! `β_k` at `y_k` (a Monte Carlo estimate of the power the lights emit,
//! carried through the bounces before `y_k`) divided by `N`,
//! where `N` is the number of light paths traced (each path's `β` is a flux
//! estimate of the whole scene's light: dividing by `N` shares it out). The
//! paths are the light subpaths of light and bidirectional tracing
//! ([`super::subpath::light_subpath`]: the lights' own emission sampling,
//! BRDF sampling and Russian roulette), in importance mode.
//!
//! Each photon knows how it got there ([`PhotonKind`]): straight from the
//! light (*direct*), through mirrors and glass only (*caustic*, the lecture's
//! "слънчеви зайчета", L S+ D paths), or after at least one diffuse or
//! glossy bounce (*indirect*); and how many segments it travelled, so that a
//! maximum depth D can be kept exactly.
//!
//! **Determinism.** Paths are traced in batches of [`BATCH`]; path `i` of a
//! tracing draws from `Sampler::new(seed, i, stream)`, whichever thread runs
//! it, and the batches' photons are concatenated in batch order. A stop
//! request (Ctrl-C) ends the tracing after whole batches: the photons kept
//! are those of the first batches, and `N` counts exactly their paths.

use std::sync::atomic::{AtomicBool, Ordering};

use rayon::prelude::*;

use super::subpath::light_subpath;
use super::vertex::{Subpath, Vertex, VertexKind, path_vertices};
use crate::math::Vec3;
use crate::sampling::Sampler;
use crate::scene::Scene;

/// Light paths per batch (the unit of parallel work and of interruption).
pub const BATCH: u64 = 1024;

/// A photon: 40 bytes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Photon {
    /// Where it landed.
    pub p: Vec3,
    /// Unit direction back towards where it came from (`ω_i` at `p`).
    pub wi: Vec3,
    /// Its flux `Φ` (watts per channel).
    pub power: Vec3,
    /// Segments travelled from the light (1: direct).
    pub segments: u32,
}

/// How a photon reached its surface.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PhotonKind {
    /// Straight from the light (one segment).
    Direct,
    /// Through mirrors and glass only (L S+ D).
    Caustic,
    /// After at least one diffuse or glossy bounce.
    Indirect,
}

/// How to trace photons.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PhotonTracing {
    /// Light paths to trace.
    pub paths: u64,
    /// Mitsuba's max depth D of the whole camera-to-light path (`None`:
    /// unlimited); a photon is kept only if at least one camera segment
    /// still fits (`segments ≤ D − 1`).
    pub max_depth: Option<u32>,
    /// Russian roulette from this many bounces on.
    pub rr_depth: u32,
    pub seed: u64,
    /// Which numbers: a second tracing with another stream (an SPPM pass)
    /// draws independent paths.
    pub stream: u64,
}

/// The photons of one tracing, by kind.
#[derive(Clone, Debug, Default)]
pub struct TracedPhotons {
    pub direct: Vec<Photon>,
    pub caustic: Vec<Photon>,
    pub indirect: Vec<Photon>,
    /// Light paths traced (`N`; fewer than asked if interrupted).
    pub paths: u64,
    /// Whether a stop request cut the tracing short.
    pub interrupted: bool,
}

impl TracedPhotons {
    /// The photon count of all kinds.
    pub fn len(&self) -> usize {
        self.direct.len() + self.caustic.len() + self.indirect.len()
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Bytes the photons hold.
    pub fn bytes(&self) -> usize {
        self.len() * std::mem::size_of::<Photon>()
    }
}

/// The sample index of photon stream `stream`: far above any pixel sample,
/// so that photon paths and camera samples never share random numbers.
#[inline]
pub fn photon_sample_index(stream: u64) -> u64 {
    (1 << 48) | stream
}

/// The vertices of light paths that `keep` turns into items (photons,
/// virtual point lights), for paths `0..settings.paths` in batches of
/// [`BATCH`], in path order whatever the threads.
pub struct LightVertices<T> {
    pub items: Vec<T>,
    /// Light paths traced (`N`; fewer than asked if interrupted).
    pub paths: u64,
    pub interrupted: bool,
}

/// A light-subpath vertex offered to the `keep` of [`trace_light_vertices`]:
/// the vertex `y_k` (`k ≥ 1`, on a surface that is not a mirror or glass),
/// its `k`, and whether every vertex between the light and it was a delta.
pub struct LightVertex<'a> {
    pub vertex: &'a Vertex,
    pub segments: u32,
    pub only_delta_before: bool,
}

/// Traces the light paths of `settings` on rayon's pool, stopping after the
/// batches in progress once `stop` is set, and keeps what `keep` makes of
/// each non-delta surface vertex. Draws, per light path, the light
/// subpath's numbers ([`light_subpath`]) from `Sampler::new(seed, path,
/// photon_sample_index(stream))`. The items' `β` is not divided by `N`.
pub fn trace_light_vertices<T: Send>(
    scene: &Scene,
    settings: &PhotonTracing,
    stop: &AtomicBool,
    keep: impl Fn(LightVertex) -> Option<T> + Sync,
) -> LightVertices<T> {
    let batches = settings.paths.div_ceil(BATCH);
    let results: Vec<Option<(Vec<T>, u64)>> = (0..batches)
        .into_par_iter()
        .map(|b| {
            if stop.load(Ordering::Relaxed) {
                return None;
            }
            let first = b * BATCH;
            let last = (first + BATCH).min(settings.paths);
            Some((
                trace_batch(scene, settings, first..last, &keep),
                last - first,
            ))
        })
        .collect();
    let mut all = LightVertices {
        items: Vec::new(),
        paths: 0,
        interrupted: false,
    };
    for batch in results {
        let Some((items, paths)) = batch else {
            all.interrupted = true;
            break;
        };
        all.items.extend(items);
        all.paths += paths;
    }
    all
}

/// The items of light paths `paths`.
fn trace_batch<T>(
    scene: &Scene,
    s: &PhotonTracing,
    paths: std::ops::Range<u64>,
    keep: &impl Fn(LightVertex) -> Option<T>,
) -> Vec<T> {
    let mut out = Vec::new();
    // An item needs one camera segment after it: at most D − 1 of its own,
    // i.e. light subpaths of at most D vertices.
    let max_vertices = path_vertices(s.max_depth).saturating_sub(1);
    let mut path: Subpath = Vec::new();
    for i in paths {
        let mut sampler = Sampler::new(s.seed, i, photon_sample_index(s.stream));
        let n = light_subpath(scene, &mut sampler, &mut path, max_vertices, s.rr_depth);
        let mut only_delta = true;
        for (k, v) in path.iter().enumerate().take(n).skip(1) {
            if v.kind != VertexKind::Surface || scene.brdf(&v.it).is_delta() {
                continue;
            }
            if v.beta.is_finite() && v.beta.max_element() > 0.0 {
                out.extend(keep(LightVertex {
                    vertex: v,
                    segments: k as u32,
                    only_delta_before: only_delta,
                }));
            }
            only_delta = false;
        }
    }
    out
}

/// Traces the photons of `settings` (see [`trace_light_vertices`]), their
/// power divided by the number of paths.
pub fn trace_photons(scene: &Scene, settings: &PhotonTracing, stop: &AtomicBool) -> TracedPhotons {
    let traced = trace_light_vertices(scene, settings, stop, |v| {
        let kind = match (v.segments, v.only_delta_before) {
            (1, _) => PhotonKind::Direct,
            (_, true) => PhotonKind::Caustic,
            _ => PhotonKind::Indirect,
        };
        let photon = Photon {
            p: v.vertex.it.p.into(),
            wi: v.vertex.it.wo.into(),
            power: Vec3::from(v.vertex.beta),
            segments: v.segments,
        };
        Some((kind, photon))
    });
    // Each path's β is a flux estimate: share it out among the N paths.
    let scale = 1.0 / traced.paths.max(1) as f32;
    let mut all = TracedPhotons {
        paths: traced.paths,
        interrupted: traced.interrupted,
        ..TracedPhotons::default()
    };
    for (kind, mut photon) in traced.items {
        photon.power *= scale;
        match kind {
            PhotonKind::Direct => all.direct.push(photon),
            PhotonKind::Caustic => all.caustic.push(photon),
            PhotonKind::Indirect => all.indirect.push(photon),
        }
    }
    all
}
