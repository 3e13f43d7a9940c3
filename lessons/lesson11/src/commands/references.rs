//! `lesson11 references`: the instructor regenerates the stored references,
//! the grader's and the lesson's own.

use anyhow::{Result, anyhow};
use clap::Args;
use grading::compare::{COMPARISONS, REFERENCE_SPP};

use crate::reference::{caustic_settings, door_settings};

/// Regenerate every stored reference at many samples per pixel (mean and variance EXR):
/// the ones the grader compares students' images against (tests/references/), the
/// door scene's for the equal-time comparison of `lesson11 compare` and the caustic
/// scene's for `lesson11 biased` (lessons/lesson11/references/; a few minutes). Tables are insta snapshots: review their
/// changes with `cargo insta review`.
#[derive(Args, Debug)]
pub struct ReferencesArgs {
    /// Only the grader's references (seconds), not the door and caustic scenes' (minutes).
    #[arg(long)]
    pub grader_only: bool,
}

pub fn run(args: &ReferencesArgs) -> Result<()> {
    for c in COMPARISONS {
        crate::console::say!(
            "{}: {} with the renderer's own integrator, {REFERENCE_SPP} spp",
            c.name,
            c.scene
        );
        let path = grading::compare::render_reference(c, true).map_err(|e| anyhow!(e))?;
        crate::console::say!("  wrote {} and its -variance.exr", path.display());
    }
    crate::console::say!(
        "ex17_caustic: caustic with the renderer's photon mapping, {} independent photon maps",
        grading::ex17_photon_mapping::REFERENCE_MAPS
    );
    let path = grading::ex17_photon_mapping::render_reference(true).map_err(|e| anyhow!(e))?;
    crate::console::say!(
        "  wrote {} and its -variance.exr (per tile)",
        path.display()
    );
    if !args.grader_only {
        for stored in [door_settings(), caustic_settings()] {
            crate::console::say!(
                "{}: bidirectional path tracing, {}×{}, max depth {}, {} spp, seed {}",
                stored.scene,
                stored.width,
                stored.height,
                stored.max_depth,
                stored.spp,
                stored.seed
            );
            let path = stored.render_and_store()?;
            crate::console::say!(
                "  wrote {}, its -variance.exr and its settings",
                path.display()
            );
        }
    }
    crate::console::say!(
        "Now run `cargo test -p grading --features solutions` and `cargo test -p lesson11`, and \
         commit tests/references/ and lessons/lesson11/references/."
    );
    Ok(())
}
