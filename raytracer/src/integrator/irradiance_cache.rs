//! Irradiance caching (Ward, Rubinstein & Clear 1988), with Ward &
//! Heckbert's irradiance gradients (1992) as an option: the
//! `irradiance-cache` integrator.
//!
//! Lecture topic: "Algorithms for Global Illumination" — the second biased
//! algorithm of the lecture's list. Indirect light on a diffuse surface
//! changes slowly, so it is computed carefully at a few points (*records*)
//! and interpolated in between. At a Lambert surface `x`
//!
//! ```text
//!   L(x, ω_o) = L_e + L_direct (a light sample) + ρ/π · E_ind(x)
//! ```
//!
//! where a record at `x_i` holds `E_i = (π/N) Σ_k L_ind(x_i, ω_k)` (N
//! cosine-distributed rays, each continued as a path tracer with light
//! sampling does, without the emission of the surface it first hits: that
//! light is direct light, sampled already) and the harmonic mean `R_i` of the
//! distances the rays travelled. `x` uses every record whose error
//!
//! ```text
//!   ε_i(x) = ‖x − x_i‖ / R_i + √(1 − n · n_i)
//! ```
//!
//! stays below the threshold `a`, weighted by `w_i = 1/ε_i`:
//! `E(x) = Σ w_i E_i / Σ w_i`. Where surfaces are close (`R_i` small:
//! corners, contact) records crowd; on open walls one record serves a wide
//! disk. A larger `a` means fewer records, a faster render, and the bias of
//! interpolation: blotches where the records' own noise is spread over a
//! disk, and light smeared across changes it should follow. As `a` shrinks
//! the cache approaches the path tracer's indirect light.
//!
//! # Irradiance gradients (`gradients`, `--ic-gradients`)
//!
//! Averaging treats every record as flat: a record at a wall's foot says
//! nothing about the wall getting brighter towards the corner. Ward &
//! Heckbert read, from the very rays that made `E_i`, how `E` changes when
//! the normal turns (rotational gradient `∇_r E_i`) and when the point moves
//! in its tangent plane (translational gradient `∇_t E_i`), and interpolate
//! first-order extrapolations instead of constants (each channel clamped at
//! zero, a first-order guess can go below):
//!
//! ```text
//!   E(x) = Σ w_i max(0, E_i + (n_i × n)·∇_r E_i + (x − x_i)·∇_t E_i) / Σ w_i
//! ```
//!
//! For that the hemisphere is sampled *stratified*, in `M × N` cells that
//! each hold the same projected solid angle `π/(MN)`: `M` bands in `θ`
//! uniform in `sin²θ` (cosine-distributed) and `N` sectors in `φ`, one ray
//! per cell (`N ≈ πM` keeps the cells square: [`Strata::for_rays`]). Ray
//! `(j, k)` leaves at `sin²θ = (j + ξ₁)/M`, `φ = 2π(k + ξ₂)/N`, brings back
//! `L_jk` and the distance `r_jk` to what it hit, and `E_i = (π/MN) Σ L_jk`
//! as before. With the band edges `sin²θ_j− = j/M` (`θ_j+ = θ_(j+1)−`),
//! the cell centres `θ_j` (`sin²θ_j = (j + ½)/M`) and `φ_k = 2π(k + ½)/N`,
//! the sector edges `φ_k− = 2πk/N`, and in the tangent plane
//! `u(φ) = (cos φ, sin φ, 0)`, `v(φ) = (−sin φ, cos φ, 0)`:
//!
//! - **Rotation.** Turning the normal by a small rotation `α` (axis times
//!   angle) changes `cos θ = n·ω` by `α·(n × ω)`, so
//!   `∇_r E = ∫ L(ω) (n × ω) dω`, with `n × ω = sin θ v(φ)`: divided by
//!   the density `cos θ/π`, each cell's `L_jk` counts with `tan θ v(φ)`.
//!   Ward & Heckbert take `tan θ_j` at the cell's centre (at the ray's own
//!   `θ` the variance would be infinite: `∫ tan²θ cos θ dω` diverges at the
//!   horizon), and write `−tan θ_j` with `v` pointing the other way. The
//!   centre's value is low, as `tan` is convex and steep near the horizon
//!   (7% low on the half-plane of this module's test, even at `M = 36`), so
//!   here each cell counts with the *mean* of `tan θ v(φ)` over it under
//!   the cosine density, exact when `L` is constant over the cell and as
//!   bounded as Ward's:
//!
//!   ```text
//!     ∇_r E ≈ (π/MN) Σ_k s_N v(φ_k) Σ_j t_j L_jk,
//!     t_j = 2M ∫_{θ_j−}^{θ_j+} sin²θ dθ = M [θ − sin θ cos θ]_{θ_j−}^{θ_j+},
//!     s_N = sin(π/N) / (π/N)   (the mean of v(φ) over a sector is s_N v(φ_k))
//!   ```
//!
//! - **Translation.** Moving `x` by `δ` leaves the radiance inside each
//!   cell as it is, but slides the scene across the cells' edges: a surface
//!   at distance `r` drifts by `δ·e_θ / r` in `θ` and by
//!   `δ·v(φ) / (r sin θ)` in `φ`. Across an edge between cells of radiance
//!   `L_a` and `L_b` the projected solid angle `cos θ sin θ dθ dφ` of the
//!   strip that changes hands times `L_b − L_a` is the change of `E`; taking
//!   for `r` the nearer of the two cells' distances (the nearer surface is
//!   the one that moves, and occludes), and summing the `θ` edges (between
//!   bands `j − 1` and `j`) and the `φ` edges (between sectors `k − 1` and
//!   `k`, cyclic):
//!
//!   ```text
//!     ∇_t E ≈ Σ_k [ u(φ_k) (2π/N) Σ_{j=1}^{M−1} sin θ_j− cos²θ_j− (L_jk − L_(j−1)k) / min(r_jk, r_(j−1)k)
//!                  + v(φ_k−) Σ_{j=0}^{M−1} (sin θ_j+ − sin θ_j−) (L_jk − L_j(k−1)) / min(r_jk, r_j(k−1)) ]
//!   ```
//!
//!   (the `θ` edge integrates `cos(φ − φ_δ)` over the sector, ≈ `(2π/N)
//!   cos(φ_k − φ_δ)`, which is used exactly here: `2 sin(π/N)` for `2π/N`;
//!   the `φ` edge `cos θ` over the band). It lies in the tangent plane; `r_jk` is
//!   clamped below as `R_i` is, so that a contact does not make it
//!   explode.
//!
//! Both come free: no extra rays, only `M × N` stored `(L, r)` pairs per
//! record while it is made, and six vectors per record kept. At the same
//! `a` the image is smoother and closer to the path tracer: on the Cornell
//! box (`raytracer/tests/biased.rs`) the RMSE falls by a quarter at
//! `a = 1`, by 12–15% at `a = 0.4–0.6`. Later
//! refinements (Křivánek et al.'s gradient limiting and neighbour clamping,
//! Jarosz et al.'s improved gradients) are left out. Off by default: the
//! lecture meets the 1988 cache first, and off the sampling is the 1988
//! one, so its images stay what they were bit for bit.
//!
//! **Determinism.** Records are made level by level on a grid of pixel
//! centres, every 16th pixel, then every 8th, …, every pixel: at each level
//! the pixels whose visible point no record covers yet make a record each
//! (in parallel, with random numbers keyed by the pixel), added in raster
//! order. The cache is then fixed, and the render only reads it. A point the
//! cache does not cover at render time (rare: between the pixel centres
//! and the cache's validity disks) gets an estimate of its own, not stored.
//!
//! Surfaces that are not Lambert (Phong) get their indirect light from one
//! BRDF sample continued as above; mirrors and glass are followed to the
//! visible point ([`super::visible_point`]).

