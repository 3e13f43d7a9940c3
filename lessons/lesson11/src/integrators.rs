//! The integrators a command line can choose (`--integrator`) and their
//! options: the lecture's algorithms from direct light to bidirectional path
//! tracing and Metropolis light transport, shared by `lesson11 render`, the
//! lab and the stereo chapter (SPPM and Metropolis only by `render` and the
//! lab's Render tab: they render the whole image in loops of their own, not
//! one pixel sample at a time).
//!
//! Every option is checked before anything is rendered
//! ([`IntegratorKind::plan`]): an option the chosen integrator does not use
//! is an error, not silently ignored, and naive recursion states its
//! worst-case ray count. Every option that multiplies work keeps to one
//! budget ([`crate::options::check_work`]) unless `--force`. What takes long (photon maps, VPLs, irradiance records) is
//! built afterwards ([`IntegratorPlan::build`]) and can be stopped.

pub mod biased;
pub mod build_summary;

pub use biased::{BiasedArgs, BiasedKind, BiasedPlan, render_sppm_to_files};

use std::sync::atomic::AtomicBool;

use anyhow::{Result, bail};
use clap::{Args, ValueEnum};
use raytracer::integrator::{
    AmbientOcclusion, Bdpt, Direct, DirectStrategy, Integrator, LightTracer, NaiveRecursive,
    PathTracer,
};
use raytracer::render::sppm::SppmSettings;
use raytracer::render::{Metropolis, RenderOptions, interrupt_flag, memory_needed};
use raytracer::scene::{Scene, max_depth_from};

use crate::metropolis::MetropolisArgs;
use crate::options::{check_memory, check_work};

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
    /// Naive recursive Monte Carlo: N rays at every hit (see --branching), up to 1 + N + … + N^(D−1) rays per sample.
    Naive,
    /// Light tracing: paths start on the lights and every vertex is connected to the camera.
    Light,
    /// Bidirectional path tracing: camera and light subpaths, every connection, MIS over all of them.
    Bdpt,
    /// Metropolis light transport: Markov chains over bidirectional paths; --spp counts mutations
    /// per pixel (see --chains, --bootstrap, --large-step-probability, --mutation-size).
    Mlt,
    /// Photon mapping (biased): photon maps from light paths, density estimates at the camera's hits.
    Photon,
    /// Stochastic progressive photon mapping (biased but consistent): --spp passes, radii shrinking by --alpha.
    Sppm,
    /// Instant radiosity (biased if clamped): virtual point lights from light paths, gathered with shadow rays.
    Vpl,
    /// Irradiance caching (biased): indirect irradiance at a few records, interpolated (Ward).
    IrradianceCache,
}

/// The max depth of naive recursion when neither the command line nor the
/// scene gives a finite one (an unlimited one must be asked for with
/// `--max-depth -1 --roulette` and a last branching factor of 1).
pub const NAIVE_DEFAULT_DEPTH: u32 = 4;

/// A checked `--integrator` choice, not built yet: what
/// [`IntegratorKind::plan`] makes of the command line.
pub enum IntegratorPlan {
    /// An integrator of pixel samples that needs no preparation.
    Ready(Box<dyn Integrator + Send>),
    /// Photon mapping, instant radiosity or irradiance caching: pixel
    /// samples once their maps, lights or records are built.
    Biased(BiasedPlan),
    /// SPPM: passes of its own (`raytracer::render::sppm`), `--spp` of them.
    Sppm(SppmSettings),
    /// Metropolis light transport: Markov chains over bidirectional path
    /// tracing (`raytracer::render::metropolis`).
    Metropolis(Bdpt, Metropolis),
}

impl IntegratorKind {
    /// The integrator with the command line's options, checked and built;
    /// `options` and `force` decide whether naive recursion stays within its
    /// budget. Ctrl-C stops a build (see [`IntegratorPlan::build`]). SPPM and
    /// Metropolis are refused: they are no integrators of pixel samples.
    pub fn build(
        self,
        args: &IntegratorArgs,
        scene: &Scene,
        options: &RenderOptions,
        force: bool,
    ) -> Result<Box<dyn Integrator + Send>> {
        self.plan(args, scene, options, force)?
            .build(scene, options, interrupt_flag())
    }

