//! Named random-number dimensions: a step of an algorithm draws its numbers
//! through a [`Draw`] that says what they are for.
//!
//! A [`Sampler`] hands out dimension after dimension of one pixel sample's
//! random numbers, so the `k`-th number an integrator draws is always
//! dimension `k`. One draw more (or less) anywhere shifts every later
//! dimension and changes every picture, and every reference image with it.
//! Drawing through named constants makes the layout readable (Blender Cycles
//! names its dimensions the same way: filter, lens, light, BSDF, terminate)
//! and an extra draw visible: it needs a name of its own.

use super::Sampler;
use crate::math::Vec2;

/// `N` consecutive random numbers with a name (what they choose).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Draw<const N: usize> {
    pub name: &'static str,
}

impl<const N: usize> Draw<N> {
    pub const fn new(name: &'static str) -> Self {
        Draw { name }
    }

    /// The number of dimensions the draw uses.
    pub const fn dimensions(&self) -> u32 {
        N as u32
    }
}

impl Draw<1> {
    /// The next number of `sampler`.
    #[inline(always)]
    pub fn draw(&self, sampler: &mut Sampler) -> f32 {
        sampler.next_1d()
    }
}

impl Draw<2> {
    /// The next two numbers of `sampler`, in that order (`x` first).
    #[inline(always)]
    pub fn draw(&self, sampler: &mut Sampler) -> Vec2 {
        sampler.next_2d()
    }
}
