//! `lesson11 references`: the instructor regenerates the grader's references.

use anyhow::{Result, anyhow};
use clap::Args;
use grading::compare::{COMPARISONS, REFERENCE_SPP};

/// Regenerate every reference the grader compares students' images against
/// (mean and variance EXR in tests/references/), at many samples per pixel.
/// Tables are insta snapshots: review their changes with `cargo insta review`.
#[derive(Args, Debug)]
pub struct ReferencesArgs {}

pub fn run(_: &ReferencesArgs) -> Result<()> {
    for c in COMPARISONS {
        println!(
            "{}: {} with the renderer's own integrator, {REFERENCE_SPP} spp",
            c.name, c.scene
        );
        let path = grading::compare::render_reference(c, true).map_err(|e| anyhow!(e))?;
        println!("  wrote {} and its -variance.exr", path.display());
    }
    println!("Now run `cargo test -p grading --features solutions` and commit tests/references/.");
    Ok(())
}
