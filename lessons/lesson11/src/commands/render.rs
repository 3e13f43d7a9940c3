//! `lesson11 render`: one scene, one integrator, PNG and EXR out.

mod student;

use anyhow::Result;
use clap::Args;

use crate::integrators::{IntegratorArgs, IntegratorKind, render_sppm_to_files};
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
    /// Render with your own code from exercises/ (path: exercise 11, naive: 10, direct: 12) beside the renderer's integrator with the same estimator.
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
    if args.integrator == IntegratorKind::Mlt {
        let (bdpt, metropolis) =
            args.integrator_args
                .metropolis(&scene, &options, args.scene.force)?;
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
    if args.integrator == IntegratorKind::Sppm {
        let ia = &args.integrator_args;
        ia.check_only(args.integrator)?;
        let settings = ia
            .biased
            .sppm(ia.max_depth(args.integrator, &scene)?, ia.rr_depth(&scene))?;
        return render_sppm_to_files(
            &scene,
            &settings,
            &options,
            &args.scene.out,
            args.exposure,
            args.scene.force,
        );
    }
    let integrator =
        args.integrator
            .build(&args.integrator_args, &scene, &options, args.scene.force)?;
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
