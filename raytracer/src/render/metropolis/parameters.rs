//! The parameters of Metropolis light transport and their ranges: how many
//! chains, how many bootstrap paths, how often a large step, how big a small
//! one.
//!
//! Lecture topic: Metropolis light transport. Every front-end checks them
//! with [`Metropolis::check`] before rendering; the error names the field so
//! that a command line can name its flag.

/// The parameters of Metropolis light transport (the samples per pixel of
/// [`RenderOptions::spp`](crate::render::RenderOptions::spp) count *mutations* per pixel: the chains make
/// `spp · W · H` steps in all).
#[derive(Clone, Debug, PartialEq)]
pub struct Metropolis {
    /// Independent chains; each makes an equal share of the steps.
    pub chains: u32,
    /// Paths of the bootstrap; `None`: one per pixel, `W · H`.
    pub bootstrap: Option<u32>,
    /// Probability of a large step (a fresh, independent path).
    pub large_step_probability: f32,
    /// Standard deviation of a small step, a fraction of `[0, 1)`.
    pub mutation_size: f32,
}

impl Default for Metropolis {
    /// 64 chains, one bootstrap path per pixel, and pbrt-v4's defaults for
    /// the steps: large with probability 0.3, small of deviation 0.01.
    fn default() -> Self {
        Metropolis {
            chains: 64,
            bootstrap: None,
            large_step_probability: 0.3,
            mutation_size: 0.01,
        }
    }
}

impl Metropolis {
    /// The bootstrap's number of paths for a `width × height` image.
    pub fn bootstrap_paths(&self, width: u32, height: u32) -> u64 {
        self.bootstrap
            .map_or(width as u64 * height as u64, u64::from)
    }

    /// Bytes a render of `width × height` on `threads` threads needs beside
    /// the film's ([`crate::render::memory_needed`]), at its peak (`None` if
    /// the number does not fit in 64 bits): each chain in flight keeps an
    /// `f64` sum per channel and pixel (24 bytes), and fewer than
    /// `3·threads + 1` are in flight (one per worker, and the chains that
    /// finished early and wait, at most `2·threads`, to be merged in chain
    /// order); each bootstrap path keeps its `f` and its share of the
    /// distribution that picks the chains' starts (16 bytes at the peak).
    pub fn memory_needed(&self, width: u32, height: u32, threads: usize) -> Option<u64> {
        let pixels = (width as u64).checked_mul(height as u64)?;
        let runs = (threads as u64).checked_mul(3)?.checked_add(1)?;
        let chains = pixels.checked_mul(24)?.checked_mul(runs)?;
        let paths = self.bootstrap_paths(width, height).checked_mul(16)?;
        chains.checked_add(paths)
    }

    /// Checks the parameters for `mutations` steps in all.
    pub fn check(&self, mutations: u64) -> Result<(), ParameterError> {
        let wrong = |field, reason: String| Err(ParameterError { field, reason });
        let p = self.large_step_probability;
        if !(0.0..=1.0).contains(&p) {
            return wrong(
                "large_step_probability",
                format!("must be in [0, 1] (0: small steps only, 1: independent paths), got {p}"),
            );
        }
        let s = self.mutation_size;
        if !(s > 0.0 && s <= 1.0) {
            return wrong(
                "mutation_size",
                format!(
                    "must be in (0, 1] (the deviation of a small step, a fraction of the unit interval; 0.01 is usual), got {s}"
                ),
            );
        }
        if self.chains == 0 {
            return wrong("chains", "must be at least 1, got 0".into());
        }
        if self.chains as u64 > mutations {
            return wrong(
                "chains",
                format!(
                    "is {} but there are only {mutations} mutations in all (mutations per pixel × pixels), and every chain needs one: use fewer chains or more mutations per pixel",
                    self.chains
                ),
            );
        }
        if self.bootstrap == Some(0) {
            return wrong(
                "bootstrap",
                "must be at least 1 path (the bootstrap estimates the brightness b), got 0".into(),
            );
        }
        Ok(())
    }
}

/// A parameter of [`Metropolis`] out of its range.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ParameterError {
    /// The field of [`Metropolis`], e.g. `large_step_probability`.
    pub field: &'static str,
    /// What it must be and what it is, e.g. `must be in [0, 1] (…), got 1.5`.
    pub reason: String,
}

impl std::fmt::Display for ParameterError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Metropolis `{}` {}", self.field, self.reason)
    }
}

impl std::error::Error for ParameterError {}
