//! The options of the biased integrators (`photon`, `sppm`, `vpl`,
//! `irradiance-cache`), checked before anything is traced ([`plan`],
//! [`sppm_plan`]), and what they build: photon maps, VPLs and the
//! irradiance cache are made before the render ([`BiasedPlan::build`], with
//! a line saying how many and how much memory, stopped by a stop flag);
//! SPPM renders in passes of its own ([`render_sppm_to_files`]).

use std::path::Path;
use std::sync::atomic::AtomicBool;

use anyhow::{Result, bail};
use clap::Args;
use raytracer::integrator::photon::{Photon, PhotonKind, PhotonTracing, trace_light_vertices};
use raytracer::integrator::roulette::MAX_SURVIVAL;
use raytracer::integrator::vpl::Vpl;
use raytracer::integrator::{
    InstantRadiosity, Integrator, IrradianceCache, IrradianceCacheSettings, PhotonMapping,
    PhotonSettings, VplSettings,
};
use raytracer::render::sppm::SppmSettings;
use raytracer::render::{RenderOptions, sppm::render_sppm};
use raytracer::scene::Scene;

use crate::options::{check_memory, check_work, create_dir};
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
    /// irradiance-cache: Ward & Heckbert's gradients: records extrapolate E_i + (n_i × n)·∇_r E_i + (x − x_i)·∇_t E_i from their stratified rays instead of only averaging.
    #[arg(long)]
    pub ic_gradients: bool,
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
        let given: [(&str, bool, &[BiasedKind]); 10] = [
            ("--photons", self.photons.is_some(), &[Photon, Sppm]),
            ("--k", self.k.is_some(), &[Photon]),
            ("--radius", self.radius.is_some(), &[Photon, Sppm]),
            ("--final-gather", self.final_gather.is_some(), &[Photon]),
            ("--alpha", self.alpha.is_some(), &[Sppm]),
            ("--vpl-paths", self.vpl_paths.is_some(), &[Vpl]),
            ("--clamp", self.clamp.is_some(), &[Vpl]),
            ("--ic-error", self.ic_error.is_some(), &[IrradianceCache]),
            ("--ic-rays", self.ic_rays.is_some(), &[IrradianceCache]),
            ("--ic-gradients", self.ic_gradients, &[IrradianceCache]),
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
            gradients: self.ic_gradients,
        };
        s.check().map_err(anyhow::Error::msg)?;
        Ok(s)
    }
}

/// The photons (or VPLs) a light path leaves on average, at most: one per
/// vertex after the light's, and a path has at most `D − 1` of them (one
/// camera segment must still fit, `D` = `max_depth`). Paths have no other
/// cap: without a finite `D` only Russian roulette ends a path that neither
/// escapes nor fails to scatter (a closed white scene). Its first
/// `max(rr_depth, 1)` vertices need no roulette; every further vertex needs
/// one more survival, each with probability at most
/// [`MAX_SURVIVAL`] = 0.95, so the expected count is at most
/// `max(rr_depth, 1) + Σ_{j≥1} 0.95^j = max(rr_depth, 1) + 19` (a closed
/// box of white walls at the default `rr_depth` 5 comes close: 24). One
/// path's count has a standard deviation below 20 (the tail after `rr_depth`
/// is at most geometric with survival 0.95: √0.95/0.05 ≈ 19.5).
fn vertices_per_path(max_depth: Option<u32>, rr_depth: u32) -> u64 {
    let roulette = (MAX_SURVIVAL as f64 / (1.0 - MAX_SURVIVAL as f64)).ceil() as u64;
    let by_roulette = (rr_depth.max(1) as u64).saturating_add(roulette);
    match max_depth {
        Some(d) => by_roulette.min((d as u64).saturating_sub(1).max(1)),
        None => by_roulette,
    }
}

