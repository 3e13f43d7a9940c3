//! `--integrator mlt`: Metropolis light transport's options and its render
//! to files (the chains run over bidirectional path tracing; see
//! `raytracer::render::metropolis` for the algorithm and the choice).
//!
//! `--spp` counts mutations per pixel: the chains make `spp · W · H` steps
//! in all, after a bootstrap of `--bootstrap` independent paths. The options
//! are checked before anything is rendered, and name the flag that is wrong.

use std::path::Path;

use anyhow::{Result, anyhow, bail};
use clap::Args;
use raytracer::integrator::Integrator;
use raytracer::render::metropolis::{ParameterError, render_metropolis};
use raytracer::render::{Metropolis, RenderOptions};
use raytracer::scene::Scene;

use crate::page::Picture;
use crate::render_files::{OutputFiles, warn_if_unlit};

/// Options of Metropolis light transport (`--integrator mlt`).
#[derive(Args, Debug, Clone, Default)]
pub struct MetropolisArgs {
    /// Metropolis: independent Markov chains, each with an equal share of the mutations (default
    /// 64, or one per mutation if there are fewer). The image does not depend on --threads; the
    /// chains' spread is its variance EXR.
    #[arg(long, allow_negative_numbers = true)]
    pub chains: Option<i64>,
    /// Metropolis: independent paths of the bootstrap that estimates the brightness b and starts
    /// the chains (default: one per pixel).
    #[arg(long, allow_negative_numbers = true)]
    pub bootstrap: Option<i64>,
    /// Metropolis: probability of a large step, a fresh independent path, in [0, 1] (default 0.3).
    #[arg(long, allow_negative_numbers = true)]
    pub large_step_probability: Option<f32>,
    /// Metropolis: standard deviation of a small step in primary sample space, in (0, 1]
    /// (default 0.01).
    #[arg(long, allow_negative_numbers = true)]
    pub mutation_size: Option<f32>,
}

impl MetropolisArgs {
    /// The first Metropolis option given on the command line, as a flag.
    pub fn first_given(&self) -> Option<&'static str> {
        [
            (self.chains.is_some(), "--chains"),
            (self.bootstrap.is_some(), "--bootstrap"),
            (
                self.large_step_probability.is_some(),
                "--large-step-probability",
            ),
            (self.mutation_size.is_some(), "--mutation-size"),
        ]
        .into_iter()
        .find_map(|(given, flag)| given.then_some(flag))
    }

    /// The parameters, checked for `mutations` steps in all (one line
    /// naming the flag if one is out of range).
    pub fn metropolis(&self, mutations: u64) -> Result<Metropolis> {
        let count = |flag: &str, v: i64| -> Result<u32> {
            u32::try_from(v).map_err(|_| {
                if v < 1 {
                    anyhow!("{flag} must be at least 1, got {v}")
                } else {
                    anyhow!("{flag} must be at most {}, got {v}", u32::MAX)
                }
            })
        };
        let default = Metropolis::default();
        let metropolis = Metropolis {
            chains: match self.chains {
                Some(v) => count("--chains", v)?,
                // A tiny render has fewer mutations than 64.
                None => default
                    .chains
                    .min(mutations.clamp(1, u32::MAX as u64) as u32),
            },
            bootstrap: self
                .bootstrap
                .map(|v| count("--bootstrap", v))
                .transpose()?,
            large_step_probability: self
                .large_step_probability
                .unwrap_or(default.large_step_probability),
            mutation_size: self.mutation_size.unwrap_or(default.mutation_size),
        };
        metropolis.check(mutations).map_err(flag_error)?;
        Ok(metropolis)
    }
}

/// A core parameter error, with the flag that sets the field.
fn flag_error(e: ParameterError) -> anyhow::Error {
    anyhow!("--{} {}", e.field.replace('_', "-"), e.reason)
}

/// Renders `scene` by Metropolis light transport over `integrator` and
/// writes `dir/stem.png`, `.exr` and `-variance.exr` (the variance of each
/// pixel's mean from the spread of the independent chains), then prints one
/// line with the bootstrap's `b`. An interrupted render writes the chains
/// it ran, says so, and returns an error.
pub fn render_to_files(
    scene: &Scene,
    integrator: &dyn Integrator,
    options: &RenderOptions,
    metropolis: &Metropolis,
    dir: &Path,
    stem: &str,
    exposure: f32,
) -> Result<Picture> {
    let files = OutputFiles::new(dir, stem)?;
    warn_if_unlit(scene, integrator);
    let r = render_metropolis(scene, integrator, options, metropolis);
    if let Some(b) = &r.bootstrap {
        crate::console::say!(
            "  Metropolis: b = {:.5} ± {:.2} % from {} bootstrap paths, {} chains, acceptance {:.0} %",
            b.b,
            100.0 * b.relative_error(),
            b.paths,
            r.chains,
            100.0 * r.acceptance_rate
        );
    }
    // A lit scene whose bootstrap found no light would be all black: no
    // picture is better than a wrong one (`--bootstrap 1` on the door gave
    // "b = 0.0000" and a black image with exit 0).
    if let Some(b) = &r.bootstrap
        && b.b == 0.0
        && !scene.lights.is_empty()
        && !r.stats.interrupted
    {
        bail!(
            "Metropolis: none of the {} bootstrap paths found light, so its brightness b is 0 and \
             the picture would be black although the scene is lit: raise --bootstrap (nothing was written)",
            b.paths
        );
    }
    let mutations = options.spp as u64 * scene.camera.width as u64 * scene.camera.height as u64;
    files.write(&r.film, &r.stats, options.spp, exposure, || {
        format!(
            "INTERRUPTED after {} of {mutations} mutations ({} of {} chains merged, {:.2} s)",
            r.stats.samples,
            r.chains,
            metropolis.chains,
            r.stats.elapsed.as_secs_f64()
        )
    })
}

/// Refuses Metropolis options given to another integrator.
pub fn refuse_unused(args: &MetropolisArgs, integrator: &str) -> Result<()> {
    if let Some(flag) = args.first_given() {
        bail!(
            "{flag} does not apply to --integrator {integrator}: it is an option of --integrator mlt"
        );
    }
    Ok(())
}
