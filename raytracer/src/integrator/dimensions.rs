//! The random-number layout of every integrator: which numbers each step
//! draws, in which order.
//!
//! Lecture topic: Monte Carlo — every random number is a pure function of
//! (seed, pixel or path, sample, dimension), and the dimension is simply the
//! count of numbers drawn before it in the same pixel sample. So the order
//! and the number of draws are part of every picture: one more draw anywhere
//! shifts all later dimensions and changes the image bit for bit (and every
//! reference image of the grader). Each step therefore draws through one of
//! the named [`Draw`]s below, and nowhere else (a test holds the integrators
//! to that); a new draw needs a name here and a line in the layouts.
//!
//! # Steps
//!
//! | step | draws |
//! |---|---|
//! | camera ray ([`super::camera_ray`]) | [`FILM`] (2), [`LENS`] (2) |
//! | light sample ([`super::nee::sample_light_point`]) | [`LIGHT_CHOICE`] (1), [`LIGHT_POINT`] (2) |
//! | continuation ([`super::continuation::sample_continuation`]) | [`BRDF_LOBE`] (1), [`BRDF_DIRECTION`] (2) |
//! | Russian roulette ([`super::roulette::russian_roulette`]) | [`ROULETTE`] (1), none when the path ends for sure (`q ≤ 0`) |
//! | light path's start ([`super::subpath::light_subpath`]) | [`LIGHT_CHOICE`] (1), [`EMISSION_POINT`] (2), [`EMISSION_DIRECTION`] (2) |
//! | connection to the camera (light tracing, `t = 1`) | [`LENS`] (2) |
//! | occlusion ray (ambient occlusion) | [`AO_DIRECTION`] (2) |
//! | visible point ([`super::visible_point::visible_point`]) | camera ray, then a continuation per mirror or glass bounce |
//! | irradiance-cache ray ([`super::irradiance_cache`]) | [`IC_DIRECTION`] (2), then per surface: light sample (not at delta surfaces), continuation, roulette |
//! | irradiance-cache ray with gradients | [`IC_STRATUM`] (2) instead of [`IC_DIRECTION`], the rest alike; a record's rays go cell by cell, `θ` band `j` outer, `φ` sector `k` inner |
//!
//! # Layouts
//!
//! In order, for one pixel sample. "Roulette" is drawn only where Russian
//! roulette plays (from `rr_depth` bounces on, or with naive recursion's
//! `--roulette`).
//!
//! - **direct**: camera ray; at a hit: light sample, continuation.
//! - **ao**: camera ray; at a hit: occlusion ray.
//! - **path** (and `path-brdf`, `path-nee`): camera ray; then per bounce, at a
//!   hit below the maximum depth: light sample (not for `path-brdf`),
//!   continuation, roulette.
//! - **naive**: camera ray; at a hit below the maximum depth, for each of its
//!   `N` branches in turn: continuation, roulette, then that branch's whole
//!   recursion, depth first.
//! - **light**: light path's start; per bounce of the light subpath:
//!   continuation, roulette; then for each light vertex in order: connection
//!   to the camera.
//! - **bdpt**: the camera subpath (camera ray; per bounce: continuation,
//!   roulette), the light subpath (light path's start; per bounce:
//!   continuation, roulette), then the strategies for `t = 1, 2, …` and
//!   within each `s = 0, 1, …`: `t = 1` draws a connection to the camera,
//!   `s = 1` (`t ≥ 2`, at a vertex that can be connected to) a light sample,
//!   the others nothing. The three parts start the camera, light and
//!   connection [`Stream`](crate::sampling::Stream)s, which change nothing
//!   here (a hashed sampler reads one sequence) but Metropolis's layout.
//! - **mlt** (Metropolis light transport, [`crate::render::metropolis`]):
//!   the pixel (2 numbers), then the layout of the integrator it runs over;
//!   the numbers are the coordinates of the chain's state, number `k` of
//!   stream `s` (camera 0, light 1, connection 2) coordinate `s + 3k`; the
//!   pixel and an integrator without streams read the camera stream.
//! - **photon**, **vpl**, **sppm** (one pixel's pass), **irradiance-cache**:
//!   the visible point; there, below the maximum depth: light sample. Then
//!   `photon` with final gathering, for each gather ray: continuation and a
//!   continuation per delta bounce; `irradiance-cache` at a point no record
//!   covers: its record rays (`rays` of them, or with gradients one per
//!   cell of its `M × N` strata), and at a Phong surface: continuation and an
//!   irradiance-cache ray's path. Their light paths (photons, VPLs) and the
//!   cache's records draw from streams of their own (see Streams below),
//!   each light path as a light path's start and per bounce: continuation,
//!   roulette.
//!
//! # Streams
//!
//! Numbers that belong to no pixel sample come from streams of their own,
//! named here in one place so that no two algorithms share one by accident:
//! the light paths of photon mapping, instant radiosity and SPPM's passes
//! (sample index `2^48 + stream`, [`super::photon::photon_sample_index`]),
//! the irradiance cache's records (sample index `2^47`) and the derived
//! seeds of Metropolis light transport's chains.