    /// Every check of the command line's options for this integrator
    /// (quick, nothing is traced): the plan of the render, or one line on
    /// what is wrong.
    pub fn plan(
        self,
        args: &IntegratorArgs,
        scene: &Scene,
        options: &RenderOptions,
        force: bool,
    ) -> Result<IntegratorPlan> {
        if self == IntegratorKind::Mlt {
            let (bdpt, metropolis) = args.metropolis(scene, options, force)?;
            return Ok(IntegratorPlan::Metropolis(bdpt, metropolis));
        }
        args.check(self)?;
        let max_depth = args.max_depth(self, scene)?;
        let rr_depth = args.rr_depth(scene);
        let path = |strategy| {
            Box::new(PathTracer {
                max_depth,
                rr_depth,
                strategy,
            })
        };
        Ok(IntegratorPlan::Ready(match self {
            IntegratorKind::Direct => Box::new(Direct),
            IntegratorKind::Ao => Box::new(AmbientOcclusion {
                distance: args.ao_distance.unwrap_or(1.0),
            }),
            IntegratorKind::Path => path(DirectStrategy::Mis),
            IntegratorKind::PathBrdf => path(DirectStrategy::BrdfOnly),
            IntegratorKind::PathNee => path(DirectStrategy::LightOnly),
            IntegratorKind::Naive => {
                let naive = NaiveRecursive::try_new(
                    args.branching(),
                    max_depth,
                    args.roulette.then_some(rr_depth),
                    args.cutoff,
                )
                .map_err(|e| anyhow::anyhow!("{e}"))?;
                check_ray_budget(&naive, scene, options, force)?;
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
            IntegratorKind::Sppm => {
                let settings = biased::sppm_plan(&args.biased, scene, max_depth, rr_depth, force)?;
                check_work(
                    "SPPM",
                    settings.photons as f64 * options.spp as f64,
                    lang::pick("light paths", "светлинни пътя"),
                    lang::pick(
                        "--photons (per pass) or --spp (passes)",
                        "--photons (на проход) или --spp (проходи)",
                    ),
                    force,
                )?;
                return Ok(IntegratorPlan::Sppm(settings));
            }
            IntegratorKind::Mlt
            | IntegratorKind::Photon
            | IntegratorKind::Vpl
            | IntegratorKind::IrradianceCache => {
                let Some(kind) = self.biased() else {
                    bail!("{self:?} is not a biased integrator")
                };
                let plan = biased::plan(
                    kind,
                    &args.biased,
                    scene,
                    options.seed,
                    max_depth,
                    rr_depth,
                    force,
                )?;
                plan.check_work(scene, options.spp, force)?;
                return Ok(IntegratorPlan::Biased(plan));
            }
        }))
    }
}

/// Why `--integrator mlt` has no pixel samples.
const MLT_IS_NO_SAMPLER: &str = "--integrator mlt runs Markov chains over the whole image, not one pixel \
     sample at a time: only `lesson11 render --integrator mlt` (and the lab's Render tab) renders with it";

/// Why `--integrator sppm` has no pixel samples.
const SPPM_IS_NO_SAMPLER: &str = "sppm renders in passes of its own, not sample by sample: use \
     `lesson11 render --integrator sppm` (or the lab's Render tab)";

impl IntegratorPlan {
    /// Refuses SPPM and Metropolis where pixel samples are needed (they
    /// render the whole image in loops of their own).
    pub fn check_pixel_samples(&self) -> Result<()> {
        match self {
            IntegratorPlan::Sppm(_) => bail!(SPPM_IS_NO_SAMPLER),
            IntegratorPlan::Metropolis(..) => bail!(MLT_IS_NO_SAMPLER),
            IntegratorPlan::Ready(_) | IntegratorPlan::Biased(_) => Ok(()),
        }
    }

