//! `lesson11 render`: one scene, one integrator, PNG and EXR out.

pub mod student;

use anyhow::{Result, bail};
use clap::{Args, ValueEnum};

use raytracer::integrator::{DirectStrategy, PathTracer};
use raytracer::render::interrupt_flag;
use raytracer::scene::Scene;
use raytracer::wavefront::WavefrontPathTracer;

use crate::engine::Engine;

use crate::integrators::{IntegratorArgs, IntegratorKind, IntegratorPlan, render_sppm_to_files};
use crate::options::{SceneArgs, check_exposure};
use crate::render_files::{render_to_files, render_with_to_files, warn_if_unlit};

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
    /// Which engine runs --integrator path: the lecture's (scalar) or the wavefront engine
    /// (a tile's paths in lockstep; the same image bit for bit, faster).
    #[arg(long, value_enum, default_value = "scalar")]
    pub engine: Engine,
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
    let wavefront = wavefront_engine(args, &scene)?;
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
    if let Some(engine) = wavefront {
        let stem = format!("{}-{}", scene.name, integrator.name());
        warn_if_unlit(&scene, integrator.as_ref());
        render_with_to_files(
            &scene,
            &options,
            &args.scene.out,
            &stem,
            args.exposure,
            || engine.render(&scene, &options),
        )?;
        return Ok(());
    }
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

/// The wavefront engine if `--engine wavefront` asks for it (`None` for the
/// scalar engine), or one line on why it cannot run this render. The lab
/// asks it too.
pub fn wavefront_engine(args: &RenderArgs, scene: &Scene) -> Result<Option<WavefrontPathTracer>> {
    if args.engine == Engine::Scalar {
        return Ok(None);
    }
    if args.integrator != IntegratorKind::Path {
        bail!(
            "--engine {} runs --integrator path only",
            engine_name(args.engine)
        );
    }
    let path = PathTracer {
        max_depth: args.integrator_args.max_depth(args.integrator, scene)?,
        rr_depth: args.integrator_args.rr_depth(scene),
        strategy: DirectStrategy::Mis,
    };
    Ok(Some(WavefrontPathTracer::from_path(&path)?))
}

/// The engine's name as the command line spells it.
fn engine_name(engine: Engine) -> String {
    engine
        .to_possible_value()
        .map_or_else(String::new, |v| v.get_name().to_string())
}
