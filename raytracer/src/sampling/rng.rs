//! Counter-based random numbers: every number is a pure function of
//! (seed, pixel or path index, sample index, dimension).
//!
//! A sequential generator shared between threads would make the image depend
//! on the order in which threads ran. Here nothing is carried over from one
//! pixel sample to the next: [`Sampler::new`] hashes its address, and each call
//! to [`Sampler::next_1d`] hashes the next dimension into it. Rendering the same
//! pixel sample again, on any thread, yields the same numbers; the two eyes of
//! a stereo pair, given the same seed, see the same random numbers.
//!
//! The hash is the SplitMix64 finaliser (Steele, Lea and Flood, "Fast
//! Splittable Pseudorandom Number Generators", 2014), which passes BigCrush
//! when applied to a counter.
//!
//! **Primary samples.** Metropolis light transport (Kelemen et al. 2002)
//! runs an integrator on numbers it chooses itself: a point of *primary
//! sample space* that a Markov chain moves around. [`Sampler::primary`]
//! makes a sampler whose dimension `d` is coordinate `d` of such a point
//! ([`PrimarySample`]); the integrators draw from it exactly as from a
//! hashed sampler and need not know the difference. The hashed path pays one
//! well-predicted branch per number for it (measured: no change in samples
//! per second, see the commit).

use super::primary::{PrimarySample, Stream};
use crate::math::Vec2;

/// Random numbers for one pixel sample (or one light path).
#[derive(Clone, Debug)]
pub struct Sampler {
    key: u64,
    dimension: u32,
    /// `Some`: the numbers are the coordinates of a Metropolis chain's state.
    primary: Option<Box<PrimarySample>>,
}

#[inline]
pub fn mix64(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

const GOLDEN: u64 = 0x9e37_79b9_7f4a_7c15;

/// The key of the numbers of sample `sample` of `index` for `seed`.
#[inline]
pub fn key(seed: u64, index: u64, sample: u64) -> u64 {
    mix64(seed.wrapping_mul(GOLDEN) ^ mix64(index.wrapping_add(mix64(sample ^ GOLDEN))))
}

/// Number `dimension` of the sequence with `key`, uniform in `[0, 1)`.
#[inline]
pub fn uniform(key: u64, dimension: u32) -> f32 {
    let bits = mix64(key ^ (dimension as u64 + 1).wrapping_mul(GOLDEN));
    // The top 24 bits fill an f32 mantissa exactly: the result is < 1.
    (bits >> 40) as f32 * (1.0 / (1u64 << 24) as f32)
}

impl Sampler {
    /// The numbers of sample `sample` of pixel (or light path) `index`, for `seed`.
    #[inline]
    pub fn new(seed: u64, index: u64, sample: u64) -> Self {
        Sampler {
            key: key(seed, index, sample),
            dimension: 0,
            primary: None,
        }
    }

    /// A sampler whose dimension `d` is coordinate `d` of `state`, a point
    /// of primary sample space that a Metropolis chain moves (see
    /// [`PrimarySample`]).
    pub fn primary(state: PrimarySample) -> Self {
        Sampler {
            key: 0,
            dimension: 0,
            primary: Some(Box::new(state)),
        }
    }

    /// The primary sample this sampler reads, if it is one.
    pub fn primary_sample(&mut self) -> Option<&mut PrimarySample> {
        self.primary.as_deref_mut()
    }

    /// The dimension the next number will come from.
    #[inline]
    pub fn dimension(&self) -> u32 {
        self.dimension
    }

    /// Jumps to a given dimension, so that a part of an integrator can use a
    /// fixed address for its numbers (e.g. a fixed stride per bounce). On a
    /// primary sample with streams: to number `dimension` of the camera
    /// stream, every other stream back at its start.
    #[inline]
    pub fn set_dimension(&mut self, dimension: u32) {
        self.dimension = dimension;
        if let Some(state) = &mut self.primary {
            state.restart(dimension);
        }
    }

    /// The next numbers belong to `stream`: on a primary sample with
    /// streams they continue that stream (see [`Stream`]), so that a small
    /// step moves each stream's numbers a little whatever the others used.
    /// A hashed sampler has one sequence for all streams: the numbers go on
    /// in drawing order, and its images do not change.
    #[inline]
    pub fn start_stream(&mut self, stream: Stream) {
        if let Some(state) = &mut self.primary {
            state.start_stream(stream);
        }
    }

    /// A uniform number in `[0, 1)`.
    #[inline]
    pub fn next_1d(&mut self) -> f32 {
        let d = self.dimension;
        self.dimension += 1;
        match &mut self.primary {
            None => uniform(self.key, d),
            Some(state) => state.next(d),
        }
    }

    /// Two uniform numbers in `[0, 1)²`.
    #[inline]
    pub fn next_2d(&mut self) -> Vec2 {
        let x = self.next_1d();
        Vec2::new(x, self.next_1d())
    }
}
