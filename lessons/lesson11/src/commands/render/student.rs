//! `lesson11 render --student`: the student's own integrator rendered beside
//! the reference one, and the grader's tile z-test between the two.

use std::time::Instant;

use anyhow::{Result, anyhow, bail};
use exercises::ex16_metropolis;
use exercises::plug::{ChainSettings, PrimaryPaths, StudentRender, chains_film, run_chains};
use grading::Outcome;
use raytracer::film::Image;
use raytracer::metrics::{z_test, z_threshold};
use raytracer::render::RenderStats;
use raytracer::render::metropolis::render_metropolis;

use crate::integrators::{IntegratorArgs, IntegratorKind, IntegratorPlan};
use crate::options::SceneArgs;
use crate::page::Picture;
use crate::render_files::{OutputFiles, render_to_files};

/// The student's integrator (exercises 10–15, 17 and 18, by `--integrator`:
/// naive, path-brdf, direct or path-nee, path, light, bdpt, photon, vpl; 16
/// with `--integrator mlt`, see [`run_metropolis`]) beside the renderer's
/// integrator with the same estimator, and their tile z-test.
pub fn run(
    scene_args: &SceneArgs,
    integrator: IntegratorKind,
    ia: &IntegratorArgs,
    exposure: f32,
) -> Result<()> {
    if integrator == IntegratorKind::Mlt {
        return run_metropolis(scene_args, ia, exposure);
    }
    let (scene, options) = scene_args.load("cornell")?;
    // The checks of the options (naive recursion's ray budget among them)
    // apply to the student's integrator as to the renderer's.
    integrator.build(ia, &scene, &options, scene_args.force)?;
    let which = student_render(integrator, ia, &scene, &options)?;
    announce(&which)?;
    let (student, reference) = (which.student(), which.reference());
    let out = &scene_args.out;
    let stem = format!("{}-{}", scene.name, reference.name());
    let a = render_to_files(
        &scene,
        student.as_ref(),
        &options,
        out,
        &format!("{stem}-student"),
        exposure,
    )?;
    // Another seed for the reference: the two integrators may use the same
    // random numbers in the same order, and correlated pictures would hide
    // a difference.
    let mut other = options.clone();
    other.seed = other.seed.wrapping_add(1);
    let b = render_to_files(
        &scene,
        reference.as_ref(),
        &other,
        out,
        &format!("{stem}-reference"),
        exposure,
    )?;
    // Compared as written (mean and variance EXR), not rendered again.
    let read = |p: &Picture| -> Result<(Image, Image)> {
        let variance = p.exr.with_file_name(format!(
            "{}-variance.exr",
            p.exr.file_stem().unwrap_or_default().to_string_lossy()
        ));
        Ok((
            Image::read_exr(&p.exr).map_err(|e| anyhow!("{}: {e}", p.exr.display()))?,
            Image::read_exr(&variance).map_err(|e| anyhow!("{}: {e}", variance.display()))?,
        ))
    };
    say_tile_z_test(&read(&a)?, &read(&b)?);
    Ok(())
}

/// The exercise that `--integrator` names, with the options it takes
/// (checked), and the renderer's integrator of the same estimator beside it:
/// what `lesson11 render --student` and the lab's "Your code" tab render.
/// Exercise 16 (Metropolis) is refused: its chains are not pixel samples.
pub fn student_render(
    integrator: IntegratorKind,
    ia: &IntegratorArgs,
    scene: &raytracer::scene::Scene,
    options: &raytracer::render::RenderOptions,
) -> Result<StudentRender> {
    let max_depth = ia.max_depth(integrator, scene)?;
    let rr_depth = ia.rr_depth(scene);
    Ok(match integrator {
        IntegratorKind::PathBrdf => StudentRender::Path {
            max_depth,
            rr_depth,
        },
        IntegratorKind::PathNee => StudentRender::PathNee {
            max_depth,
            rr_depth,
        },
        IntegratorKind::Path => StudentRender::PathMis {
            max_depth,
            rr_depth,
        },
        IntegratorKind::Naive => StudentRender::Naive {
            max_depth: max_depth.unwrap_or(crate::integrators::NAIVE_DEFAULT_DEPTH),
            branching: ia.branching()[0],
        },
        IntegratorKind::Direct => StudentRender::Direct,
        IntegratorKind::Light => StudentRender::Light {
            max_depth,
            rr_depth,
        },
        IntegratorKind::Bdpt => StudentRender::Bdpt {
            max_depth,
            rr_depth,
        },
        IntegratorKind::Mlt => bail!(
            "--student -i mlt (exercise 16) runs Markov chains, not pixel samples: lesson11 render --student -i mlt renders it"
        ),
        IntegratorKind::Photon => {
            // Exercise 17 has no depth limit and no final gathering.
            // (A scene's own max_depth is not a request: it is ignored here.)
            if (ia.max_depth.is_some() && max_depth.is_some())
                || ia.biased.final_gather.is_some_and(|g| g > 0)
            {
                bail!(
                    "--student -i photon (exercise 17) traces photons with no depth limit and reads the maps directly: drop --max-depth and --final-gather"
                );
            }
            let s = ia.biased.photon(None, rr_depth, options.seed)?;
            StudentRender::Photon {
                photons: s.photons,
                k: s.k,
                radius_bits: s.radius.map(f32::to_bits),
                rr_depth,
                seed: options.seed,
            }
        }
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
        IntegratorKind::Ao | IntegratorKind::Sppm | IntegratorKind::IrradianceCache => bail!(
            "--student renders the exercises that are whole integrators: use --integrator naive (exercise 10), \
             path-brdf (11), direct or path-nee (12), path (13), light (14), bdpt (15), mlt (16), \
             photon (17) or vpl (18); ambient occlusion, SPPM and irradiance caching are the renderer's only"
        ),
    })
}

