//! Primary sample space: the random numbers of one sample, as a point that a
//! Markov chain moves (Kelemen, Szirmay-Kalos, Antal and Csonka, "A Simple
//! and Robust Mutation Strategy for the Metropolis Light Transport
//! Algorithm", 2002).
//!
//! Lecture topic: Metropolis light transport, the last unbiased algorithm
//! the lecture names. An integrator turns the numbers `u = (u_0, u_1, …)` it
//! draws into a path and the path into a contribution `f(u)`; so a path *is*
//! a point `u` of the unit hypercube, and to move from one path to a similar
//! one it is enough to move `u` a little. A [`PrimarySample`] is such a point
//! with the two moves of Kelemen et al.:
//!
//! - a **large step**: every coordinate drawn afresh (an independent path,
//!   as the integrator alone would make);
//! - a **small step**: every coordinate moved by a normal perturbation of
//!   standard deviation `σ`, wrapped around `[0, 1)` (a torus, so the move is
//!   symmetric: `T(x → y) = T(y → x)`).
//!
//! The chain proposes a step, the integrator evaluates the proposal, and the
//! chain [`accept`](PrimarySample::accept)s it or
//! [`reject`](PrimarySample::reject)s it (which restores the old point).
//!
//! **Lazily.** An integrator draws a different number of coordinates for
//! each path (a longer path, more numbers), so coordinates are made and
//! moved only when they are read, as in pbrt-v3/v4's `MLTSampler`: a
//! coordinate remembers the iteration it was last moved at; read at
//! iteration `t` after `n = t − t_last` small steps it did not take part in,
//! it takes their sum at once, one normal step of deviation `σ√n` (the sum of
//! `n` independent normal steps). A coordinate that has not been read since
//! the state's last large step takes that step's fresh number first.
//!
//! **Streams.** An integrator may split its numbers into
//! [`Stream`]s: bidirectional path tracing draws its camera subpath, its
//! light subpath and its connections each from a stream of its own
//! ([`super::Sampler::start_stream`]), and number `k` of stream `s` is
//! coordinate `s + 3k` (pbrt-v4's `MLTSampler` interleaves its three
//! streams the same way). So the light subpath reads the same coordinates
//! whatever the camera subpath read: without streams, a small step that
//! makes the camera subpath one bounce longer (or shorter) would hand the
//! light subpath the coordinates that followed the camera's, all of them
//! other numbers than before, and redraw it whole (measured on `cornell`
//! over BDPT at unlimited depth: 22.6 % of small steps). A point made
//! [`from_coordinates`](PrimarySample::from_coordinates) has no streams:
//! its coordinates are read in the order drawn.
//!
//! **Addresses.** Every number comes from the counter-based hash of
//! [`super::rng`]: the starting point is the sequence of
//! `Sampler::new(seed, index, sample)` (so a chain can start exactly at a
//! path of the bootstrap), and each step's numbers come from the address the
//! chain gives it (its seed, its index, the iteration). A chain is then a
//! pure function of its addresses, whichever thread runs it.

use super::rng::{key, uniform};
use crate::math::PI;

/// The streams of primary sample space: which part of a sample a number
/// belongs to (see the module doc). An integrator that names none draws
/// from [`Stream::Camera`], where the pixel of a Metropolis sample lies.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stream {
    /// The pixel and the camera subpath (all numbers of a path tracer).
    Camera = 0,
    /// The light subpath.
    Light = 1,
    /// The connections of the two subpaths (bidirectional strategies).
    Connection = 2,
}

/// The number of [`Stream`]s: number `k` of stream `s` is coordinate
/// `s + STREAMS · k`.
const STREAMS: u32 = 3;

/// The largest `f32` below 1 (coordinates stay in `[0, 1)`).
pub const ONE_MINUS_EPSILON: f32 = 1.0 - f32::EPSILON / 2.0;

/// One coordinate: its value, the iteration it was last moved at, and the
/// two as they were before the current proposal moved them.
#[derive(Clone, Copy, Debug)]
struct Coordinate {
    value: f32,
    moved: u64,
    backup_value: f32,
    backup_moved: u64,
}

/// A point of primary sample space moved by large and small steps.
#[derive(Clone, Debug)]
pub struct PrimarySample {
    coordinates: Vec<Coordinate>,
    /// The steps the state took, plus one while a proposal is open (0: the
    /// starting point).
    iteration: u64,
    /// Whether proposal `t` is a large step.
    large_step: bool,
    /// The iteration of the current state's last large step (0: the start)
    /// and the key of that step's fresh numbers.
    last_large_step: u64,
    state_key: u64,
    /// The keys of the current proposal's fresh numbers (large step) and of
    /// its perturbations (small step).
    proposal_key: u64,
    /// Standard deviation of a small step, a fraction of the unit interval.
    sigma: f32,
    /// `Some`: the stream being read and the next number of each stream;
    /// `None`: no streams, coordinates in the order drawn.
    streams: Option<(Stream, [u32; STREAMS as usize])>,
}

impl PrimarySample {
    /// The point whose coordinate `d` is number `d` of
    /// `Sampler::new(seed, index, sample)`, read in [`Stream`]s. An
    /// integrator that names no stream reads coordinates `0, 3, 6, …` (the
    /// camera stream); the bootstrap of Metropolis light transport
    /// evaluates its paths on such points, so that a chain starts on
    /// exactly the path it chose. `sigma` is the standard deviation of a
    /// small step.
    pub fn new(seed: u64, index: u64, sample: u64, sigma: f32) -> Self {
        PrimarySample {
            coordinates: Vec::new(),
            iteration: 0,
            large_step: false,
            last_large_step: 0,
            state_key: key(seed, index, sample),
            proposal_key: 0,
            sigma,
            streams: Some((Stream::Camera, [0; STREAMS as usize])),
        }
    }