use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use rayon::prelude::*;

use super::continuation::sample_continuation;
use super::dimensions::{IC_DIRECTION, IC_STRATUM};
use super::grid::Grid;
use super::roulette::russian_roulette;
use super::visible_point::{GatherPoint, follow_delta_chain, lit_visible_point};
use super::{Integrator, nee, stop};
use crate::brdf::{Brdf, TransportMode};
use crate::film::Splat;
use crate::frame::Frame;
use crate::geometry::Interaction;
use crate::math::{Color, PI, Ray, UVec2, Vec2, Vec3A};
use crate::sampling::Sampler;
use crate::sampling::warp::cosine_hemisphere;
use crate::scene::Scene;

/// The options of irradiance caching.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IrradianceCacheSettings {
    /// The error threshold `a` (Ward's; 0.1–0.5 is usual).
    pub error: f32,
    /// Hemisphere rays per record.
    pub rays: u32,
    pub max_depth: Option<u32>,
    pub rr_depth: u32,
    pub seed: u64,
    /// Ward & Heckbert's irradiance gradients: stratified record rays and
    /// first-order extrapolation (see the module doc). Off by default.
    pub gradients: bool,
}

impl Default for IrradianceCacheSettings {
    fn default() -> Self {
        IrradianceCacheSettings {
            error: 0.3,
            rays: 128,
            max_depth: None,
            rr_depth: 5,
            seed: 0,
            gradients: false,
        }
    }
}

