//! `lesson11 render`: one scene, one integrator, PNG and EXR out.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result};
use clap::{Args, ValueEnum};
use raytracer::integrator::{
    AmbientOcclusion, Bdpt, Direct, DirectStrategy, Integrator, LightTracer, NaiveRecursive,
    PathTracer,
};
use raytracer::render::{RenderOptions, render};
use raytracer::scene::Scene;

use crate::options::{SceneArgs, create_dir};

/// The integrators this build offers.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum IntegratorKind {
    /// Direct lighting: emitters seen directly plus one bounce (light sampling and BRDF sampling under MIS).
    Direct,
    /// Ambient occlusion: the fraction of the hemisphere that is open (not physically based).
    Ao,
    /// Path tracing: one continuation per bounce, light sampling and BRDF sampling under MIS.
    Path,
    /// Path tracing with BRDF sampling only (a teaching baseline: lights are found by chance).
    PathBrdf,
    /// Path tracing with light sampling only, no MIS (a teaching baseline).
    PathNee,
    /// Naive recursive Monte Carlo: N rays at every hit (see --branching), N^D rays per sample.
    Naive,
    /// Light tracing: paths start on the lights and every vertex is connected to the camera.
    Light,
    /// Bidirectional path tracing: camera and light subpaths, every connection, MIS over all of them.
    Bdpt,
}

impl IntegratorKind {
    pub fn build(self, args: &IntegratorArgs, scene: &Scene) -> Box<dyn Integrator> {
        let max_depth = match args.max_depth {
            Some(d) if d < 0 => None,
            Some(d) => Some(d as u32),
            None => scene.settings.max_depth,
        };
        let rr_depth = args.rr_depth.unwrap_or(scene.settings.rr_depth);
        let path = |strategy| {
            Box::new(PathTracer {
                max_depth,
                rr_depth,
                strategy,
            })
        };
        match self {
            IntegratorKind::Direct => Box::new(Direct),
            IntegratorKind::Ao => Box::new(AmbientOcclusion {
                distance: args.ao_distance,
            }),
            IntegratorKind::Path => path(DirectStrategy::Mis),
            IntegratorKind::PathBrdf => path(DirectStrategy::BrdfOnly),
            IntegratorKind::PathNee => path(DirectStrategy::LightOnly),
            IntegratorKind::Naive => {
                let mut naive = NaiveRecursive::new(args.branching.clone(), max_depth.or(Some(4)));
                naive.roulette_depth = args.roulette.then_some(rr_depth);
                naive.cutoff = args.cutoff;
                Box::new(naive)
            }
            IntegratorKind::Light => Box::new(LightTracer {
                max_depth,
                rr_depth,
            }),
            IntegratorKind::Bdpt => Box::new(Bdpt {
                max_depth,
                rr_depth,
                strategy_images: None,
            }),
        }
    }
}

/// Options of the integrators.
#[derive(Args, Debug, Clone)]
pub struct IntegratorArgs {
    /// Maximum path depth, Mitsuba's convention: 1 = emitters seen directly, 2 = direct light,
    /// D = at most D−1 bounces, −1 = unlimited (default: the scene's).
    #[arg(long, allow_negative_numbers = true)]
    pub max_depth: Option<i32>,
    /// Russian roulette may end paths after this many bounces (default: the scene's).
    #[arg(long)]
    pub rr_depth: Option<u32>,
    /// Branching factor of naive recursion, one per level (the last repeats), e.g. 16,4,2.
    #[arg(long, value_delimiter = ',', default_value = "8")]
    pub branching: Vec<u32>,
    /// Naive recursion: end by Russian roulette (unbiased) from --rr-depth on.
    #[arg(long)]
    pub roulette: bool,
    /// Naive recursion: stop once the product of BRDF weights is below this (the lecture's idea; biased).
    #[arg(long)]
    pub cutoff: Option<f32>,
    /// Length of the occlusion rays of `--integrator ao`, in scene units (metres).
    #[arg(long, default_value_t = 1.0)]
    pub ao_distance: f32,
}

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
    if args.student {
        return crate::exercises_cmd::render_student(args);
    }
    let (scene, options) = args.scene.load("cornell")?;
    if args.integrator_args.branching.contains(&0) {
        anyhow::bail!("--branching factors must be at least 1");
    }
    let integrator = args.integrator.build(&args.integrator_args, &scene);
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

/// What a rendered picture left on disk.
pub struct Picture {
    pub png: PathBuf,
    pub exr: PathBuf,
    pub seconds: f64,
    pub spp: u32,
}

/// Renders and writes `dir/stem.png`, `dir/stem.exr` and `dir/stem-variance.exr`,
/// then prints one summary line. An interrupted render (Ctrl-C) still writes
/// what it computed.
pub fn render_to_files(
    scene: &Scene,
    integrator: &dyn Integrator,
    options: &RenderOptions,
    dir: &Path,
    stem: &str,
    exposure: f32,
) -> Result<Picture> {
    create_dir(dir)?;
    let result = render(scene, integrator, options);
    let png = dir.join(format!("{stem}.png"));
    let exr = dir.join(format!("{stem}.exr"));
    let variance = dir.join(format!("{stem}-variance.exr"));
    result
        .film
        .write_png(&png, exposure)
        .with_context(|| format!("cannot write {}", png.display()))?;
    result
        .film
        .write_exr(&exr)
        .with_context(|| format!("cannot write {}", exr.display()))?;
    result
        .film
        .variance_image()
        .write_exr(&variance)
        .with_context(|| format!("cannot write {}", variance.display()))?;
    let stats = &result.stats;
    let seconds = stats.elapsed.as_secs_f64();
    println!(
        "  wrote {} and .exr ({} spp, {seconds:.2} s)",
        png.display(),
        options.spp
    );
    if stats.nonfinite > 0 {
        println!(
            "  note: {} samples were NaN, infinite or negative and counted as zero",
            stats.nonfinite
        );
    }
    if stats.interrupted {
        anyhow::bail!(
            "interrupted by Ctrl-C; what was rendered so far is in {}",
            exr.display()
        );
    }
    Ok(Picture {
        png,
        exr,
        seconds,
        spp: options.spp,
    })
}
