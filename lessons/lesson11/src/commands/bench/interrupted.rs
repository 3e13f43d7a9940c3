//! How `lesson11 bench` ends when Ctrl-C stops it: every part asks here, so
//! that a figure cut short is never printed.

use anyhow::{Result, bail};
use raytracer::render::interrupted;

/// The error of an interrupted benchmark, once `cut_short` (a measurement
/// that Ctrl-C ended early) or the interrupt flag says so: nothing after
/// it is measured, and its figure is not printed.
pub fn stop_if_interrupted(cut_short: bool) -> Result<()> {
    if cut_short || interrupted() {
        bail!("interrupted: the figures above are all that was measured");
    }
    Ok(())
}