impl IrradianceCacheSettings {
    /// One line naming what is wrong, if anything is.
    pub fn check(&self) -> Result<(), String> {
        if !(self.error.is_finite() && self.error > 0.0) {
            return Err(format!(
                "--ic-error must be a positive threshold a (0.1–0.5 is usual), got {}",
                self.error
            ));
        }
        if self.rays == 0 {
            return Err("--ic-rays must be at least 1 (hemisphere rays per record)".into());
        }
        if self.gradients && self.rays < Strata::MIN_RAYS {
            return Err(format!(
                "--ic-gradients needs --ic-rays of at least {} (M × N strata, at least 2 in θ and 6 in φ), got {}",
                Strata::MIN_RAYS,
                self.rays
            ));
        }
        Ok(())
    }
}

/// A record of the cache.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Record {
    pub p: Vec3A,
    /// The shading normal, on the side the camera saw.
    pub n: Vec3A,
    /// The indirect irradiance `E_i`.
    pub e: Color,
    /// The harmonic mean distance `R_i`, clamped.
    pub r: f32,
    /// Segments from the lens to the record's point (the depth its rays start at).
    pub depth: u32,
}

/// Ward & Heckbert's gradients of a record's `E_i`, one vector per colour
/// channel (in world space).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Gradients {
    /// `∇_r E_i`: turning the normal from `n_i` to `n` changes `E` by
    /// `(n_i × n)·∇_r E_i`.
    pub rotation: [Vec3A; 3],
    /// `∇_t E_i`, in the record's tangent plane: moving from `x_i` to `x`
    /// changes `E` by `(x − x_i)·∇_t E_i`.
    pub translation: [Vec3A; 3],
}

impl Gradients {
    /// `max(0, E_i + axis·∇_r E_i + d·∇_t E_i)` per channel, with `axis =
    /// n_i × n` and `d = x − x_i`.
    pub fn extrapolate(&self, e: Color, axis: Vec3A, d: Vec3A) -> Color {
        let channel =
            |c: usize| (e[c] + axis.dot(self.rotation[c]) + d.dot(self.translation[c])).max(0.0);
        Color::new(channel(0), channel(1), channel(2))
    }

    /// The gradients turned from a local frame (normal `z`) to the world.
    fn to_world(self, frame: &Frame) -> Gradients {
        Gradients {
            rotation: self.rotation.map(|g| frame.to_world(g)),
            translation: self.translation.map(|g| frame.to_world(g)),
        }
    }
}

/// The `M × N` cells of a stratified record: `M` bands in `θ`, uniform in
/// `sin²θ` (so that every cell holds the projected solid angle `π/(MN)`),
/// and `N` sectors in `φ`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Strata {
    pub m: u32,
    pub n: u32,
}

