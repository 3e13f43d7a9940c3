//! What `lesson11 render --student` renders: the student's integrator beside
//! the renderer's of the same estimator.

use std::sync::OnceLock;
use std::sync::atomic::AtomicBool;

use raytracer::film::Splat;
use raytracer::integrator::{
    Bdpt, DirectStrategy, InstantRadiosity, Integrator, LightTracer, NaiveRecursive, PathTracer,
    PhotonMapping, VplSettings,
};
use raytracer::math::{Color, UVec2};
use raytracer::sampling::Sampler;
use raytracer::scene::Scene;

use crate::{ex12_nee, ex13_mis};

use super::*;

/// What `lesson11 render --student` renders: one of the exercises that are
/// whole integrators, with the renderer's integrator that computes the same
/// estimator beside it, so that the two pictures compare like with like
/// (the same expected value *and* the same kind of noise).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum StudentRender {
    /// Exercise 10: naive recursion with one branching factor.
    Naive { max_depth: u32, branching: u32 },
    /// Exercise 11: path tracing with BRDF sampling only.
    Path {
        max_depth: Option<u32>,
        rr_depth: u32,
    },
    /// Exercise 12 (part 2): direct light by next event estimation only.
    Direct,
    /// Exercise 12 (part 3): path tracing with next event estimation.
    PathNee {
        max_depth: Option<u32>,
        rr_depth: u32,
    },
    /// Exercise 13: path tracing with light and BRDF sampling under MIS.
    PathMis {
        max_depth: Option<u32>,
        rr_depth: u32,
    },
    /// Exercise 14: light tracing.
    Light {
        max_depth: Option<u32>,
        rr_depth: u32,
    },
    /// Exercise 15: bidirectional path tracing, every strategy under MIS.
    Bdpt {
        max_depth: Option<u32>,
        rr_depth: u32,
    },
    /// Exercise 16: Metropolis light transport, the student's chains over
    /// bidirectional path tracing of this maximum depth ([`run_chains`]),
    /// beside the renderer's Metropolis over the same
    /// (`raytracer::render::metropolis`). Both are whole-image loops, not
    /// integrators of pixel samples: [`StudentRender::student`] and
    /// [`StudentRender::reference`] give the integrator their chains run
    /// over, and the front-end runs the chains.
    Metropolis {
        max_depth: Option<u32>,
        rr_depth: u32,
    },
    /// Exercise 17: photon mapping (no depth limit, no final gathering);
    /// the fixed radius as `f32::to_bits` (see [`photon_settings`]).
    Photon {
        photons: u64,
        k: usize,
        radius_bits: Option<u32>,
        rr_depth: u32,
        seed: u64,
    },
    /// Exercise 18: instant radiosity, one VPL set of `paths` light paths
    /// traced from `seed`, G clamped at `clamp` (`None`: not clamped).
    Vpl {
        paths: u32,
        clamp: Option<f32>,
        max_depth: Option<u32>,
        rr_depth: u32,
        seed: u64,
    },
}

