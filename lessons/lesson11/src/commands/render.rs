//! `lesson11 render`: one scene, one integrator, PNG and EXR out.

pub(crate) mod student;

use anyhow::Result;
use clap::Args;

use raytracer::render::interrupt_flag;

use crate::integrators::{IntegratorArgs, IntegratorKind, IntegratorPlan, render_sppm_to_files};
use crate::options::{SceneArgs, check_exposure};
use crate::render_files::render_to_files;

/// Render a scene with one integrator and write NAME.png (tone mapped, sRGB),
/// NAME.exr (linear radiance) and NAME-variance.exr (variance of each pixel's mean).
#[derive(Args, Debug)]
pub struct RenderArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    /// The algorithm that estimates each pixel.
    #[arg(long, short, value_enum, default_value = "direct")]
    pub integrator: IntegratorKind,
    #[command(flatten)]
    pub integrator_args: IntegratorArgs,
    /// Exposure in stops for the PNG (+1 doubles the brightness); the EXR is never changed.
    #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
    pub exposure: f32,
    /// Render with your own code from exercises/ (naive: exercise 10, path-brdf: 11, direct and path-nee: 12, path: 13, light: 14, bdpt: 15, mlt: 16, photon: 17, vpl: 18) beside the renderer's integrator with the same estimator.
    #[arg(long)]
    pub student: bool,
}

pub fn run(args: &RenderArgs) -> Result<()> {
    check_exposure(args.exposure)?;
    if args.student {
        return student::run(
            &args.scene,
            args.integrator,
            &args.integrator_args,
            args.exposure,
        );
    }
    let (scene, options) = args.scene.load("cornell")?;
    // The lab renders from the same plan (`commands/lab/job.rs`).
    let plan = args
        .integrator
        .plan(&args.integrator_args, &scene, &options, args.scene.force)?;
    let integrator = match plan {
        IntegratorPlan::Metropolis(bdpt, metropolis) => {
            crate::metropolis::render_to_files(
                &scene,
                &bdpt,
                &options,
                &metropolis,
                &args.scene.out,
                &format!("{}-mlt", scene.name),
                args.exposure,
            )?;
            return Ok(());
        }
        IntegratorPlan::Sppm(settings) => {
            return render_sppm_to_files(
                &scene,
                &settings,
                &options,
                &args.scene.out,
                args.exposure,
            );
        }
        plan => plan.build(&scene, &options, interrupt_flag())?,
    };
    let stem = format!("{}-{}", scene.name, integrator.name());
    render_to_files(
        &scene,
        integrator.as_ref(),
        &options,
        &args.scene.out,
        &stem,
        args.exposure,
    )?;
    Ok(())
}