impl Strata {
    /// The fewest rays for which gradients are made (`2 × 6` strata).
    pub const MIN_RAYS: u32 = 12;

    /// Square-ish cells from at most `rays` rays: a band is `π/2M` high at
    /// the zenith and a sector `2π/N` wide, so `N ≈ πM`:
    /// `M = round(√(rays/π))`, `N = ⌊rays/M⌋` (128 rays: 6 × 21 = 126).
    pub fn for_rays(rays: u32) -> Strata {
        let m = ((rays as f32 / PI).sqrt().round() as u32).max(1);
        Strata {
            m,
            n: (rays / m).max(1),
        }
    }

    /// The rays used: `M·N`.
    pub fn rays(&self) -> u32 {
        self.m * self.n
    }

    /// The local direction (normal `z`) of the ray of cell `(j, k)` at the
    /// point `u` within it: `sin²θ = (j + u_x)/M`, `φ = 2π(k + u_y)/N`.
    pub fn direction(&self, j: u32, k: u32, u: Vec2) -> Vec3A {
        let sin2 = ((j as f32 + u.x) / self.m as f32).min(1.0);
        let (sin_t, cos_t) = (sin2.sqrt(), (1.0 - sin2).max(0.0).sqrt());
        let phi = 2.0 * PI * (k as f32 + u.y) / self.n as f32;
        Vec3A::new(sin_t * phi.cos(), sin_t * phi.sin(), cos_t)
    }

    /// `(E, R, gradients)` in the local frame (normal `z`) from one ray per
    /// cell: `trace(j, k)` returns the cell's `(L_jk, r_jk)`, called for
    /// `j = 0..M` and within each `k = 0..N`, in that order. Distances
    /// below `r_min` count as `r_min` in the translational gradient. The
    /// formulas are the module doc's.
    pub fn estimate(
        &self,
        r_min: f32,
        mut trace: impl FnMut(u32, u32) -> (Color, f32),
    ) -> (Color, f32, Gradients) {
        let (m, n) = (self.m as usize, self.n as usize);
        let mut cells = Vec::with_capacity(m * n);
        for j in 0..self.m {
            // A stop request ends the record (its caller drops it).
            if stop::stop_requested() {
                return (Color::ZERO, 1.0, Gradients::default());
            }
            for k in 0..self.n {
                cells.push(trace(j, k));
            }
        }
        let cell = |j: usize, k: usize| cells[j * n + k];
        // 1/min(r_a, r_b): a ray that escaped (r = ∞) adds nothing.
        let inv_min = |a: f32, b: f32| 1.0 / a.min(b).max(r_min);
        let u = |phi: f32| Vec3A::new(phi.cos(), phi.sin(), 0.0);
        let v = |phi: f32| Vec3A::new(-phi.sin(), phi.cos(), 0.0);
        let (mf, nf) = (m as f32, n as f32);
        // Per band j, computed once (every sector uses them): t_j = M [θ −
        // sin θ cos θ] between the band's edges (sin²θ_j− = j/M); the weight
        // of its upper θ edge but for 1/min(r), 2 sin(π/N) sin θ_j− cos²θ_j−;
        // the width sin θ_j+ − sin θ_j− of its φ edges.
        let sin_pi_n = (PI / nf).sin();
        let f = |s2: f32| {
            let s2 = s2.min(1.0);
            s2.sqrt().asin() - (s2 * (1.0 - s2)).sqrt()
        };
        let band_tan: Vec<f32> = (0..m)
            .map(|j| mf * (f((j + 1) as f32 / mf) - f(j as f32 / mf)))
            .collect();
        let theta_edge: Vec<f32> = (0..m)
            .map(|j| {
                let s2 = j as f32 / mf;
                2.0 * sin_pi_n * s2.sqrt() * (1.0 - s2)
            })
            .collect();
        let band_width: Vec<f32> = (0..m)
            .map(|j| ((j + 1) as f32 / mf).sqrt() - (j as f32 / mf).sqrt())
            .collect();
        let s_n = sin_pi_n / (PI / nf);
        let (mut e, mut inv_dist) = (Color::ZERO, 0.0f32);
        let mut g = Gradients::default();
        let add = |to: &mut [Vec3A; 3], dir: Vec3A, l: Color| {
            for (c, t) in to.iter_mut().enumerate() {
                *t += dir * l[c];
            }
        };
        for k in 0..n {
            let phi_k = 2.0 * PI * (k as f32 + 0.5) / nf;
            let phi_edge = 2.0 * PI * k as f32 / nf;
            let (u_k, v_k, v_edge) = (u(phi_k), v(phi_k), v(phi_edge));
            let prev = (k + n - 1) % n;
            for j in 0..m {
                let (l, r) = cell(j, k);
                e += l;
                inv_dist += 1.0 / r.max(1e-4);
                // Rotation: the cell's mean of tan θ v(φ), s_N t_j v(φ_k).
                add(&mut g.rotation, v_k, l * (s_n * band_tan[j]));
                // Translation across the θ edge sin²θ_j− = j/M (to band j − 1).
                if j > 0 {
                    let (l_up, r_up) = cell(j - 1, k);
                    let w = theta_edge[j] * inv_min(r, r_up);
                    add(&mut g.translation, u_k, (l - l_up) * w);
                }
                // Translation across the φ edge φ_k− (to sector k − 1).
                let (l_side, r_side) = cell(j, prev);
                add(
                    &mut g.translation,
                    v_edge,
                    (l - l_side) * (band_width[j] * inv_min(r, r_side)),
                );
            }
        }
        let scale = PI / (mf * nf);
        g.rotation = g.rotation.map(|r| r * scale);
        (e * scale, (mf * nf) / inv_dist.max(1e-6), g)
    }
}