    /// The integrator of pixel samples: built now for the biased ones
    /// (their maps, lights or records, on `options.threads` threads, ended
    /// early once `stop` is set), refused for SPPM and Metropolis.
    pub fn build(
        self,
        scene: &Scene,
        options: &RenderOptions,
        stop: &AtomicBool,
    ) -> Result<Box<dyn Integrator + Send>> {
        match self {
            IntegratorPlan::Ready(integrator) => Ok(integrator),
            IntegratorPlan::Biased(plan) => Ok(plan.build(scene, options, stop)?.0),
            IntegratorPlan::Sppm(_) => bail!(SPPM_IS_NO_SAMPLER),
            IntegratorPlan::Metropolis(..) => bail!(MLT_IS_NO_SAMPLER),
        }
    }
}

impl IntegratorKind {
    /// False for SPPM and Metropolis, which render the whole image in
    /// loops of their own (see [`IntegratorPlan::check_pixel_samples`]).
    pub fn renders_pixel_samples(self) -> bool {
        !matches!(self, IntegratorKind::Sppm | IntegratorKind::Mlt)
    }

    /// The biased integrator this is, if it is one.
    pub fn biased(self) -> Option<BiasedKind> {
        match self {
            IntegratorKind::Photon => Some(BiasedKind::Photon),
            IntegratorKind::Sppm => Some(BiasedKind::Sppm),
            IntegratorKind::Vpl => Some(BiasedKind::Vpl),
            IntegratorKind::IrradianceCache => Some(BiasedKind::IrradianceCache),
            _ => None,
        }
    }
}

/// Prints the worst-case ray count of a naive recursive render and refuses
/// more than the work budget unless `force`.
fn check_ray_budget(
    naive: &NaiveRecursive,
    scene: &Scene,
    options: &RenderOptions,
    force: bool,
) -> Result<()> {
    let depth = naive.max_depth().map_or_else(
        || lang::pick("unlimited", "без граница").to_string(),
        |d| d.to_string(),
    );
    let Some(per_sample) = naive.rays_per_sample_bound() else {
        let ends = match (naive.roulette_depth().is_some(), lang::current()) {
            (true, lang::Lang::En) => "Russian roulette",
            (false, lang::Lang::En) => "the cutoff",
            (true, lang::Lang::Bg) => "руската рулетка",
            (false, lang::Lang::Bg) => "прагът (cutoff)",
        };
        crate::console::say!(
            "{}",
            lang::fill(
                lang::pick(
                    "naive recursion (N = {n}, D = {depth}): no bound on the rays per sample; {ends} ends the recursion",
                    "наивна рекурсия (N = {n}, D = {depth}): няма граница на лъчите за проба; рекурсията я спира {ends}",
                ),
                &[
                    ("n", &format!("{:?}", naive.branching())),
                    ("depth", &depth),
                    ("ends", &ends),
                ]
            )
        );
        return Ok(());
    };
    let samples = scene.camera.width as f64 * scene.camera.height as f64 * options.spp as f64;
    let total = per_sample as f64 * samples;
    // The bound saturates at u64::MAX ("18446744073709551615 rays").
    let per_sample = if per_sample == u64::MAX {
        format!(
            "{} {:.1e}",
            lang::pick("more than", "повече от"),
            u64::MAX as f64
        )
    } else {
        per_sample.to_string()
    };
    crate::console::say!(
        "{}",
        lang::fill(
            lang::pick(
                "naive recursion (N = {n}, D = {depth}): at most {per_sample} rays per sample, {total} rays for {w}×{h} at {spp} spp",
                "наивна рекурсия (N = {n}, D = {depth}): най-много {per_sample} лъча за проба, {total} лъча за {w}×{h} при {spp} spp",
            ),
            &[
                ("n", &format!("{:?}", naive.branching())),
                ("depth", &depth),
                ("per_sample", &per_sample),
                ("total", &format!("{total:.2e}")),
                ("w", &scene.camera.width),
                ("h", &scene.camera.height),
                ("spp", &options.spp),
            ]
        )
    );
    check_work(
        lang::pick("naive recursion", "наивната рекурсия"),
        total,
        lang::pick("rays", "лъча"),
        lang::pick(
            "--branching, --max-depth, --spp or the image size",
            "--branching, --max-depth, --spp или размера на картината",
        ),
        force,
    )
}

/// Options of the integrators.
#[derive(Args, Debug, Clone, Default)]
pub struct IntegratorArgs {
    /// Maximum path depth D, Mitsuba's convention: 1 = emitters seen directly, 2 = direct light,
    /// D = at most D−1 bounces, −1 = unlimited; at most 65535, as in a scene file (default: the
    /// scene's; naive recursion: 4 unless the scene's is finite). Not for direct or ao.
    #[arg(long, allow_negative_numbers = true)]
    pub max_depth: Option<i64>,
    /// Russian roulette may end paths after this many bounces (default: the scene's). Not for direct or ao.
    #[arg(long)]
    pub rr_depth: Option<u32>,
    /// Naive recursion: branching factor N, one per level (the last repeats), e.g. 16,4,2 (default: 8).
    #[arg(long, value_delimiter = ',')]
    pub branching: Vec<u32>,
    /// Naive recursion: end by Russian roulette (unbiased) from --rr-depth on.
    #[arg(long)]
    pub roulette: bool,
    /// Naive recursion: stop once the product of BRDF weights is below this (the lecture's idea; biased).
    #[arg(long, allow_negative_numbers = true)]
    pub cutoff: Option<f32>,
    /// Ambient occlusion: length of the occlusion rays, in scene units (metres; default 1).
    #[arg(long, allow_negative_numbers = true)]
    pub ao_distance: Option<f32>,
    #[command(flatten)]
    pub metropolis: MetropolisArgs,
    #[command(flatten)]
    pub biased: BiasedArgs,
}

impl IntegratorArgs {
    /// Refuses options that `kind` does not use, and values that mean nothing.
    fn check(&self, kind: IntegratorKind) -> Result<()> {
        use IntegratorKind::{Ao, Direct, Naive};
        let name = kind
            .to_possible_value()
            .map_or_else(String::new, |v| v.get_name().to_string());
        let unused = |option: &str, why: &str| -> Result<()> {
            bail!("{option} does not apply to --integrator {name}: {why}")
        };
        if matches!(kind, Direct | Ao) {
            let why = if kind == Direct {
                "direct lighting is D = 2 by definition (emitters seen directly and one bounce); \
                 for another depth use --integrator path --max-depth D"
            } else {
                "ambient occlusion traces one occlusion ray, no paths"
            };
            if self.max_depth.is_some() {
                unused("--max-depth", why)?;
            }
            if self.rr_depth.is_some() {
                unused("--rr-depth", why)?;
            }
        }
        if kind != Naive {
            let why = "it is an option of --integrator naive";
            if !self.branching.is_empty() {
                unused("--branching", why)?;
            }
            if self.roulette {
                unused("--roulette", why)?;
            }
            if self.cutoff.is_some() {
                unused("--cutoff", why)?;
            }
        }
        if kind != Ao && self.ao_distance.is_some() {
            unused("--ao-distance", "it is an option of --integrator ao")?;
        }
        if kind != IntegratorKind::Mlt {
            crate::metropolis::refuse_unused(&self.metropolis, &name)?;
        }
        self.biased.check(kind.biased(), &name)?;
        if self.branching.contains(&0) {
            bail!("--branching factors must be at least 1");
        }
        if let Some(c) = self.cutoff
            && !(c.is_finite() && c >= 0.0)
        {
            bail!("--cutoff must be a number ≥ 0 (a product of BRDF weights), got {c}");
        }
        if let Some(d) = self.ao_distance
            && !(d.is_finite() && d > 0.0)
        {
            bail!("--ao-distance must be a positive distance, got {d}");
        }
        Ok(())
    }

