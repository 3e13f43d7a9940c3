//! The path inspector's data: the paths that the current integrator traced
//! for one sample of one pixel, as the page draws them over the picture and
//! lists them in a table.
//!
//! DESIGN.md's contract "Paths can be recorded": the integrator runs the
//! sample again with the path recorder of `raytracer`
//! ([`raytracer::integrator::record`]), with the render's random numbers for
//! that pixel and sample, so the record is of the very sample the picture
//! averaged; the slides' path figures come from the same recorder. The
//! record is the lab's wire format as it is (serialized to JSON), with every
//! vertex and sampled point projected into the picture.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc;
use std::time::Duration;

use raytracer::integrator::Integrator;
use raytracer::integrator::record::{PathRecord, record_sample};
use raytracer::integrator::stop;
use raytracer::math::UVec2;
use raytracer::scene::Scene;

/// The longest the inspector computes one sample (naive recursion can trace
/// N^D rays for it).
pub const LONGEST_SAMPLE: Duration = Duration::from_secs(10);

/// The record of pixel `pixel`'s sample `k` of a render with seed `seed`,
/// projected into the camera's picture; `Err` with a one-line reason if the
/// sample takes longer than [`LONGEST_SAMPLE`].
pub fn record(
    integrator: &dyn Integrator,
    scene: &Scene,
    pixel: [u32; 2],
    k: u32,
    seed: u64,
) -> Result<PathRecord, String> {
    let flag = AtomicBool::new(false);
    let (done, wait) = mpsc::channel::<()>();
    let (mut record, abandoned) = std::thread::scope(|scope| {
        let flag = &flag;
        scope.spawn(move || {
            if wait.recv_timeout(LONGEST_SAMPLE).is_err() {
                flag.store(true, Ordering::Relaxed);
            }
        });
        let recorded = stop::watch(flag, || {
            let (record, _splats) =
                record_sample(integrator, scene, UVec2::from_array(pixel), seed, k);
            (record, stop::take_abandoned())
        });
        let _ = done.send(());
        recorded
    });
    if abandoned {
        return Err(lang::pick(
            format!(
                "this sample traces more rays than the inspector computes in {} s (lower the max \
                 depth or the branching)",
                LONGEST_SAMPLE.as_secs()
            ),
            format!(
                "тази проба проследява повече лъчи, отколкото инспекторът изчислява за {} s \
                 (намалете максималната дълбочина или разклоняването)",
                LONGEST_SAMPLE.as_secs()
            ),
        ));
    }
    record.project(&scene.camera);
    Ok(record)
}
