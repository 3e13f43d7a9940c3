//! The lecture's two families of GI algorithms side by side: unbiased (path
//! tracing, bidirectional path tracing) and biased (photon mapping, SPPM,
//! instant radiosity, irradiance caching), each run with an amount of work
//! `n` and timed as a whole — what chapter 9 puts at equal time.
//!
//! For the unbiased algorithms and SPPM the work is the samples per pixel
//! (SPPM: passes, each with its own photons). Photon mapping, instant
//! radiosity and irradiance caching first build something once — photon
//! maps, virtual point lights, cache records — and then render `n` samples
//! per pixel that all read it: the build is part of every run's time, and
//! its error does not fall with `n` (their curves flatten at it).

use std::sync::atomic::AtomicBool;
use std::time::Instant;

use raytracer::film::Image;
use raytracer::integrator::{
    Bdpt, InstantRadiosity, Integrator, IrradianceCache, IrradianceCacheSettings, PathTracer,
    PhotonMapping, PhotonSettings, VplSettings,
};
use raytracer::render::sppm::SppmSettings;
use raytracer::render::sppm::render_sppm_with_stop;
use raytracer::render::{RenderOptions, render};
use raytracer::scene::Scene;

/// One of the lecture's GI algorithms.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Algorithm {
    Path,
    Bdpt,
    Photon,
    Sppm,
    Vpl,
    IrradianceCache,
}

/// The knobs of the biased algorithms' builds (the unbiased ones have none).
#[derive(Clone, Copy, Debug)]
pub struct Knobs {
    /// Photon mapping: light paths traced once.
    pub photons: u64,
    /// Photon mapping: the k nearest photons of each density estimate.
    pub photon_k: usize,
    /// SPPM: photon paths per pass.
    pub sppm_photons: u64,
    /// Instant radiosity: light paths that leave the VPLs.
    pub vpl_paths: u64,
    /// Instant radiosity: the bound on the geometry term (0: none).
    pub clamp: f32,
    /// Irradiance caching: Ward's error threshold a.
    pub ic_error: f32,
    /// Irradiance caching: hemisphere rays per record.
    pub ic_rays: u32,
}

/// What one run made.
pub struct Run {
    pub image: Image,
    /// Wall-clock seconds, the build included.
    pub seconds: f64,
    /// Samples per pixel (SPPM: passes).
    pub spp: u32,
}

impl Algorithm {
    pub const ALL: [Algorithm; 6] = [
        Algorithm::Path,
        Algorithm::Bdpt,
        Algorithm::Photon,
        Algorithm::Sppm,
        Algorithm::Vpl,
        Algorithm::IrradianceCache,
    ];

