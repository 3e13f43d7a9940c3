//! The options of the biased integrators (`photon`, `sppm`, `vpl`,
//! `irradiance-cache`), checked before anything is traced, and what they
//! build: photon maps, VPLs and the irradiance cache are made before the
//! render (with a line saying how many and how much memory); SPPM renders
//! in passes of its own ([`render_sppm_to_files`]).

use std::path::Path;

use anyhow::{Result, bail};
use clap::Args;
use raytracer::integrator::sppm::SppmSettings;
use raytracer::integrator::{
    InstantRadiosity, Integrator, IrradianceCache, IrradianceCacheSettings, PhotonMapping,
    PhotonSettings, VplSettings,
};
use raytracer::render::{RenderOptions, interrupt_flag, sppm::render_sppm};
use raytracer::scene::Scene;

use crate::options::{check_memory, create_dir};
use crate::render_files::write_png_and_exr;

/// Options of the biased integrators.
#[derive(Args, Debug, Clone, Default)]
pub struct BiasedArgs {
    /// photon: light paths traced (default 200000); sppm: photon paths per pass (default 50000).
    #[arg(long)]
    pub photons: Option<u64>,
    /// photon: density estimate from the k nearest photons (default 50).
    #[arg(long)]
    pub k: Option<usize>,
    /// photon: a fixed search radius instead of the k nearest; sppm: the initial radius
    /// (default: 1% of the scene's diagonal). In scene units.
    #[arg(long, allow_negative_numbers = true)]
    pub radius: Option<f32>,
    /// photon: final gathering with this many BRDF rays per visible point (default 0: read the
    /// global map directly).
    #[arg(long)]
    pub final_gather: Option<u32>,
    /// sppm: the fraction α of new photons kept each pass, in (0, 1) (default 2/3).
    #[arg(long, allow_negative_numbers = true)]
    pub alpha: Option<f32>,
    /// vpl: light paths traced; each leaves a virtual point light at every diffuse vertex (default 256).
    #[arg(long)]
    pub vpl_paths: Option<u64>,
    /// vpl: clamp the geometry term G at this bound (default 0: no clamping, unbiased).
    #[arg(long, allow_negative_numbers = true)]
    pub clamp: Option<f32>,
    /// irradiance-cache: Ward's error threshold a (default 0.3; smaller: more records).
    #[arg(long, allow_negative_numbers = true)]
    pub ic_error: Option<f32>,
    /// irradiance-cache: hemisphere rays per record (default 128).
    #[arg(long)]
    pub ic_rays: Option<u32>,
}

/// The biased integrators, as `--integrator` names them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BiasedKind {
    Photon,
    Sppm,
    Vpl,
    IrradianceCache,
}

impl BiasedKind {
    /// Its `--integrator` name.
    pub fn name(self) -> &'static str {
        match self {
            BiasedKind::Photon => "photon",
            BiasedKind::Sppm => "sppm",
            BiasedKind::Vpl => "vpl",
            BiasedKind::IrradianceCache => "irradiance-cache",
        }
    }
}

impl BiasedArgs {
    /// Refuses an option that `kind` (`None`: an unbiased integrator, named
    /// `name`) does not use.
    pub fn check(&self, kind: Option<BiasedKind>, name: &str) -> Result<()> {
        use BiasedKind::{IrradianceCache, Photon, Sppm, Vpl};
        let given: [(&str, bool, &[BiasedKind]); 9] = [
            ("--photons", self.photons.is_some(), &[Photon, Sppm]),
            ("--k", self.k.is_some(), &[Photon]),
            ("--radius", self.radius.is_some(), &[Photon, Sppm]),
            ("--final-gather", self.final_gather.is_some(), &[Photon]),
            ("--alpha", self.alpha.is_some(), &[Sppm]),
            ("--vpl-paths", self.vpl_paths.is_some(), &[Vpl]),
            ("--clamp", self.clamp.is_some(), &[Vpl]),
            ("--ic-error", self.ic_error.is_some(), &[IrradianceCache]),
            ("--ic-rays", self.ic_rays.is_some(), &[IrradianceCache]),
        ];
        for (option, set, users) in given {
            if set && !kind.is_some_and(|k| users.contains(&k)) {
                let names: Vec<&str> = users.iter().map(|u| u.name()).collect();
                bail!(
                    "{option} does not apply to --integrator {name}: it is an option of --integrator {}",
                    names.join(" and ")
                );
            }
        }
        if self.k.is_some() && self.radius.is_some() {
            bail!(
                "--k and --radius exclude each other: the k nearest photons, or all within a fixed radius"
            );
        }
        Ok(())
    }

    /// Photon mapping's settings, checked.
    pub fn photon(
        &self,
        max_depth: Option<u32>,
        rr_depth: u32,
        seed: u64,
    ) -> Result<PhotonSettings> {
        let d = PhotonSettings::default();
        let s = PhotonSettings {
            photons: self.photons.unwrap_or(d.photons),
            k: self.k.unwrap_or(d.k),
            radius: self.radius,
            final_gather: self.final_gather.unwrap_or(0),
            max_depth,
            rr_depth,
            seed,
        };
        s.check().map_err(anyhow::Error::msg)?;
        Ok(s)
    }