/// The sample index of the cache's own random numbers (far above pixel samples).
const CACHE_SAMPLE: u64 = super::dimensions::IRRADIANCE_CACHE_SAMPLE;

/// Irradiance caching with its cache filled.
#[derive(Clone, Debug)]
pub struct IrradianceCache {
    pub settings: IrradianceCacheSettings,
    records: Vec<Record>,
    /// The records' gradients, in the same order (empty without `gradients`).
    gradients: Vec<Gradients>,
    grid: Grid,
    /// `R_i` is clamped to this range (from the scene's size).
    r_range: (f32, f32),
    pub building: Duration,
    pub interrupted: bool,
}

impl IrradianceCache {
    /// Fills the cache for `scene`'s camera (see the module doc), on rayon's
    /// pool. `stop` ends the filling at once: a record whose rays saw it is
    /// dropped, the records made before it are kept (the cache is then
    /// marked `interrupted`).
    pub fn build(
        scene: &Scene,
        settings: IrradianceCacheSettings,
        stop: &AtomicBool,
    ) -> Result<IrradianceCache, String> {
        settings.check()?;
        let start = Instant::now();
        let diag = {
            let b = scene.geometry.bounds();
            if b.is_empty() {
                1.0
            } else {
                b.diagonal().length()
            }
        };
        let mut cache = IrradianceCache {
            settings,
            records: Vec::new(),
            gradients: Vec::new(),
            grid: Grid::empty(),
            r_range: (0.005 * diag, 0.25 * diag),
            building: Duration::ZERO,
            interrupted: false,
        };
        let (w, h) = (scene.camera.width, scene.camera.height);
        for stride in [16u32, 8, 4, 2, 1] {
            if stop.load(Ordering::Relaxed) {
                cache.interrupted = true;
                break;
            }
            let pixels: Vec<UVec2> = (0..h)
                .step_by(stride as usize)
                .flat_map(|y| {
                    (0..w)
                        .step_by(stride as usize)
                        .map(move |x| UVec2::new(x, y))
                })
                .collect();
            // A record of 2³² rays takes minutes: its rays watch `stop` too.
            let new: Vec<(Record, Option<Gradients>)> = pixels
                .par_iter()
                .filter_map(|&pixel| {
                    stop::watch(stop, || {
                        let record = cache.record_for_pixel(scene, pixel);
                        let abandoned = stop::take_abandoned();
                        record.filter(|_| !abandoned)
                    })
                })
                .collect();
            for (record, gradients) in new {
                cache.records.push(record);
                cache.gradients.extend(gradients);
            }
            cache.rebuild_grid();
        }
        cache.interrupted |= stop.load(Ordering::Relaxed);
        cache.building = start.elapsed();
        Ok(cache)
    }

