//! The path queue: the state of every path of a unit, structure of arrays.
//!
//! One path's state is split across arrays, one per field, indexed by the
//! path's *slot*; a stage reads only the arrays it needs, so the camera
//! stage never touches the throughputs and the trace stage streams through
//! rays alone. The *live list* holds the slots still bouncing, in increasing
//! order; [`PathQueue::compact`] drops the paths that ended, so each stage
//! loops over live paths only and a lane is never spent on a finished one.
//!
//! Slot `i` is sample `k = first + i % n` of the tile's pixel `i / n` (raster
//! order), `n` samples per pixel: reading the slots in order adds the samples
//! to the film in the order of the per-sample render loop.

use crate::geometry::Interaction;
use crate::math::{Color, Ray, Vec3A};
use crate::sampling::Sampler;

/// The BRDF sample that sent a path's current ray: what the MIS weight of an
/// emitter the ray hits needs (as in `path`).
#[derive(Clone, Copy, Debug)]
pub struct PreviousBounce {
    /// Where the ray left.
    pub p: Vec3A,
    /// Density of its direction per unit solid angle.
    pub pdf_w: f32,
    /// Whether it came from a delta lobe (MIS weight 1).
    pub is_delta: bool,
}

/// The state of all paths of a unit, one array per field.
#[derive(Debug, Default)]
pub struct PathQueue {
    /// The ray each path traces next.
    pub ray: Vec<Ray>,
    /// What the trace stage found along it (`None`: it escaped).
    pub hit: Vec<Option<Interaction>>,
    /// Throughput `β = Π f_r |cos θ| / p`.
    pub beta: Vec<Color>,
    /// Radiance gathered so far (the sample's value once the path ends).
    pub l: Vec<Color>,
    /// Relative IOR² crossed (roulette undoes the 1/η² of refraction).
    pub eta_scale: Vec<f32>,
    /// The BRDF sample that sent `ray` (`None`: the camera ray).
    pub prev: Vec<Option<PreviousBounce>>,
    /// Bounces made.
    pub depth: Vec<u32>,
    /// Each path's random numbers: `Sampler::new(seed, pixel, k)`.
    pub sampler: Vec<Sampler>,
    /// False once the path has ended (it leaves the live list at the next
    /// compaction, after its last shadow ray is resolved).
    pub alive: Vec<bool>,
    /// The slots still bouncing, increasing.
    pub live: Vec<u32>,
}

impl PathQueue {
    /// Empties the queue for `n` new paths, keeping the arrays' memory.
    pub fn reset(&mut self, samplers: impl Iterator<Item = Sampler>) {
        self.sampler.clear();
        self.sampler.extend(samplers);
        let n = self.sampler.len();
        fill(&mut self.ray, n, Ray::new(Vec3A::ZERO, Vec3A::Z));
        fill(&mut self.hit, n, None);
        fill(&mut self.beta, n, Color::ONE);
        fill(&mut self.l, n, Color::ZERO);
        fill(&mut self.eta_scale, n, 1.0);
        fill(&mut self.prev, n, None);
        fill(&mut self.depth, n, 0);
        fill(&mut self.alive, n, true);
        self.live.clear();
        self.live.extend(0..n as u32);
    }

    /// Number of paths (live or not).
    pub fn len(&self) -> usize {
        self.sampler.len()
    }

    /// Whether the queue holds no path.
    pub fn is_empty(&self) -> bool {
        self.sampler.is_empty()
    }

    /// Stream compaction: keeps the live slots whose path goes on, in order.
    pub fn compact(&mut self) {
        let alive = &self.alive;
        self.live.retain(|&s| alive[s as usize]);
    }
}

/// `v` becomes `n` copies of `x`, in the memory it already has.
fn fill<T: Clone>(v: &mut Vec<T>, n: usize, x: T) {
    v.clear();
    v.resize(n, x);
}

/// The shadow rays of one bounce, with what each brings if unblocked.
#[derive(Debug, Default)]
pub struct ShadowQueue {
    /// The path each belongs to.
    pub slot: Vec<u32>,
    pub ray: Vec<Ray>,
    /// `β · f_r L_e |cos θ| w / p`: added to the path's radiance if nothing
    /// blocks the ray.
    pub contribution: Vec<Color>,
}

impl ShadowQueue {
    pub fn clear(&mut self) {
        self.slot.clear();
        self.ray.clear();
        self.contribution.clear();
    }

    pub fn push(&mut self, slot: u32, ray: Ray, contribution: Color) {
        self.slot.push(slot);
        self.ray.push(ray);
        self.contribution.push(contribution);
    }

    pub fn len(&self) -> usize {
        self.slot.len()
    }

    pub fn is_empty(&self) -> bool {
        self.slot.is_empty()
    }
}