/// Says which exercise renders and what stands beside it; refuses one that
/// is not started.
fn announce(which: &StudentRender) -> Result<()> {
    let exercise = which.exercise();
    let outcome = grading::grade_exercise(exercise).unwrap_or(Outcome::NotStarted(None));
    if outcome.is_not_started() {
        bail!(
            "{exercise} is not started yet ({outcome}): fill in exercises/src/{exercise}.rs first"
        );
    }
    crate::console::say!("{exercise}: {outcome}");
    crate::console::say!("  beside it: {}", which.reference_note());
    Ok(())
}

/// The grader's tile z-test (16-pixel tiles, family-wise 1e-4) between the
/// student's picture and the reference's, each as (mean, variance), said in
/// one line.
fn say_tile_z_test(a: &(Image, Image), b: &(Image, Image)) {
    let z = z_test(&a.0, &a.1, &b.0, &b.1, 16);
    let threshold = z_threshold(z.z.len() * 3, 1e-4);
    crate::console::say!(
        "  tile z-test: largest |z| = {:.1} in tile {} (threshold {threshold:.1}): {}",
        z.max_abs_z,
        z.worst_tile,
        if (z.max_abs_z as f64) <= threshold {
            "consistent with the reference"
        } else {
            "DIFFERS from the reference"
        }
    );
}

/// The student's Metropolis chains (exercise 16) over bidirectional path
/// tracing beside the renderer's Metropolis over the same, with the same
/// options (`--spp` mutations per pixel, `--chains`, `--bootstrap`,
/// `--large-step-probability`, `--mutation-size`), and their tile z-test.
/// Each of the student's chains makes its own bootstrap (an equal share
/// of `--bootstrap`, at least 256 paths).
fn run_metropolis(scene_args: &SceneArgs, ia: &IntegratorArgs, exposure: f32) -> Result<()> {
    let (scene, options) = scene_args.load("door")?;
    let IntegratorPlan::Metropolis(bdpt, metropolis) =
        IntegratorKind::Mlt.plan(ia, &scene, &options, scene_args.force)?
    else {
        bail!("--integrator mlt planned no Metropolis render");
    };
    let which = StudentRender::Metropolis {
        max_depth: bdpt.max_depth,
        rr_depth: bdpt.rr_depth,
    };
    announce(&which)?;
    let (w, h) = (scene.camera.width, scene.camera.height);
    let chains = metropolis.chains;
    let settings = ChainSettings {
        // Unlimited depth: paths longer than 16 bounces read fixed numbers
        // past the state (rare with Russian roulette).
        dimensions: PrimaryPaths::bdpt_dimensions(bdpt.max_depth.unwrap_or(16)),
        bootstrap: (metropolis.bootstrap_paths(w, h) / chains as u64).max(256) as usize,
        mutations: (options.spp as u64 * w as u64 * h as u64 / chains as u64).max(1),
        large_step_probability: metropolis.large_step_probability,
        mutation_size: metropolis.mutation_size,
    };
    let out = &scene_args.out;
    let stem = format!("{}-mlt", scene.name);
    let start = Instant::now();
    let integrator = which.student();
    let images = run_chains(
        ex16_metropolis::metropolis_chain,
        &scene,
        integrator.as_ref(),
        &settings,
        chains,
        options.seed,
    );
    let student = chains_film(&images, w, h);
    let stats = RenderStats {
        elapsed: start.elapsed(),
        samples: settings.mutations * chains as u64,
        interrupted: false,
        nonfinite: student.nonfinite_count(),
    };
    OutputFiles::new(out, &format!("{stem}-student"))?.write(
        &student,
        &stats,
        options.spp,
        exposure,
        String::new,
    )?;
    // The renderer's Metropolis with another seed: correlated pictures
    // would hide a difference.
    let mut quiet = options.clone();
    quiet.seed = quiet.seed.wrapping_add(1);
    let reference = render_metropolis(&scene, &bdpt, &quiet, &metropolis);
    OutputFiles::new(out, &format!("{stem}-reference"))?.write(
        &reference.film,
        &reference.stats,
        options.spp,
        exposure,
        || "INTERRUPTED".to_string(),
    )?;
    // Pixels of one chain are not independent (its streaks), so this test
    // is only a guide; the grader tests tiles with the chains' own spread.
    say_tile_z_test(
        &(student.image(), student.variance_image()),
        &(reference.film.image(), reference.film.variance_image()),
    );
    Ok(())
}