    /// The records (for pictures of where they are).
    pub fn records(&self) -> &[Record] {
        &self.records
    }

    /// The records' gradients, in the order of [`Self::records`] (empty
    /// without `gradients`).
    pub fn gradients(&self) -> &[Gradients] {
        &self.gradients
    }

    /// Bytes one record holds (with its gradients, if any).
    pub fn record_bytes(&self) -> usize {
        std::mem::size_of::<Record>()
            + if self.settings.gradients {
                std::mem::size_of::<Gradients>()
            } else {
                0
            }
    }

    /// Bytes the records and their grid hold.
    pub fn bytes(&self) -> usize {
        self.records.len() * self.record_bytes() + self.grid.bytes()
    }

    /// One line on the cache.
    pub fn summary(&self) -> String {
        format!(
            "irradiance cache: a = {}, {} records × {} bytes = {:.2} MiB ({}, built in {:.2} s){}",
            self.settings.error,
            self.records.len(),
            self.record_bytes(),
            self.bytes() as f64 / (1 << 20) as f64,
            if self.settings.gradients {
                let s = Strata::for_rays(self.settings.rays);
                format!(
                    "{} rays each in {} × {} strata, with gradients",
                    s.rays(),
                    s.m,
                    s.n
                )
            } else {
                format!("{} rays each", self.settings.rays)
            },
            self.building.as_secs_f64(),
            if self.interrupted {
                ", INTERRUPTED"
            } else {
                ""
            }
        )
    }

    fn rebuild_grid(&mut self) {
        let (mut lo, mut hi) = (Vec3A::splat(f32::MAX), Vec3A::splat(f32::MIN));
        let a = self.settings.error;
        for r in &self.records {
            lo = lo.min(r.p - Vec3A::splat(a * r.r));
            hi = hi.max(r.p + Vec3A::splat(a * r.r));
        }
        let mean_r =
            self.records.iter().map(|r| r.r).sum::<f32>() / self.records.len().max(1) as f32;
        let records = &self.records;
        self.grid = Grid::build(lo, hi, a * mean_r, records.len(), |i| {
            let reach = Vec3A::splat(a * records[i].r);
            (records[i].p - reach, records[i].p + reach)
        });
    }

    /// The record a pixel centre's visible point needs, if no record covers
    /// it yet and it is a Lambert surface.
    fn record_for_pixel(&self, scene: &Scene, pixel: UVec2) -> Option<(Record, Option<Gradients>)> {
        let index = pixel.y as u64 * scene.camera.width as u64 + pixel.x as u64;
        let mut sampler = Sampler::new(self.settings.seed, index, CACHE_SAMPLE);
        let ray = scene
            .camera
            .generate_ray(pixel.as_vec2() + Vec2::splat(0.5), Vec2::splat(0.5));
        let vp = follow_delta_chain(
            scene,
            ray,
            Color::ONE,
            1,
            &mut sampler,
            self.settings.max_depth,
            false,
        );
        let x = vp.hit?;
        if !diffuse_towards_viewer(scene.brdf(&x), &x) || vp.depth >= self.max_depth() {
            return None;
        }
        if self.interpolate(&x, vp.depth).is_some() {
            return None;
        }
        Some(self.new_record(scene, &x, vp.depth, &mut sampler))
    }

    fn max_depth(&self) -> u32 {
        super::max_segments(self.settings.max_depth)
    }