    /// SPPM's settings, checked.
    pub fn sppm(&self, max_depth: Option<u32>, rr_depth: u32) -> Result<SppmSettings> {
        let d = SppmSettings::default();
        let s = SppmSettings {
            photons: self.photons.unwrap_or(d.photons),
            radius: self.radius,
            alpha: self.alpha.unwrap_or(d.alpha),
            max_depth,
            rr_depth,
        };
        s.check().map_err(anyhow::Error::msg)?;
        Ok(s)
    }

    /// Instant radiosity's settings, checked.
    pub fn vpl(&self, max_depth: Option<u32>, rr_depth: u32, seed: u64) -> Result<VplSettings> {
        let d = VplSettings::default();
        let s = VplSettings {
            paths: self.vpl_paths.unwrap_or(d.paths),
            clamp: self.clamp.unwrap_or(0.0),
            max_depth,
            rr_depth,
            seed,
        };
        s.check().map_err(anyhow::Error::msg)?;
        Ok(s)
    }

    /// Irradiance caching's settings, checked.
    pub fn irradiance_cache(
        &self,
        max_depth: Option<u32>,
        rr_depth: u32,
        seed: u64,
    ) -> Result<IrradianceCacheSettings> {
        let d = IrradianceCacheSettings::default();
        let s = IrradianceCacheSettings {
            error: self.ic_error.unwrap_or(d.error),
            rays: self.ic_rays.unwrap_or(d.rays),
            max_depth,
            rr_depth,
            seed,
        };
        s.check().map_err(anyhow::Error::msg)?;
        Ok(s)
    }
}

/// Bytes a photon tracing of `paths` light paths may need: 40 bytes per
/// photon, at most 16 photons per path kept in the estimate (Russian
/// roulette ends almost every path before; deeper ones are rare).
fn photon_bytes(paths: u64) -> Option<u64> {
    paths.checked_mul(40 * 16)
}

/// Runs `work` on `threads` threads (rayon's global pool if `None`).
fn in_pool<R: Send>(threads: Option<usize>, work: impl FnOnce() -> R + Send) -> R {
    match threads.and_then(|n| rayon::ThreadPoolBuilder::new().num_threads(n).build().ok()) {
        Some(pool) => pool.install(work),
        None => work(),
    }
}

/// Builds `photon`, `vpl` or `irradiance-cache` (their maps, lights or
/// records made now) and prints one line on what they hold.
pub fn build(
    kind: BiasedKind,
    args: &BiasedArgs,
    scene: &Scene,
    options: &RenderOptions,
    max_depth: Option<u32>,
    rr_depth: u32,
    force: bool,
) -> Result<Box<dyn Integrator>> {
    let seed = options.seed;
    let stop = interrupt_flag();
    let (integrator, summary): (Box<dyn Integrator>, String) = match kind {
        BiasedKind::Photon => {
            let s = args.photon(max_depth, rr_depth, seed)?;
            check_memory(
                &format!("{} photon paths", s.photons),
                photon_bytes(s.photons),
                "--photons",
                force,
            )?;
            let pm = in_pool(options.threads, || PhotonMapping::build(scene, s, stop))
                .map_err(anyhow::Error::msg)?;
            let line = pm.summary();
            (Box::new(pm), line)
        }
        BiasedKind::Vpl => {
            let s = args.vpl(max_depth, rr_depth, seed)?;
            check_memory(
                &format!("{} VPL paths", s.paths),
                s.paths.checked_mul(16 * 128),
                "--vpl-paths",
                force,
            )?;
            let ir = in_pool(options.threads, || InstantRadiosity::build(scene, s, stop))
                .map_err(anyhow::Error::msg)?;
            let line = ir.summary();
            (Box::new(ir), line)
        }
        BiasedKind::IrradianceCache => {
            let s = args.irradiance_cache(max_depth, rr_depth, seed)?;
            let ic = in_pool(options.threads, || IrradianceCache::build(scene, s, stop))
                .map_err(anyhow::Error::msg)?;
            let line = ic.summary();
            (Box::new(ic), line)
        }
        other => bail!("{other:?} is not built here"),
    };
    if options.progress {
        println!("  {summary}");
    }
    Ok(integrator)
}

/// `lesson11 render --integrator sppm`: `--spp` passes, then `dir/stem.png`
/// and `.exr` (no variance image: SPPM's pixels are not means of
/// independent samples). An interrupted render writes its finished passes
/// and returns an error.
pub fn render_sppm_to_files(
    scene: &Scene,
    settings: &SppmSettings,
    options: &RenderOptions,
    dir: &Path,
    exposure: f32,
    force: bool,
) -> Result<()> {
    check_memory(
        &format!("{} photon paths per pass", settings.photons),
        photon_bytes(settings.photons),
        "--photons",
        force,
    )?;
    create_dir(dir)?;
    let stem = format!("{}-sppm", scene.name);
    let result = render_sppm(scene, settings, options);
    if result.passes == 0 {
        println!(
            "  {}: interrupted before any pass was finished; nothing written",
            dir.join(&stem).display()
        );
        bail!("interrupted before any pass was finished");
    }
    let (png, exr) = write_png_and_exr(&result.image, dir, &stem, exposure)?;
    println!(
        "  wrote {} and {} ({} of {} passes, {:.2} s)",
        png.display(),
        exr.display(),
        result.passes,
        options.spp,
        result.stats.elapsed.as_secs_f64()
    );
    if result.stats.interrupted {
        bail!(
            "interrupted; the {} finished passes are in {}",
            result.passes,
            exr.display()
        );
    }
    Ok(())
}