/// Peak bytes per photon while a tracing is gathered: each photon is a
/// (kind, photon) pair of `size_of` 44 bytes, held twice while the batches'
/// vectors are concatenated (its batch's and the whole tracing's), and a
/// vector that grows by doubling may hold up to twice what it uses: 4 × 44
/// bytes. (Splitting them by kind afterwards, and building the maps' grids,
/// holds less: 2 × 44 + 2 × 40, then 40 + 4 + 40.)
const PHOTON_PEAK_BYTES: u64 = 4 * std::mem::size_of::<(PhotonKind, Photon)>() as u64;

/// Peak bytes per virtual point light, by the same count (held twice, each
/// vector up to twice its length; the scaling afterwards reuses the buffer).
const VPL_PEAK_BYTES: u64 = 4 * std::mem::size_of::<Vpl>() as u64;

/// Light paths of the pilot tracing that measures what a scene's light paths
/// leave (a few milliseconds).
const PILOT_PATHS: u64 = 8192;

/// The photons (or VPLs) a light path of `scene` leaves on average, as a
/// number memory can be planned with: the mean of a pilot of
/// [`PILOT_PATHS`] light paths (random numbers of their own), plus 4
/// standard errors of that mean (a path's count has a standard deviation
/// below 20, see [`vertices_per_path`]: 4 · 20/√8192 < 0.9), and never more
/// than the bound [`vertices_per_path`]. Open scenes leave far fewer than the
/// bound (the Cornell box about 3 of its 24). For the `N` ≫ 8192 paths where
/// memory matters, `N` paths then leave fewer than `N` times this number
/// except with a probability below 1e-4.
fn expected_vertices_per_path(scene: &Scene, max_depth: Option<u32>, rr_depth: u32) -> f64 {
    let bound = vertices_per_path(max_depth, rr_depth) as f64;
    let tracing = PhotonTracing {
        paths: PILOT_PATHS,
        max_depth,
        rr_depth,
        seed: 0x9170,
        stream: u64::MAX,
    };
    let pilot = trace_light_vertices(scene, &tracing, &AtomicBool::new(false), |_| Some(()));
    let mean = pilot.items.len() as f64 / pilot.paths.max(1) as f64;
    (mean + 4.0 * 20.0 / (PILOT_PATHS as f64).sqrt()).min(bound)
}

/// What a tracing of `paths` light paths of `scene` needs at its peak
/// (`None`: more than 2⁶⁴ bytes), and the words that say so.
fn tracing_memory(
    scene: &Scene,
    paths: u64,
    max_depth: Option<u32>,
    rr_depth: u32,
    what: &str,
    peak_bytes: u64,
) -> (String, Option<u64>) {
    let per_path = expected_vertices_per_path(scene, max_depth, rr_depth);
    let bytes = paths as f64 * per_path * peak_bytes as f64;
    (
        format!(
            "tracing {paths} light paths (about {per_path:.1} {what} each on average, \
             measured on {PILOT_PATHS})"
        ),
        (bytes < u64::MAX as f64).then_some(bytes.ceil() as u64),
    )
}

/// Runs `work` on `threads` threads (rayon's global pool if `None`).
fn in_pool<R: Send>(threads: Option<usize>, work: impl FnOnce() -> R + Send) -> R {
    match threads.and_then(|n| rayon::ThreadPoolBuilder::new().num_threads(n).build().ok()) {
        Some(pool) => pool.install(work),
        None => work(),
    }
}

/// `photon`, `vpl` or `irradiance-cache` with their settings checked, not
/// built yet: the checks are quick, the build ([`BiasedPlan::build`]) may
/// take long.
#[derive(Clone, Debug)]
pub enum BiasedPlan {
    Photon(PhotonSettings),
    Vpl(VplSettings),
    IrradianceCache(IrradianceCacheSettings),
}

/// A search radius in proportion to the scene: from 1e-5 of its diagonal
/// (below, no photon is ever found and r² underflows to 0) to the diagonal
/// itself (above, every disk holds every photon, and r² of 1e30 overflows:
/// SPPM then wrote NaN pixels and a black PNG with exit 0).
fn check_radius(radius: Option<f32>, scene: &Scene) -> Result<()> {
    let (Some(r), b) = (radius, scene.geometry.bounds()) else {
        return Ok(());
    };
    if b.is_empty() {
        return Ok(());
    }
    let diagonal = b.diagonal().length();
    let smallest = 1e-5 * diagonal;
    if !(smallest..=diagonal).contains(&r) {
        bail!(
            "--radius {r} is out of proportion with the scene, whose diagonal is {diagonal:.3}: \
             give a radius from {smallest:.1e} to {diagonal:.3} (SPPM starts at 1% of the diagonal)"
        );
    }
    Ok(())
}

