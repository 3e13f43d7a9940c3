//! Merging the chains of Metropolis light transport into one film, in chain
//! order whichever thread finished first, so that the image is the same bit
//! for bit on any number of threads.
//!
//! Lecture topic: Metropolis light transport. Each chain's image is one
//! sample of every pixel (scaled by `W·H · b̂ / N`), so the film's mean is
//! the render and its variance image the spread of the independent chains.

use super::chain::ChainRun;
use crate::film::Film;
use crate::math::{Color, UVec2};
use std::collections::VecDeque;

/// Merges finished chains into the film in chain order.
pub struct Merger {
    pub(super) film: Film,
    tile: u32,
    b: f64,
    /// The next chain to merge, and finished chains `next, next+1, …`.
    pub(super) next: u64,
    pending: VecDeque<Option<ChainRun>>,
    pub(super) spare: Vec<ChainRun>,
    pub(super) chains: u32,
    pub(super) steps: u64,
    pub(super) accepted: u64,
    pub(super) nonfinite: u64,
    pub(super) tile_means: Vec<Vec<Color>>,
}

impl Merger {
    pub(super) fn new(width: u32, height: u32, tile: u32, b: f64) -> Self {
        Merger {
            film: Film::new(width, height),
            tile,
            b,
            next: 0,
            pending: VecDeque::new(),
            spare: Vec::new(),
            chains: 0,
            steps: 0,
            accepted: 0,
            nonfinite: 0,
            tile_means: Vec::new(),
        }
    }

    /// Takes finished chain `c`, merges every chain now next in line (calling
    /// `merged` after each one, in chain order), and hands back a run to reuse.
    pub(super) fn submit(
        &mut self,
        c: u64,
        run: ChainRun,
        mut merged: impl FnMut(&Merger),
    ) -> ChainRun {
        let slot = (c - self.next) as usize;
        if self.pending.len() <= slot {
            self.pending.resize_with(slot + 1, || None);
        }
        self.pending[slot] = Some(run);
        while let Some(Some(_)) = self.pending.front() {
            let run = self.pending.pop_front().flatten().expect("checked above");
            self.merge(&run);
            self.spare.push(run);
            self.next += 1;
            merged(self);
        }
        self.spare.pop().unwrap_or_default()
    }

    /// Adds a chain's estimate `W·H · b̂ / N · Σ` as one sample of every pixel.
    fn merge(&mut self, run: &ChainRun) {
        self.steps += run.steps;
        self.accepted += run.accepted;
        self.nonfinite += run.nonfinite;
        if run.steps == 0 {
            return;
        }
        let (w, h) = (self.film.width(), self.film.height());
        let scale = w as f64 * h as f64 * self.b / run.steps as f64;
        let tiles_x = w.div_ceil(self.tile);
        let tiles = tiles_x as usize * h.div_ceil(self.tile) as usize;
        let mut sums = vec![([0.0f64; 3], 0u32); tiles];
        for y in 0..h {
            for x in 0..w {
                let s = run.sums[(y * w + x) as usize];
                let v = [s[0] * scale, s[1] * scale, s[2] * scale];
                let value = Color::new(v[0] as f32, v[1] as f32, v[2] as f32);
                self.film.add_sample(UVec2::new(x, y), value);
                let t = &mut sums[((y / self.tile) * tiles_x + x / self.tile) as usize];
                for (acc, c) in t.0.iter_mut().zip(value.to_array()) {
                    *acc += c as f64;
                }
                t.1 += 1;
            }
        }
        self.tile_means.push(
            sums.iter()
                .map(|(s, n)| {
                    let n = *n as f64;
                    Color::new((s[0] / n) as f32, (s[1] / n) as f32, (s[2] / n) as f32)
                })
                .collect(),
        );
        self.chains += 1;
    }
}