    /// A new record at `x`, reached in `depth` segments.
    fn new_record(
        &self,
        scene: &Scene,
        x: &Interaction,
        depth: u32,
        sampler: &mut Sampler,
    ) -> (Record, Option<Gradients>) {
        let (e, r, gradients) = self.irradiance(scene, x, depth, sampler);
        let record = Record {
            p: x.p,
            n: facing_normal(x),
            e,
            r: r.clamp(self.r_range.0, self.r_range.1),
            depth,
        };
        (record, gradients)
    }

    /// `(E_ind, R, gradients)` at `x` by the cache's hemisphere rays:
    /// with `gradients`, one per cell of [`Strata::for_rays`] (drawing, per
    /// ray, [`IC_STRATUM`] and then the path's numbers); without, `rays`
    /// cosine-distributed ones (drawing [`IC_DIRECTION`] and then the path's).
    fn irradiance(
        &self,
        scene: &Scene,
        x: &Interaction,
        depth: u32,
        sampler: &mut Sampler,
    ) -> (Color, f32, Option<Gradients>) {
        let frame = Frame::from_normal(facing_normal(x));
        if self.settings.gradients {
            let strata = Strata::for_rays(self.settings.rays);
            let (e, r, g) = strata.estimate(self.r_range.0, |j, k| {
                let w = strata.direction(j, k, IC_STRATUM.draw(sampler));
                incoming_indirect(
                    scene,
                    x.spawn_ray(frame.to_world(w)),
                    depth + 1,
                    self.settings.max_depth,
                    self.settings.rr_depth,
                    sampler,
                )
            });
            return (e, r, Some(g.to_world(&frame)));
        }
        let n = self.settings.rays;
        let (mut sum, mut inv_dist) = (Color::ZERO, 0.0f32);
        for _ in 0..n {
            // The caller drops a record cut short.
            if stop::stop_requested() {
                break;
            }
            let w = frame.to_world(cosine_hemisphere(IC_DIRECTION.draw(sampler)));
            let ray = x.spawn_ray(w);
            let (l, t) = incoming_indirect(
                scene,
                ray,
                depth + 1,
                self.settings.max_depth,
                self.settings.rr_depth,
                sampler,
            );
            sum += l;
            inv_dist += 1.0 / t.max(1e-4);
        }
        // E = ∫ L cos θ dω ≈ (1/N) Σ L cos θ / (cos θ / π) = (π/N) Σ L.
        (sum * (PI / n as f32), n as f32 / inv_dist.max(1e-6), None)
    }

    /// `E(x)` from the records that cover `x` (`None` if none does): the
    /// weighted mean of their `E_i`, or with gradients of their clamped
    /// extrapolations `max(0, E_i + (n_i × n)·∇_r E_i + (x − x_i)·∇_t E_i)`.
    pub fn interpolate(&self, x: &Interaction, depth: u32) -> Option<Color> {
        let n = facing_normal(x);
        let a = self.settings.error;
        let (mut sum, mut weights) = (Color::ZERO, 0.0f32);
        for &i in self.grid.at(x.p) {
            let r = &self.records[i as usize];
            if r.depth != depth {
                continue;
            }
            let d = x.p - r.p;
            // Ward's test: a record in front of x (on the side its light comes from) does not apply.
            if d.dot(n + r.n) * 0.5 < -0.05 * r.r {
                continue;
            }
            let eps = d.length() / r.r + (1.0 - n.dot(r.n)).max(0.0).sqrt();
            if eps >= a {
                continue;
            }
            let w = 1.0 / eps.max(1e-6);
            let e = match self.gradients.get(i as usize) {
                Some(g) => g.extrapolate(r.e, r.n.cross(n), d),
                None => r.e,
            };
            sum += e * w;
            weights += w;
        }
        (weights > 0.0).then(|| sum / weights)
    }
}

/// The shading normal of `x` turned towards `ω_o`.
#[inline]
fn facing_normal(x: &Interaction) -> Vec3A {
    let n = x.frame.n;
    if n.dot(x.wo) < 0.0 { -n } else { n }
}