/// Checks the settings of `photon`, `vpl` or `irradiance-cache` and the
/// memory their build needs (the cap doubles with `force`).
pub fn plan(
    kind: BiasedKind,
    args: &BiasedArgs,
    scene: &Scene,
    seed: u64,
    max_depth: Option<u32>,
    rr_depth: u32,
    force: bool,
) -> Result<BiasedPlan> {
    Ok(match kind {
        BiasedKind::Photon => {
            let s = args.photon(max_depth, rr_depth, seed)?;
            check_radius(s.radius, scene)?;
            let (what, bytes) = tracing_memory(
                scene,
                s.photons,
                max_depth,
                rr_depth,
                "photons",
                PHOTON_PEAK_BYTES,
            );
            check_memory(
                &what,
                bytes,
                lang::pick("--photons (or --max-depth)", "--photons (или --max-depth)"),
                force,
            )?;
            BiasedPlan::Photon(s)
        }
        BiasedKind::Vpl => {
            let s = args.vpl(max_depth, rr_depth, seed)?;
            let (what, bytes) =
                tracing_memory(scene, s.paths, max_depth, rr_depth, "VPLs", VPL_PEAK_BYTES);
            check_memory(
                &what,
                bytes,
                lang::pick(
                    "--vpl-paths (or --max-depth)",
                    "--vpl-paths (или --max-depth)",
                ),
                force,
            )?;
            BiasedPlan::Vpl(s)
        }
        BiasedKind::IrradianceCache => {
            BiasedPlan::IrradianceCache(args.irradiance_cache(max_depth, rr_depth, seed)?)
        }
        BiasedKind::Sppm => bail!("sppm is not built before its render: see `sppm_plan`"),
    })
}

/// SPPM's settings, checked, and the memory of one pass's photons (the cap
/// doubles with `force`).
pub fn sppm_plan(
    args: &BiasedArgs,
    scene: &Scene,
    max_depth: Option<u32>,
    rr_depth: u32,
    force: bool,
) -> Result<SppmSettings> {
    let settings = args.sppm(max_depth, rr_depth)?;
    check_radius(settings.radius, scene)?;
    let (what, bytes) = tracing_memory(
        scene,
        settings.photons,
        settings.max_depth,
        settings.rr_depth,
        "photons",
        PHOTON_PEAK_BYTES,
    );
    check_memory(
        &format!("{what} {}", lang::pick("per pass", "на проход")),
        bytes,
        lang::pick("--photons (or --max-depth)", "--photons (или --max-depth)"),
        force,
    )?;
    Ok(settings)
}

