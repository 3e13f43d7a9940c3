//! `lesson11 render --student`: the student's own integrator rendered beside
//! the reference one, and the grader's tile z-test between the two.

use anyhow::{Result, bail};
use exercises::plug::StudentRender;
use grading::Outcome;
use raytracer::metrics::{z_test, z_threshold};
use raytracer::render::render;

use crate::integrators::{IntegratorArgs, IntegratorKind};
use crate::options::SceneArgs;
use crate::render_files::render_to_files;

/// The student's integrator (exercise 10, 11, 12 or 18, by `--integrator`)
/// beside the renderer's integrator with the same estimator, and their tile
/// z-test.
pub fn run(
    scene_args: &SceneArgs,
    integrator: IntegratorKind,
    ia: &IntegratorArgs,
    exposure: f32,
) -> Result<()> {
    let (scene, options) = scene_args.load("cornell")?;
    // The checks of the options (naive recursion's ray budget among them)
    // apply to the student's integrator as to the renderer's.
    integrator.build(ia, &scene, &options, scene_args.force)?;
    let max_depth = ia.max_depth(integrator, &scene)?;
    let rr_depth = ia.rr_depth(&scene);
    let which = match integrator {
        IntegratorKind::Path | IntegratorKind::PathBrdf => StudentRender::Path {
            max_depth,
            rr_depth,
        },
        IntegratorKind::Naive => StudentRender::Naive {
            max_depth: max_depth.unwrap_or(crate::integrators::NAIVE_DEFAULT_DEPTH),
            branching: ia.branching()[0],
        },
        IntegratorKind::Direct | IntegratorKind::PathNee => StudentRender::Direct,
        IntegratorKind::Vpl => {
            let s = ia.biased.vpl(max_depth, rr_depth, options.seed)?;
            StudentRender::Vpl {
                paths: u32::try_from(s.paths).unwrap_or(u32::MAX),
                clamp: (s.clamp > 0.0).then_some(s.clamp),
                max_depth,
                rr_depth,
                seed: s.seed,
            }
        }
        IntegratorKind::Ao
        | IntegratorKind::Light
        | IntegratorKind::Bdpt
        | IntegratorKind::Mlt
        | IntegratorKind::Photon
        | IntegratorKind::Sppm
        | IntegratorKind::IrradianceCache => bail!(
            "--student renders the exercises that are whole integrators: use --integrator path, naive, direct or vpl \
             (light tracing, bidirectional tracing and Metropolis light transport are graded piece by piece: \
             exercises 14, 15 and 16; photon mapping: 17)"
        ),
    };
    let exercise = which.exercise();
    let (student, reference) = (which.student(), which.reference());
    let outcome = grading::grade_exercise(exercise).unwrap_or(Outcome::NotStarted(None));
    if outcome.is_not_started() {
        bail!(
            "{exercise} is not started yet ({outcome}): fill in exercises/src/{exercise}.rs first"
        );
    }
    println!("{exercise}: {outcome}");
    println!("  beside it: {}", which.reference_note());
    let out = &scene_args.out;
    let stem = format!("{}-{}", scene.name, reference.name());
    render_to_files(
        &scene,
        student.as_ref(),
        &options,
        out,
        &format!("{stem}-student"),
        exposure,
    )?;
    render_to_files(
        &scene,
        reference.as_ref(),
        &options,
        out,
        &format!("{stem}-reference"),
        exposure,
    )?;
    // Compare them tile by tile (16-pixel tiles), as the grader does.
    // Different seeds: the two integrators may use the same random numbers in
    // the same order, and correlated pictures would hide a difference.
    let mut quiet = options.clone();
    quiet.progress = false;
    let a = render(&scene, student.as_ref(), &quiet);
    quiet.seed = quiet.seed.wrapping_add(1);
    let b = render(&scene, reference.as_ref(), &quiet);
    let z = z_test(
        &a.film.image(),
        &a.film.variance_image(),
        &b.film.image(),
        &b.film.variance_image(),
        16,
    );
    let threshold = z_threshold(z.z.len() * 3, 1e-4);
    println!(
        "  tile z-test: largest |z| = {:.1} in tile {} (threshold {threshold:.1}): {}",
        z.max_abs_z,
        z.worst_tile,
        if (z.max_abs_z as f64) <= threshold {
            "consistent with the reference"
        } else {
            "DIFFERS from the reference"
        }
    );
    Ok(())
}