/// The radiance arriving along `ray` (segment number `depth` of its path)
/// without the emission of the first surface it hits, and that surface's
/// distance: the path tracer with light sampling only (emitters found by a
/// BRDF sample count only after a delta bounce), Russian roulette after
/// `rr_depth` bounces. Draws, per surface below the maximum depth: a light
/// sample (not at mirrors and glass), a continuation, and (from `rr_depth`
/// on) the roulette's number.
pub fn incoming_indirect(
    scene: &Scene,
    mut ray: Ray,
    mut depth: u32,
    max_depth: Option<u32>,
    rr_depth: u32,
    sampler: &mut Sampler,
) -> (Color, f32) {
    let d = super::max_segments(max_depth);
    let (mut l, mut beta) = (Color::ZERO, Color::ONE);
    // Undoes the 1/η² that refraction puts into a radiance throughput, for
    // the roulette only (as the path tracer does).
    let mut eta_scale = 1.0f32;
    let mut count_emission = false;
    let mut first_t = f32::INFINITY;
    let mut bounces = 0u32;
    loop {
        let hit = scene.intersect(&ray);
        if count_emission && let Some(e) = scene.emitter_hit(&ray, hit.as_ref()) {
            l += beta * e.le;
        }
        let Some(it) = hit else { break };
        if bounces == 0 {
            first_t = it.t;
        }
        // Unlimited depth is unlimited: roulette ends the path.
        if depth >= d {
            break;
        }
        let brdf = scene.brdf(&it);
        if !brdf.is_delta() {
            l += beta * nee::sample_light(scene, &it, brdf, sampler, false);
        }
        let Some(c) = sample_continuation(&it, brdf, TransportMode::Radiance, sampler) else {
            break;
        };
        beta *= c.weight;
        eta_scale *= c.sample.eta * c.sample.eta;
        count_emission = c.sample.is_delta;
        ray = c.ray;
        depth += 1;
        bounces += 1;
        if bounces >= rr_depth {
            let Some(q) = russian_roulette(beta, eta_scale, sampler) else {
                break;
            };
            beta /= q;
        }
    }
    (l, first_t)
}

impl Integrator for IrradianceCache {
    fn name(&self) -> &'static str {
        "irradiance-cache"
    }

    fn sample(
        &self,
        scene: &Scene,
        pixel: UVec2,
        sampler: &mut Sampler,
        _splats: &mut Vec<Splat>,
    ) -> Color {
        let (mut l, point) = lit_visible_point(scene, pixel, sampler, self.settings.max_depth);
        let Some(GatherPoint { it: x, beta, depth }) = point else {
            return l;
        };
        let brdf = scene.brdf(&x);
        if diffuse_towards_viewer(brdf, &x) {
            // f_r = ρ/π whatever the directions (on the side it is seen from).
            let f = brdf.eval(Vec3A::Z, Vec3A::Z, x.uv);
            let e = match self.interpolate(&x, depth) {
                Some(e) => e,
                None => self.irradiance(scene, &x, depth, sampler).0,
            };
            l += beta * f * e;
        } else if let Some(c) = sample_continuation(&x, brdf, TransportMode::Radiance, sampler) {
            let (li, _) = incoming_indirect(
                scene,
                c.ray,
                depth + 1,
                self.settings.max_depth,
                self.settings.rr_depth,
                sampler,
            );
            l += beta * c.weight * li;
        }
        l
    }
}

/// Whether `x` reflects as a Lambert surface towards its viewer: Lambert,
/// or a one-sided Lambert seen from the front (from behind it is black, and
/// the cache has nothing to add there).
fn diffuse_towards_viewer(brdf: &Brdf, x: &Interaction) -> bool {
    match brdf {
        Brdf::Lambert(_) => true,
        Brdf::OneSided(inner) => {
            matches!(**inner, Brdf::Lambert(_)) && x.frame.to_local(x.wo).z > 0.0
        }
        _ => false,
    }
}