impl BiasedPlan {
    /// Keeps the build and a render of `spp` samples per pixel within the
    /// work budget ([`check_work`]) unless `force`: the photon maps' light
    /// paths and the final gather's rays, the VPLs' shadow rays (one per
    /// VPL per sample, the VPLs estimated as for their memory), the cache's
    /// rays (at most one record per pixel).
    pub fn check_work(&self, scene: &Scene, spp: u32, force: bool) -> Result<()> {
        let pixels = scene.camera.width as f64 * scene.camera.height as f64;
        let samples = pixels * spp as f64;
        match self {
            BiasedPlan::Photon(s) => {
                check_work(
                    "photon mapping",
                    s.photons as f64,
                    lang::pick("light paths", "светлинни пътя"),
                    "--photons",
                    force,
                )?;
                check_work(
                    lang::pick(
                        "photon mapping's final gather",
                        "final gather на photon mapping",
                    ),
                    s.final_gather as f64 * samples,
                    lang::pick("rays", "лъча"),
                    lang::pick(
                        "--final-gather, --spp or the image size",
                        "--final-gather, --spp или размера на картината",
                    ),
                    force,
                )
            }
            BiasedPlan::Vpl(s) => {
                let vpls =
                    s.paths as f64 * expected_vertices_per_path(scene, s.max_depth, s.rr_depth);
                check_work(
                    "instant radiosity",
                    vpls * samples,
                    lang::pick(
                        "shadow rays (one per VPL and sample)",
                        "лъча за сянка (по един на VPL и проба)",
                    ),
                    lang::pick(
                        "--vpl-paths, --spp or the image size",
                        "--vpl-paths, --spp или размера на картината",
                    ),
                    force,
                )
            }
            BiasedPlan::IrradianceCache(s) => check_work(
                lang::pick("the irradiance cache", "irradiance кешът"),
                s.rays as f64 * pixels,
                lang::pick(
                    "rays (--ic-rays for each of up to one record per pixel)",
                    "лъча (--ic-rays за всеки от най-много един запис на пиксел)",
                ),
                lang::pick(
                    "--ic-rays or the image size",
                    "--ic-rays или размера на картината",
                ),
                force,
            ),
        }
    }

    /// What the build makes ("the photon maps"), for a line saying it is under way.
    pub fn what(&self) -> &'static str {
        match self {
            BiasedPlan::Photon(_) => "the photon maps",
            BiasedPlan::Vpl(_) => "the virtual point lights",
            BiasedPlan::IrradianceCache(_) => "the irradiance cache",
        }
    }

    /// Builds the maps, lights or records for `scene` on `options.threads`
    /// threads (rayon's global pool if `None`), ending early once `stop` is
    /// set (whole batches of photon paths, whole levels of the cache: an
    /// interrupted build is only good for an interrupted render). Returns
    /// the integrator and one line on what it holds (printed too, if
    /// `options.progress`).
    pub fn build(
        self,
        scene: &Scene,
        options: &RenderOptions,
        stop: &AtomicBool,
    ) -> Result<(Box<dyn Integrator + Send>, String)> {
        let (integrator, summary): (Box<dyn Integrator + Send>, String) = match self {
            BiasedPlan::Photon(s) => {
                let pm = in_pool(options.threads, || PhotonMapping::build(scene, s, stop))
                    .map_err(anyhow::Error::msg)?;
                let line = super::build_summary::photon_maps(&pm);
                (Box::new(pm), line)
            }
            BiasedPlan::Vpl(s) => {
                let ir = in_pool(options.threads, || InstantRadiosity::build(scene, s, stop))
                    .map_err(anyhow::Error::msg)?;
                let line = super::build_summary::vpls(&ir);
                (Box::new(ir), line)
            }
            BiasedPlan::IrradianceCache(s) => {
                let ic = in_pool(options.threads, || IrradianceCache::build(scene, s, stop))
                    .map_err(anyhow::Error::msg)?;
                let line = super::build_summary::irradiance_cache(&ic);
                (Box::new(ic), line)
            }
        };
        if options.progress {
            crate::console::say!("  {summary}");
        }
        Ok((integrator, summary))
    }
}

/// `lesson11 render --integrator sppm`: `--spp` passes with settings from
/// [`sppm_plan`], then `dir/stem.png` and `.exr` (no variance image: SPPM's
/// pixels are not means of independent samples). An interrupted render
/// writes its finished passes and returns an error.
pub fn render_sppm_to_files(
    scene: &Scene,
    settings: &SppmSettings,
    options: &RenderOptions,
    dir: &Path,
    exposure: f32,
) -> Result<()> {
    create_dir(dir)?;
    let stem = format!("{}-sppm", scene.name);
    let result = render_sppm(scene, settings, options);
    if result.passes == 0 {
        crate::console::say!(
            "  {}: interrupted before any pass was finished; nothing written",
            dir.join(&stem).display()
        );
        bail!("interrupted before any pass was finished");
    }
    let (png, exr) = write_png_and_exr(&result.image, dir, &stem, exposure)?;
    crate::console::say!(
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