    /// Its name on the page.
    pub fn label(self) -> &'static str {
        match self {
            Algorithm::Path => "path tracing",
            Algorithm::Bdpt => "bidirectional",
            Algorithm::Photon => "photon mapping",
            Algorithm::Sppm => "SPPM",
            Algorithm::Vpl => "instant radiosity",
            Algorithm::IrradianceCache => "irradiance caching",
        }
    }

    /// Its `--integrator` name, also its files' name.
    pub fn stem(self) -> &'static str {
        match self {
            Algorithm::Path => "path",
            Algorithm::Bdpt => "bdpt",
            Algorithm::Photon => "photon",
            Algorithm::Sppm => "sppm",
            Algorithm::Vpl => "vpl",
            Algorithm::IrradianceCache => "irradiance-cache",
        }
    }

    /// The lecture's split: unbiased (the error is only noise) or biased.
    pub fn unbiased(self) -> bool {
        matches!(self, Algorithm::Path | Algorithm::Bdpt)
    }

    /// Builds what the algorithm builds once (for `seed`), timed; `None`
    /// for SPPM, whose photons belong to its passes.
    pub fn prepare(
        self,
        scene: &Scene,
        knobs: &Knobs,
        max_depth: u32,
        seed: u64,
    ) -> Result<Prepared, String> {
        let (max_depth, rr_depth) = (Some(max_depth), scene.settings.rr_depth);
        let never = AtomicBool::new(false);
        let start = Instant::now();
        let integrator: Option<Box<dyn Integrator>> = match self {
            Algorithm::Path => Some(Box::new(PathTracer {
                max_depth,
                rr_depth,
                ..PathTracer::default()
            })),
            Algorithm::Bdpt => Some(Box::new(Bdpt {
                max_depth,
                rr_depth,
                strategy_images: None,
            })),
            Algorithm::Photon => Some(Box::new(PhotonMapping::build(
                scene,
                PhotonSettings {
                    photons: knobs.photons,
                    k: knobs.photon_k,
                    max_depth,
                    rr_depth,
                    seed,
                    ..PhotonSettings::default()
                },
                &never,
            )?)),
            Algorithm::Vpl => Some(Box::new(InstantRadiosity::build(
                scene,
                VplSettings {
                    paths: knobs.vpl_paths,
                    clamp: knobs.clamp,
                    max_depth,
                    rr_depth,
                    seed,
                },
                &never,
            )?)),
            Algorithm::IrradianceCache => Some(Box::new(IrradianceCache::build(
                scene,
                IrradianceCacheSettings {
                    error: knobs.ic_error,
                    rays: knobs.ic_rays,
                    max_depth,
                    rr_depth,
                    seed,
                    gradients: false,
                },
                &never,
            )?)),
            Algorithm::Sppm => None,
        };
        Ok(Prepared {
            integrator,
            sppm: SppmSettings {
                photons: knobs.sppm_photons,
                max_depth,
                rr_depth,
                ..SppmSettings::default()
            },
            build_seconds: start.elapsed().as_secs_f64(),
            seed,
        })
    }
}

/// An algorithm ready to render: its integrator with what it built.
pub struct Prepared {
    integrator: Option<Box<dyn Integrator>>,
    sppm: SppmSettings,
    /// Seconds the build took (0 for the unbiased algorithms).
    pub build_seconds: f64,
    seed: u64,
}

impl Prepared {
    /// Renders `n` samples per pixel (SPPM: passes) with `base`'s threads,
    /// timed with the build.
    pub fn run(&self, scene: &Scene, base: &RenderOptions, n: u32) -> Run {
        let options = RenderOptions {
            spp: n.max(1),
            seed: self.seed,
            progress: false,
            ..base.clone()
        };
        let (image, seconds) = match &self.integrator {
            Some(integrator) => {
                let r = render(scene, integrator.as_ref(), &options);
                (r.film.image(), r.stats.elapsed.as_secs_f64())
            }
            None => {
                let r = render_sppm_with_stop(scene, &self.sppm, &options, &AtomicBool::new(false));
                (r.image, r.stats.elapsed.as_secs_f64())
            }
        };
        Run {
            image,
            seconds: (seconds + self.build_seconds).max(1e-6),
            spp: options.spp,
        }
    }

    /// The work that fits `budget` seconds, from a run of `n` that took
    /// `seconds`: the build once, the rest in proportion.
    pub fn fit(&self, n: u32, seconds: f64, budget: f64) -> u32 {
        let per = ((seconds - self.build_seconds) / n.max(1) as f64).max(1e-9);
        (((budget - self.build_seconds) / per) as u32).clamp(1, 1 << 16)
    }
}

/// Its colour on every chart: `Drawn::from(algorithm).color()`.
impl From<Algorithm> for crate::plots::Drawn {
    fn from(a: Algorithm) -> Self {
        use crate::plots::Drawn;
        match a {
            Algorithm::Path => Drawn::Path,
            Algorithm::Bdpt => Drawn::Bdpt,
            Algorithm::Photon => Drawn::Photon,
            Algorithm::Sppm => Drawn::Sppm,
            Algorithm::Vpl => Drawn::Vpl,
            Algorithm::IrradianceCache => Drawn::IrradianceCache,
        }
    }
}