    /// The point whose first coordinates are `values` (each in `[0, 1)`)
    /// and whose later ones are those of `Sampler::new(seed, index, sample)`:
    /// a fixed vector of numbers for an integrator to read through
    /// [`Sampler::primary`](super::Sampler::primary), in the order it draws
    /// them, without streams (exercise 16's chains keep their states as
    /// such vectors and move them themselves).
    pub fn from_coordinates(values: &[f32], seed: u64, index: u64, sample: u64) -> Self {
        let mut point = PrimarySample::new(seed, index, sample, 0.0);
        point.streams = None;
        point.coordinates = values
            .iter()
            .map(|&value| Coordinate {
                value,
                moved: 0,
                backup_value: value,
                backup_moved: 0,
            })
            .collect();
        point
    }

    /// The number of steps the state has taken (accepted proposals), plus
    /// one while a proposal is open.
    pub fn iteration(&self) -> u64 {
        self.iteration
    }

    /// Starts the next proposal as a large step: coordinate `d` becomes
    /// number `d` of `Sampler::new(seed, index, sample)` when it is read.
    pub fn propose_large(&mut self, seed: u64, index: u64, sample: u64) {
        self.propose(true, key(seed, index, sample));
    }

    /// Starts the next proposal as a small step: coordinate `d` moves by
    /// `σ√n · N(0, 1)` when it is read, the normal number made from numbers
    /// `2d` and `2d + 1` of `Sampler::new(seed, index, sample)`.
    pub fn propose_small(&mut self, seed: u64, index: u64, sample: u64) {
        self.propose(false, key(seed, index, sample));
    }

    fn propose(&mut self, large: bool, proposal_key: u64) {
        self.iteration += 1;
        self.large_step = large;
        self.proposal_key = proposal_key;
    }

    /// Keeps the proposal: it becomes the state.
    pub fn accept(&mut self) {
        if self.large_step {
            self.last_large_step = self.iteration;
            self.state_key = self.proposal_key;
        }
    }

    /// Drops the proposal: every coordinate it moved takes back its value,
    /// and the iteration count goes back with them (as in pbrt), so that
    /// `t − t_last` counts only the steps the state really took.
    pub fn reject(&mut self) {
        for c in &mut self.coordinates {
            if c.moved == self.iteration {
                c.value = c.backup_value;
                c.moved = c.backup_moved;
            }
        }
        debug_assert!(self.iteration > 0, "reject without a proposal");
        self.iteration = self.iteration.saturating_sub(1);
    }

    /// Reads the next numbers from `stream` (where that stream left off);
    /// nothing changes for a point without streams.
    pub(crate) fn start_stream(&mut self, stream: Stream) {
        if let Some((current, _)) = &mut self.streams {
            *current = stream;
        }
    }

    /// Starts every stream again at its first number and reads the camera
    /// stream from its number `k` (a point without streams: the drawing
    /// order from `k`).
    pub(crate) fn restart(&mut self, k: u32) {
        if let Some((current, next)) = &mut self.streams {
            *current = Stream::Camera;
            *next = [k, 0, 0];
        }
    }

    /// The next number of the current stream; `d`, the number of numbers
    /// drawn before it, is the coordinate of a point without streams.
    #[inline]
    pub(crate) fn next(&mut self, d: u32) -> f32 {
        match &mut self.streams {
            None => self.coordinate(d),
            Some((stream, next)) => {
                let s = *stream as u32;
                let k = next[s as usize];
                next[s as usize] += 1;
                self.coordinate(s + STREAMS * k)
            }
        }
    }

    /// Coordinate `d` of the current proposal (of the state before the
    /// first proposal), made and moved as the module doc says.
    #[inline(never)]
    pub fn coordinate(&mut self, d: u32) -> f32 {
        let i = d as usize;
        while self.coordinates.len() <= i {
            let k = self.coordinates.len() as u32;
            let value = uniform(self.state_key, k);
            self.coordinates.push(Coordinate {
                value,
                moved: self.last_large_step,
                backup_value: value,
                backup_moved: self.last_large_step,
            });
        }
        let c = &mut self.coordinates[i];
        // Not read since the state's last large step: take its number.
        if c.moved < self.last_large_step {
            c.value = uniform(self.state_key, d);
            c.moved = self.last_large_step;
        }
        if c.moved < self.iteration {
            c.backup_value = c.value;
            c.backup_moved = c.moved;
            c.value = if self.large_step {
                uniform(self.proposal_key, d)
            } else {
                // The n small steps since it last moved, as one.
                let n = (self.iteration - c.moved) as f32;
                let normal = standard_normal(
                    uniform(self.proposal_key, 2 * d),
                    uniform(self.proposal_key, 2 * d + 1),
                );
                wrap(c.value + self.sigma * n.sqrt() * normal)
            };
            c.moved = self.iteration;
        }
        c.value
    }
}

/// A standard normal number from two uniform ones (Box–Muller).
#[inline]
fn standard_normal(u1: f32, u2: f32) -> f32 {
    // 1 − u1 lies in (0, 1]: no logarithm of 0.
    (-2.0 * (1.0 - u1).ln()).sqrt() * (2.0 * PI * u2).cos()
}

/// `x` wrapped around the unit interval, into `[0, 1)`.
#[inline]
pub fn wrap(x: f32) -> f32 {
    let w = x - x.floor();
    // x a tiny negative number: 1 − tiny rounds to 1.
    if w < 1.0 { w } else { ONE_MINUS_EPSILON }
}
