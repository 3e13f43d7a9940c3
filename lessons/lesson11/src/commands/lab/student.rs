//! The "Your code" tab: the student's own integrator (the exercises'
//! plug, as `lesson11 render --student` uses it) rendered progressively
//! beside the renderer's integrator of the same estimator, at the same
//! settings, with the grader's tile z-test between them drawn as a map
//! that updates as both converge: the grader's verdict as a picture.
//!
//! The student's code runs on the job's threads; a panic in it stops the
//! job with its message on the page (`job.rs`), never the lab, and its NaN
//! or negative samples are counted apart.

use raytracer::film::Image;
use raytracer::math::Color;
use raytracer::metrics::{ZTest, z_test, z_threshold};

use super::job::{Job, JobSpec, StudentPair};
use super::query::Query;
use super::settings::{SceneFolder, on_the_page, one_line, render_setup};
use crate::commands::render::student::student_render;

/// The grader's tile size and family-wise error rate (`render --student`'s).
pub const TILE: u32 = 16;
const FAMILY_WISE: f64 = 1e-4;

/// The student's integrator and the renderer's beside it, as the query's
/// render options say (the options of `lesson11 render --student`).
pub fn student_job(q: &Query, folder: &SceneFolder) -> Result<JobSpec, String> {
    let setup = render_setup(q, folder, "cornell", "path")?;
    let which = student_render(
        setup.kind,
        &setup.integrator_args,
        &setup.scene,
        &setup.options,
    )
    .map_err(|e| on_the_page(&one_line(&e)))?;
    Ok(JobSpec {
        kind: "student",
        command: format!(
            "cargo run --release -p lesson11 -- render --student {}",
            setup.options_line
        ),
        eyes: vec![setup.scene.clone(), setup.scene],
        build_for: None,
        plan: setup.plan,
        options: setup.options,
        wavefront: None,
        student: Some(StudentPair {
            exercise: which.exercise(),
            make: Box::new(move || (which.student(), which.reference())),
        }),
        race: None,
    })
}

/// The tile z-test of the student's picture (eye 0) against the
/// renderer's (eye 1) so far, and its verdict.
pub struct ZMap {
    pub test: ZTest,
    pub threshold: f64,
}

impl ZMap {
    /// `None` until both pictures have a snapshot.
    pub fn of(job: &Job) -> Option<ZMap> {
        let eyes = job.snapshots();
        let [a, b] = eyes.as_slice() else {
            return None;
        };
        let (a, av) = (a.image.as_ref()?, a.variance.as_ref()?);
        let (b, bv) = (b.image.as_ref()?, b.variance.as_ref()?);
        let test = z_test(a, av, b, bv, TILE);
        let threshold = z_threshold(test.z.len() * 3, FAMILY_WISE);
        Some(ZMap { test, threshold })
    }

    pub fn consistent(&self) -> bool {
        (self.test.max_abs_z as f64) <= self.threshold
    }

    /// The map at the pictures' size: each tile grey-green by |z| up to the
    /// threshold, red beyond it, magenta where z is not a number.
    pub fn image(&self, width: u32, height: u32) -> Image {
        let grid = self.test.grid;
        Image::from_fn(width, height, |x, y| {
            let (tx, ty) = (x / self.test.tile, y / self.test.tile);
            let z = self.test.z[(ty * grid.x + tx) as usize];
            let worst = z.abs().max_element();
            let t = (worst as f64 / self.threshold) as f32;
            if worst.is_nan() {
                Color::new(1.0, 0.0, 1.0)
            } else if t > 1.0 {
                Color::new(1.0, 0.05, 0.05)
            } else {
                Color::new(0.02, 0.04 + 0.4 * t * t, 0.02)
            }
        })
    }

    /// One line: the largest |z|, where, against what threshold (in
    /// English: an HTTP header carries it).
    pub fn verdict(&self) -> String {
        let [z, x, y, threshold, tile] = self.verdict_numbers();
        format!(
            "largest |z| = {z:.1} in tile ({x}, {y}) (threshold {threshold:.1}, {tile}-pixel tiles): {}",
            if self.consistent() {
                "consistent with the renderer's"
            } else {
                "DIFFERS from the renderer's (red tiles)"
            }
        )
    }

    /// The verdict's numbers, from which the page writes it in its language:
    /// the largest |z|, its tile (x, y), the threshold and the tile size.
    pub fn verdict_numbers(&self) -> [f64; 5] {
        let w = self.test.worst_tile;
        [
            self.test.max_abs_z as f64,
            w.x as f64,
            w.y as f64,
            self.threshold,
            TILE as f64,
        ]
    }
}
