//! The integrators a command line can choose (`--integrator`) and their
//! options: the lecture's algorithms from direct light to bidirectional path
//! tracing, shared by `lesson11 render` and the stereo chapter.

use clap::{Args, ValueEnum};
use raytracer::integrator::{
    AmbientOcclusion, Bdpt, Direct, DirectStrategy, Integrator, LightTracer, NaiveRecursive,
    PathTracer,
};
use raytracer::scene::Scene;

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
        let (max_depth, rr_depth) = args.depths(scene);
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

impl IntegratorArgs {
    /// The maximum depth (`None`: unlimited) and the depth where Russian
    /// roulette may start, the scene's where the command line gives none.
    pub fn depths(&self, scene: &Scene) -> (Option<u32>, u32) {
        let max_depth = match self.max_depth {
            Some(d) if d < 0 => None,
            Some(d) => Some(d as u32),
            None => scene.settings.max_depth,
        };
        (max_depth, self.rr_depth.unwrap_or(scene.settings.rr_depth))
    }
}
