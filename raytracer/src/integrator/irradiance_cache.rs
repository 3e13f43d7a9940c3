//! Irradiance caching (Ward, Rubinstein & Clear 1988): the
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
//!
//! Not done (documented): Ward & Heckbert's irradiance gradients, which
//! would let a record extrapolate instead of only average.

use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use rayon::prelude::*;

use super::continuation::sample_continuation;
use super::dimensions::IC_DIRECTION;
use super::grid::Grid;
use super::roulette::russian_roulette;
use super::visible_point::{VisiblePoint, follow_delta_chain, visible_point};
use super::{Integrator, nee};
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
}

impl Default for IrradianceCacheSettings {
    fn default() -> Self {
        IrradianceCacheSettings {
            error: 0.3,
            rays: 128,
            max_depth: None,
            rr_depth: 5,
            seed: 0,
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

/// The sample index of the cache's own random numbers (far above pixel samples).
const CACHE_SAMPLE: u64 = 1 << 47;

/// Irradiance caching with its cache filled.
#[derive(Clone, Debug)]
pub struct IrradianceCache {
    pub settings: IrradianceCacheSettings,
    records: Vec<Record>,
    grid: Grid,
    /// `R_i` is clamped to this range (from the scene's size).
    r_range: (f32, f32),
    pub building: Duration,
    pub interrupted: bool,
}

impl IrradianceCache {
    /// Fills the cache for `scene`'s camera (see the module doc), on rayon's
    /// pool. `stop` ends the filling between levels.
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
            let new: Vec<Record> = pixels
                .par_iter()
                .filter_map(|&pixel| cache.record_for_pixel(scene, pixel))
                .collect();
            cache.records.extend(new);
            cache.rebuild_grid();
        }
        cache.building = start.elapsed();
        Ok(cache)
    }

    /// The records (for pictures of where they are).
    pub fn records(&self) -> &[Record] {
        &self.records
    }

    /// Bytes the records and their grid hold.
    pub fn bytes(&self) -> usize {
        self.records.len() * std::mem::size_of::<Record>() + self.grid.bytes()
    }

    /// One line on the cache.
    pub fn summary(&self) -> String {
        format!(
            "irradiance cache: a = {}, {} records × {} bytes = {:.2} MiB ({} rays each, built in {:.2} s){}",
            self.settings.error,
            self.records.len(),
            std::mem::size_of::<Record>(),
            self.bytes() as f64 / (1 << 20) as f64,
            self.settings.rays,
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
    fn record_for_pixel(&self, scene: &Scene, pixel: UVec2) -> Option<Record> {
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
        self.settings.max_depth.unwrap_or(u32::MAX)
    }

    /// A new record at `x`, reached in `depth` segments.
    fn new_record(
        &self,
        scene: &Scene,
        x: &Interaction,
        depth: u32,
        sampler: &mut Sampler,
    ) -> Record {
        let (e, r) = self.irradiance(scene, x, depth, sampler);
        Record {
            p: x.p,
            n: facing_normal(x),
            e,
            r: r.clamp(self.r_range.0, self.r_range.1),
            depth,
        }
    }

    /// `(E_ind, R)` at `x` by the cache's hemisphere rays. Draws, per ray,
    /// [`IC_DIRECTION`] and then the path's numbers.
    fn irradiance(
        &self,
        scene: &Scene,
        x: &Interaction,
        depth: u32,
        sampler: &mut Sampler,
    ) -> (Color, f32) {
        let frame = Frame::from_normal(facing_normal(x));
        let n = self.settings.rays;
        let (mut sum, mut inv_dist) = (Color::ZERO, 0.0f32);
        for _ in 0..n {
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
        (sum * (PI / n as f32), n as f32 / inv_dist.max(1e-6))
    }

    /// `E(x)` from the records that cover `x` (`None` if none does).
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
            sum += r.e * w;
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
    let d = max_depth.unwrap_or(u32::MAX);
    let (mut l, mut beta) = (Color::ZERO, Color::ONE);
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
        if depth >= d || bounces >= 64 {
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
        count_emission = c.sample.is_delta;
        ray = c.ray;
        depth += 1;
        bounces += 1;
        if bounces >= rr_depth {
            let Some(q) = russian_roulette(beta, 1.0, sampler) else {
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
        let VisiblePoint {
            le,
            hit,
            beta,
            depth,
        } = visible_point(scene, pixel, sampler, self.settings.max_depth);
        let Some(x) = hit else {
            return le;
        };
        if depth >= self.max_depth() {
            return le;
        }
        let brdf = scene.brdf(&x);
        let mut l = le + beta * nee::sample_light(scene, &x, brdf, sampler, false);
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