impl StudentRender {
    /// The exercise's name in the registry.
    pub fn exercise(&self) -> &'static str {
        match self {
            StudentRender::Naive { .. } => "ex10_naive_recursive",
            StudentRender::Path { .. } => "ex11_path_tracing",
            StudentRender::Direct | StudentRender::PathNee { .. } => "ex12_nee",
            StudentRender::PathMis { .. } => "ex13_mis",
            StudentRender::Light { .. } => "ex14_light_tracing",
            StudentRender::Bdpt { .. } => "ex15_bdpt",
            StudentRender::Metropolis { .. } => "ex16_metropolis",
            StudentRender::Photon { .. } => "ex17_photon_mapping",
            StudentRender::Vpl { .. } => "ex18_instant_radiosity",
        }
    }

    /// The student's integrator.
    pub fn student(&self) -> Box<dyn Integrator> {
        match *self {
            StudentRender::Naive {
                max_depth,
                branching,
            } => Box::new(StudentNaive {
                max_depth,
                branching,
            }),
            StudentRender::Path {
                max_depth,
                rr_depth,
            } => Box::new(StudentPathTracer::new(max_depth, rr_depth)),
            StudentRender::Direct => Box::new(StudentDirect::default()),
            StudentRender::PathNee {
                max_depth,
                rr_depth,
            } => Box::new(StudentPathTracer {
                path_radiance: ex12_nee::path_radiance_nee,
                max_depth,
                rr_depth,
            }),
            StudentRender::PathMis {
                max_depth,
                rr_depth,
            } => Box::new(StudentPathTracer {
                path_radiance: ex13_mis::path_radiance_mis,
                max_depth,
                rr_depth,
            }),
            StudentRender::Light {
                max_depth,
                rr_depth,
            } => Box::new(StudentLightTracer::new(max_depth, rr_depth)),
            StudentRender::Bdpt {
                max_depth,
                rr_depth,
            } => Box::new(StudentBdpt::new(max_depth, rr_depth)),
            StudentRender::Metropolis { .. } => self.reference(),
            StudentRender::Photon {
                photons,
                k,
                radius_bits,
                rr_depth,
                seed,
            } => Box::new(StudentPhotonMapping::new(photon_settings(
                photons,
                k,
                radius_bits,
                rr_depth,
                seed,
            ))),
            StudentRender::Vpl {
                paths,
                clamp,
                max_depth,
                rr_depth,
                seed,
            } => Box::new(StudentVpl::new(
                paths,
                clamp,
                max_depth,
                rr_depth,
                VplSets::Shared { seed },
            )),
        }
    }

    /// The renderer's integrator with the same estimator.
    pub fn reference(&self) -> Box<dyn Integrator> {
        match *self {
            StudentRender::Naive {
                max_depth,
                branching,
            } => Box::new(NaiveRecursive::new(vec![branching], Some(max_depth))),
            StudentRender::Path {
                max_depth,
                rr_depth,
            } => Box::new(PathTracer {
                max_depth,
                rr_depth,
                strategy: DirectStrategy::BrdfOnly,
            }),
            StudentRender::Direct => Box::new(PathTracer {
                max_depth: Some(2),
                rr_depth: u32::MAX,
                strategy: DirectStrategy::LightOnly,
            }),
            StudentRender::PathNee {
                max_depth,
                rr_depth,
            } => Box::new(PathTracer {
                max_depth,
                rr_depth,
                strategy: DirectStrategy::LightOnly,
            }),
            StudentRender::PathMis {
                max_depth,
                rr_depth,
            } => Box::new(PathTracer {
                max_depth,
                rr_depth,
                strategy: DirectStrategy::Mis,
            }),
            StudentRender::Light {
                max_depth,
                rr_depth,
            } => Box::new(LightTracer {
                max_depth,
                rr_depth,
            }),
            StudentRender::Bdpt {
                max_depth,
                rr_depth,
            } => Box::new(Bdpt {
                max_depth,
                rr_depth,
                strategy_images: None,
            }),
            StudentRender::Metropolis {
                max_depth,
                rr_depth,
            } => Box::new(Bdpt {
                max_depth,
                rr_depth,
                strategy_images: None,
            }),
            StudentRender::Photon {
                photons,
                k,
                radius_bits,
                rr_depth,
                seed,
            } => {
                let settings = photon_settings(photons, k, radius_bits, rr_depth, seed);
                Box::new(BuiltAtFirstSample::new("photon", move |scene| {
                    PhotonMapping::build(scene, settings, &AtomicBool::new(false))
                        .expect("photon settings checked by the caller")
                }))
            }
            StudentRender::Vpl {
                paths,
                clamp,
                max_depth,
                rr_depth,
                seed,
            } => {
                let settings = VplSettings {
                    paths: paths as u64,
                    clamp: clamp.unwrap_or(0.0),
                    max_depth,
                    rr_depth,
                    seed,
                };
                Box::new(BuiltAtFirstSample::new("vpl", move |scene| {
                    InstantRadiosity::build(scene, settings, &AtomicBool::new(false))
                        .expect("instant radiosity's settings are checked where they are made")
                }))
            }
        }
    }

    /// Which reference it is, and why that one.
    pub fn reference_note(&self) -> &'static str {
        match self {
            StudentRender::Naive { .. } => {
                "the renderer's naive recursion with the same branching factor and max depth"
            }
            StudentRender::Path { .. } => {
                "the renderer's path tracer with BRDF sampling only (`--integrator path-brdf`), the estimator exercise 11 asks for: the same noise is expected. The MIS path tracer (`path`) has the same mean with far less noise, so it would look better than a correct solution"
            }
            StudentRender::Direct => {
                "the renderer's direct light by light sampling only (path-nee at max depth 2), the estimator exercise 12 asks for; `--integrator direct` adds BRDF sampling under MIS: the same mean, less noise"
            }
            StudentRender::PathNee { .. } => {
                "the renderer's path tracer with light sampling only (`--integrator path-nee`), the estimator exercise 12 asks for: the same noise is expected. The MIS path tracer (`path`, exercise 13) has the same mean with less noise on glossy surfaces under large lights"
            }
            StudentRender::PathMis { .. } => {
                "the renderer's path tracer with light and BRDF sampling under the power heuristic (`--integrator path`), the estimator exercise 13 asks for: the same noise is expected"
            }
            StudentRender::Light { .. } => {
                "the renderer's light tracer (`--integrator light`) with the same max depth and roulette depth: the same estimator, so the same noise is expected. Both leave dark what the camera sees only through a mirror or glass (and the environment)"
            }
            StudentRender::Bdpt { .. } => {
                "the renderer's bidirectional path tracer with the same max depth and roulette; its s = 1 strategy takes a fresh light sample where yours joins the light subpath's first vertex: the same mean, nearly the same noise"
            }
            StudentRender::Metropolis { .. } => {
                "the renderer's Metropolis light transport (`--integrator mlt`) over the same bidirectional path tracer: the same estimator, the same streaks; its chains share one bootstrap, yours have one each"
            }
            StudentRender::Photon {
                radius_bits: Some(_),
                ..
            } => {
                "the renderer's photon mapping with the same photon count, radius and roulette, no final gathering: the same estimate (direct light by a light sample, caustics and indirect light from the photons). Each picture has its own photon map, whose noise a single render's variance does not show: with few photons the tile z-test below can flag a difference that is only that (the grader compares over many maps)"
            }
            StudentRender::Photon {
                radius_bits: None, ..
            } => {
                "the renderer's photon mapping with the same photon count, k and roulette, no final gathering; it searches the k nearest in its caustic and global maps apart, yours in one map of both, so the two differ a little in bias where the caustic meets indirect light (with --radius they are the same estimate); each picture has its own photon map, whose noise the tile z-test below does not count"
            }
            StudentRender::Vpl { .. } => {
                "the renderer's instant radiosity (`--integrator vpl`) with the same number of light paths, clamp, depth and seed; it samples the light for direct light where yours gathers the VPLs on the light, and its VPL set is another draw than yours: the same mean over VPL sets, but each picture carries its own set's error, the same in every pixel, which the tile z-test does not see as noise"
            }
        }
    }
}

/// A renderer integrator that is built from the scene (photon maps, VPLs)
/// but asked for before it sees one: built at its first sample, from the
/// scene that sample is of.
pub struct BuiltAtFirstSample<I> {
    name: &'static str,
    build: Box<dyn Fn(&Scene) -> I + Send + Sync>,
    built: OnceLock<I>,
}

impl<I> BuiltAtFirstSample<I> {
    pub fn new(name: &'static str, build: impl Fn(&Scene) -> I + Send + Sync + 'static) -> Self {
        BuiltAtFirstSample {
            name,
            build: Box::new(build),
            built: OnceLock::new(),
        }
    }
}

impl<I: Integrator + Send> Integrator for BuiltAtFirstSample<I> {
    fn name(&self) -> &'static str {
        self.name
    }

    fn sample(
        &self,
        scene: &Scene,
        pixel: UVec2,
        sampler: &mut Sampler,
        splats: &mut Vec<Splat>,
    ) -> Color {
        self.built
            .get_or_init(|| (self.build)(scene))
            .sample(scene, pixel, sampler, splats)
    }
}
