//! `lesson11 render`: one scene, one integrator, PNG and EXR out.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result};
use clap::{Args, ValueEnum};
use raytracer::integrator::{AmbientOcclusion, Direct, Integrator};
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
}

impl IntegratorKind {
    pub fn build(self, ao_distance: f32) -> Box<dyn Integrator> {
        match self {
            IntegratorKind::Direct => Box::new(Direct),
            IntegratorKind::Ao => Box::new(AmbientOcclusion {
                distance: ao_distance,
            }),
        }
    }
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
    /// Exposure in stops for the PNG (+1 doubles the brightness); the EXR is never changed.
    #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
    pub exposure: f32,
    /// Length of the occlusion rays of `--integrator ao`, in scene units (metres).
    #[arg(long, default_value_t = 1.0)]
    pub ao_distance: f32,
}

pub fn run(args: &RenderArgs) -> Result<()> {
    let (scene, options) = args.scene.load("cornell")?;
    let integrator = args.integrator.build(args.ao_distance);
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
        "  {}  ({} spp, {}×{}, {:.2} s, {:.2} M samples/s{}{})",
        png.display(),
        options.spp,
        scene.camera.width,
        scene.camera.height,
        seconds,
        stats.samples_per_second() / 1e6,
        if stats.nonfinite > 0 {
            format!(", {} non-finite samples dropped", stats.nonfinite)
        } else {
            String::new()
        },
        if stats.interrupted {
            ", INTERRUPTED: partial image written"
        } else {
            ""
        },
    );
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