    /// The branching factors of naive recursion (8 if none were given).
    pub fn branching(&self) -> Vec<u32> {
        if self.branching.is_empty() {
            vec![8]
        } else {
            self.branching.clone()
        }
    }

    /// The max depth D (`None`: unlimited) for `kind`: `--max-depth` under
    /// the scene file's rule, else the scene's. Naive recursion takes
    /// [`NAIVE_DEFAULT_DEPTH`] where neither gives a finite depth, and an
    /// unlimited one only with `--roulette` (it would never end).
    pub fn max_depth(&self, kind: IntegratorKind, scene: &Scene) -> Result<Option<u32>> {
        let given = match self.max_depth {
            Some(d) => Some(max_depth_from(d).map_err(|e| anyhow::anyhow!("--max-depth {e}"))?),
            None => None,
        };
        if kind != IntegratorKind::Naive {
            return Ok(given.unwrap_or(scene.settings.max_depth));
        }
        match given {
            Some(None) if !self.roulette => bail!(
                "naive recursion with --max-depth -1 (unlimited) never ends: add --roulette \
                 with a last branching factor of 1 (e.g. --branching 8,1), or give a depth \
                 such as --max-depth 4"
            ),
            Some(d) => Ok(d),
            None => Ok(Some(
                scene.settings.max_depth.unwrap_or(NAIVE_DEFAULT_DEPTH),
            )),
        }
    }

