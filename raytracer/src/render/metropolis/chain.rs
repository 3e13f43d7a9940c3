//! One Markov chain of Metropolis light transport: propose, evaluate,
//! splat both states by their expected values, accept or reject.
//!
//! Lecture topic: Metropolis light transport. The chain's state is a point
//! `x` of primary sample space ([`PrimarySample`]); the integrator turns it
//! into a path and the path into its contributions `g_j(x)` to the pixels
//! `j` and its scalar contribution `f(x) = Σ_j Y(g_j(x))`, the luminance of
//! all it brings. Each step:
//!
//! 1. propose `y`: a large step with probability `p_large`, else a small one;
//! 2. evaluate `f(y)` (one sample of the integrator, on `y`'s numbers);
//! 3. the Metropolis acceptance probability for a symmetric proposal
//!    ([`acceptance`], the slide's `a`);
//! 4. splat *both* states, each with its probability of being the next
//!    state ([`expected_value_splat`]): the expected value of what the
//!    next state would splat, `g/f` of whichever is kept; no random number
//!    is wasted on it, and rejected proposals still count (Veach's
//!    "expected values" optimisation, pbrt's `MLTIntegrator`);
//! 5. keep `y` with probability `a`, else restore `x`.
//!
//! After `N` steps the chain's estimate of pixel `j` is
//! `I_j ≈ W·H · b / N · Σ (splatted weight · g_j)`, with `b = E[f]` from the
//! bootstrap (see the module doc of [`super`] for why that is unbiased).

use crate::film::{Splat, is_valid_radiance, pixel_of_raster};
use crate::integrator::{Integrator, stop};
use crate::math::{Color, UVec2, luminance};
use crate::sampling::{Draw, PrimarySample, Sampler};
use crate::scene::Scene;

/// The pixel a Metropolis sample lands in: the first two numbers of every
/// state's camera stream, before the integrator's own draws (its `FILM`
/// then places the sample within that pixel). Uniform pixel times uniform position is
/// uniform over the image, so the map keeps the measure.
pub const PIXEL: Draw<2> = Draw::new("pixel of a Metropolis sample");
/// Whether a step is large (below `p_large`) or small.
pub const STEP_KIND: Draw<1> = Draw::new("large or small step");
/// Whether the proposal is accepted (below `a`).
pub const ACCEPT: Draw<1> = Draw::new("accept the proposal");

/// The factors that multiply the contributions of the two states of one
/// step before the chain's common factor `W·H · b / N`: each state's
/// probability of being the next one, over its own `f`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SplatWeights {
    /// Weight of the current state's contributions (it stays with the
    /// probability that the proposal is rejected).
    pub current: f32,
    /// Weight of the proposal's contributions (taken with the acceptance
    /// probability).
    pub proposed: f32,
}

/// The Metropolis acceptance probability of a symmetric proposal from a
/// state of luminance `f_current` to one of `f_proposed` (the slide's `a`);
/// 1 when `f(x) = 0` (a chain that starts on a path that brings nothing
/// leaves it at once).
#[inline]
pub fn acceptance(f_current: f32, f_proposed: f32) -> f32 {
    if f_current > 0.0 {
        (f_proposed / f_current).min(1.0)
    } else {
        1.0
    }
}

/// The expected-value splat of one step: each state's weight is its
/// probability of being the next state over its `f` (0 for a state with
/// `f = 0`, which brings nothing). The two weights times `f` add up to 1:
/// every step splats one unit of luminance, shared by the two states as the
/// coin would share it on average.
#[inline]
pub fn expected_value_splat(f_current: f32, f_proposed: f32) -> SplatWeights {
    let a = acceptance(f_current, f_proposed);
    let over = |w: f32, f: f32| if f > 0.0 { w / f } else { 0.0 };
    SplatWeights {
        current: over(1.0 - a, f_current),
        proposed: over(a, f_proposed),
    }
}

/// What one path brings: its contributions to pixels (the sample's own
/// pixel and the splats of light tracing and BDPT's `t = 1`), and `f`, the
/// sum of their luminances.
#[derive(Clone, Debug, Default)]
pub struct PathSample {
    /// `(pixel index y·W + x, radiance)`, zero contributions left out.
    pub contributions: Vec<(u32, Color)>,
    /// `f = Σ Y(value)`, the target function of the chain.
    pub f: f32,
    /// Contributions dropped as NaN, infinite or negative (counted as zero).
    pub nonfinite: u64,
}

impl PathSample {
    fn clear(&mut self) {
        self.contributions.clear();
        self.f = 0.0;
    }

    fn add(&mut self, index: u32, value: Color) {
        if !is_valid_radiance(value) {
            self.nonfinite += 1;
        } else if value != Color::ZERO {
            self.f += luminance(value);
            self.contributions.push((index, value));
        }
    }
}