use crate::sampling::Draw;

/// Light-path stream of photon mapping's photons.
pub const PHOTON_MAPPING_STREAM: u64 = 0;
/// Light-path stream of instant radiosity's VPLs.
pub const VPL_STREAM: u64 = 1;
/// Light-path stream of SPPM's first pass; pass `k` uses this plus `k`.
pub const SPPM_FIRST_STREAM: u64 = 2;
/// Sample index of the irradiance cache's record rays (pixel: the record's
/// index): below the photon streams, far above any pixel sample.
pub const IRRADIANCE_CACHE_SAMPLE: u64 = 1 << 47;
/// Derived-seed names of Metropolis light transport's streams
/// ([`crate::render::metropolis`]): the bootstrap paths, the choice of each
/// chain's start, the chain's accept/reject numbers, its large steps and
/// its small steps.
pub const METROPOLIS_BOOTSTRAP_STREAM: u64 = 1;
pub const METROPOLIS_START_STREAM: u64 = 2;
pub const METROPOLIS_CONTROL_STREAM: u64 = 3;
pub const METROPOLIS_LARGE_STREAM: u64 = 4;
pub const METROPOLIS_SMALL_STREAM: u64 = 5;

/// The position of a camera sample within its pixel (a box filter).
pub const FILM: Draw<2> = Draw::new("position within the pixel");
/// A point on the lens (a pinhole ignores it but draws it all the same).
pub const LENS: Draw<2> = Draw::new("point on the lens");
/// Which light: next event estimation, and where a light path starts.
pub const LIGHT_CHOICE: Draw<1> = Draw::new("which light");
/// A point on the chosen light, as seen from the receiving point.
pub const LIGHT_POINT: Draw<2> = Draw::new("point on the light, seen from the receiver");
/// The point on the chosen light where a light path starts.
pub const EMISSION_POINT: Draw<2> = Draw::new("point where a light path starts");
/// The direction in which a light path leaves the light.
pub const EMISSION_DIRECTION: Draw<2> = Draw::new("direction a light path leaves in");
/// Which lobe of the BRDF (glass: reflection or refraction).
pub const BRDF_LOBE: Draw<1> = Draw::new("BRDF lobe");
/// The direction within the lobe.
pub const BRDF_DIRECTION: Draw<2> = Draw::new("direction from the BRDF");
/// Whether Russian roulette lets the path go on.
pub const ROULETTE: Draw<1> = Draw::new("Russian roulette");
/// The cosine-distributed direction of an occlusion ray.
pub const AO_DIRECTION: Draw<2> = Draw::new("direction of an occlusion ray");
/// The cosine-distributed direction of an irradiance-cache ray.
pub const IC_DIRECTION: Draw<2> = Draw::new("direction of an irradiance-cache ray");
/// The point within its `(θ, φ)` cell of a stratified irradiance-cache ray
/// (with gradients: `sin²θ = (j + u_x)/M`, `φ = 2π(k + u_y)/N`).
pub const IC_STRATUM: Draw<2> = Draw::new("point within a cell of an irradiance-cache record");