    /// Metropolis light transport (`--integrator mlt`): the integrator its
    /// chains run over, bidirectional path tracing with the depth options,
    /// and its parameters for `options.spp` mutations per pixel, all checked,
    /// with the memory the chains and the bootstrap need (the cap doubles
    /// with `force`).
    pub fn metropolis(
        &self,
        scene: &Scene,
        options: &RenderOptions,
        force: bool,
    ) -> Result<(Bdpt, Metropolis)> {
        let kind = IntegratorKind::Mlt;
        self.check(kind)?;
        let bdpt = Bdpt {
            max_depth: self.max_depth(kind, scene)?,
            rr_depth: self.rr_depth(scene),
            strategy_images: None,
        };
        let pixels = scene.camera.width as u64 * scene.camera.height as u64;
        let metropolis = self.metropolis.metropolis(options.spp as u64 * pixels)?;
        let (w, h) = (scene.camera.width, scene.camera.height);
        let threads = options
            .threads
            .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()));
        let bytes = metropolis
            .memory_needed(w, h, threads)
            .and_then(|m| m.checked_add(memory_needed(w, h)?));
        check_memory(
            &lang::fill(
                lang::pick(
                    "Metropolis light transport at {w}×{h} on {threads} threads with {paths} bootstrap paths",
                    "Metropolis light transport при {w}×{h} на {threads} нишки с {paths} пътя за bootstrap",
                ),
                &[
                    ("w", &w),
                    ("h", &h),
                    ("threads", &threads),
                    ("paths", &metropolis.bootstrap_paths(w, h)),
                ],
            ),
            bytes,
            lang::pick(
                "--width and --height, --bootstrap or --threads",
                "--width и --height, --bootstrap или --threads",
            ),
            force,
        )?;
        // Each mutation and each bootstrap path is one bidirectional sample.
        check_work(
            "Metropolis light transport",
            options.spp as f64 * pixels as f64 + metropolis.bootstrap_paths(w, h) as f64,
            lang::pick(
                "bidirectional paths (mutations and bootstrap)",
                "двупосочни пътя (мутации и bootstrap)",
            ),
            lang::pick(
                "--spp, --bootstrap or the image size",
                "--spp, --bootstrap или размера на картината",
            ),
            force,
        )?;
        Ok((bdpt, metropolis))
    }

    /// The roulette depth: `--rr-depth`, else the scene's.
    pub fn rr_depth(&self, scene: &Scene) -> u32 {
        self.rr_depth.unwrap_or(scene.settings.rr_depth)
    }
}