/// Evaluates the path of `sampler`'s numbers from the start of every
/// stream: the pixel ([`PIXEL`]), then one sample of `integrator`. `splats` is scratch space.
/// Returns false if the integrator abandoned the sample (a stop request).
pub fn evaluate(
    scene: &Scene,
    integrator: &dyn Integrator,
    sampler: &mut Sampler,
    splats: &mut Vec<Splat>,
    out: &mut PathSample,
) -> bool {
    let (w, h) = (scene.camera.width, scene.camera.height);
    sampler.set_dimension(0);
    let u = PIXEL.draw(sampler);
    let pixel = UVec2::new(
        ((u.x * w as f32) as u32).min(w - 1),
        ((u.y * h as f32) as u32).min(h - 1),
    );
    splats.clear();
    let value = integrator.sample(scene, pixel, sampler, splats);
    out.clear();
    if stop::take_abandoned() {
        return false;
    }
    out.add(pixel.y * w + pixel.x, value);
    for s in splats.iter() {
        match pixel_of_raster(s.raster, w, h) {
            Some(p) => out.add(p.y * w + p.x, s.value),
            // An invalid splat is counted even if it lands nowhere.
            None if !is_valid_radiance(s.value) => out.nonfinite += 1,
            None => {}
        }
    }
    true
}

/// Where a chain's random numbers come from: the seeds of its streams (all
/// derived from the render's seed) and its index.
#[derive(Clone, Copy, Debug)]
pub struct ChainStreams {
    /// `(seed, index)` of the bootstrap path the chain starts from.
    pub start: (u64, u64),
    pub index: u64,
    /// Large/small choice and acceptance, per step.
    pub control: u64,
    /// Fresh numbers of large steps.
    pub large: u64,
    /// Perturbations of small steps.
    pub small: u64,
}

/// How a chain moves.
#[derive(Clone, Copy, Debug)]
pub struct Moves {
    pub large_step_probability: f32,
    pub mutation_size: f32,
}

/// What a chain did.
#[derive(Clone, Debug, Default)]
pub struct ChainRun {
    /// `Σ weight · g` per pixel (`W·H` entries), before the factor `W·H·b/N`.
    pub sums: Vec<[f64; 3]>,
    /// Steps taken (`N`).
    pub steps: u64,
    pub accepted: u64,
    pub nonfinite: u64,
}

/// Runs one chain of `steps` steps into `run` (its `sums` reset to zeros).
/// `keep_going()` is asked before every step; the chain stops early,
/// keeping the steps made, when it says no or the integrator abandons a
/// sample.
pub fn run_chain(
    scene: &Scene,
    integrator: &dyn Integrator,
    streams: ChainStreams,
    moves: Moves,
    steps: u64,
    keep_going: &mut dyn FnMut() -> bool,
    run: &mut ChainRun,
) {
    let pixels = scene.camera.width as usize * scene.camera.height as usize;
    run.sums.clear();
    run.sums.resize(pixels, [0.0; 3]);
    (run.steps, run.accepted, run.nonfinite) = (0, 0, 0);
    let (seed, index) = streams.start;
    let state = PrimarySample::new(seed, index, 0, moves.mutation_size);
    let mut sampler = Sampler::primary(state);
    let mut splats = Vec::new();
    let (mut current, mut proposed) = (PathSample::default(), PathSample::default());
    if !evaluate(scene, integrator, &mut sampler, &mut splats, &mut current) {
        return;
    }
    for t in 1..=steps {
        if !keep_going() {
            break;
        }
        let mut control = Sampler::new(streams.control, streams.index, t);
        let large = STEP_KIND.draw(&mut control) < moves.large_step_probability;
        let state = sampler.primary_sample().expect("a primary sampler");
        if large {
            state.propose_large(streams.large, streams.index, t);
        } else {
            state.propose_small(streams.small, streams.index, t);
        }
        if !evaluate(scene, integrator, &mut sampler, &mut splats, &mut proposed) {
            break;
        }
        let w = expected_value_splat(current.f, proposed.f);
        splat(&mut run.sums, &current, w.current);
        splat(&mut run.sums, &proposed, w.proposed);
        let state = sampler.primary_sample().expect("a primary sampler");
        if ACCEPT.draw(&mut control) < acceptance(current.f, proposed.f) {
            state.accept();
            std::mem::swap(&mut current, &mut proposed);
            run.accepted += 1;
        } else {
            state.reject();
        }
        run.steps += 1;
    }
    run.nonfinite = current.nonfinite + proposed.nonfinite;
}

/// Adds `weight · g_j` of `path` to the sums.
#[inline]
fn splat(sums: &mut [[f64; 3]], path: &PathSample, weight: f32) {
    if weight == 0.0 {
        return;
    }
    for &(j, value) in &path.contributions {
        let s = &mut sums[j as usize];
        for (s, v) in s.iter_mut().zip(value.to_array()) {
            *s += weight as f64 * v as f64;
        }
    }
}
