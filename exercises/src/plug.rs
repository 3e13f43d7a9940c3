//! Where the student's functions plug into the renderer: integrators and
//! image operations built from renderer pieces plus the exercises, so that
//! `lesson11 render --student` (and the grader) render with the student's code.

use std::sync::OnceLock;
use std::sync::atomic::AtomicBool;

use raytracer::camera::{Camera, CameraParams};
use raytracer::film::{Image, Splat};
use raytracer::integrator::photon::photon_sample_index;
use raytracer::integrator::{
    DirectStrategy, InstantRadiosity, Integrator, NaiveRecursive, PathTracer, VplSettings,
    camera_ray,
};
use raytracer::math::{Color, Ray, UVec2, Vec3A};
use raytracer::sampling::Sampler;
use raytracer::scene::{Interaction, Scene};

use crate::{
    ex01_stereo_eyes, ex02_anaglyph, ex10_naive_recursive, ex11_path_tracing, ex12_nee,
    ex18_instant_radiosity,
};

/// The two cameras of a stereo pair ("parallel" method): each eye from
/// exercise 1, looking in the same direction as the middle camera.
pub fn stereo_cameras(camera: &Camera, stereo_separation: f32) -> (Camera, Camera) {
    let (left, right) = ex01_stereo_eyes::stereo_eyes(camera, stereo_separation);
    let eye = |p| {
        let offset = p - camera.position();
        let params = CameraParams {
            position: p,
            look_at: camera.params.look_at + offset,
            ..camera.params
        };
        Camera::new(params, camera.width, camera.height)
    };
    (eye(left), eye(right))
}

/// The anaglyph of two images of the same size, pixel by pixel with exercise 2.
///
/// # Panics
/// If the images differ in size.
pub fn anaglyph_image(left: &Image, right: &Image, desaturation: f32) -> Image {
    assert!(
        left.width == right.width && left.height == right.height,
        "the two eyes' images differ in size"
    );
    Image::from_fn(left.width, left.height, |x, y| {
        ex02_anaglyph::anaglyph(left.get(x, y), right.get(x, y), desaturation)
    })
}

/// Naive recursive Monte Carlo with the student's `naive_radiance` (exercise 10).
#[derive(Clone, Copy, Debug)]
pub struct StudentNaive {
    pub max_depth: u32,
    pub branching: u32,
}

impl Integrator for StudentNaive {
    fn name(&self) -> &'static str {
        "student-naive"
    }

    fn sample(
        &self,
        scene: &Scene,
        pixel: UVec2,
        sampler: &mut Sampler,
        _: &mut Vec<Splat>,
    ) -> Color {
        let ray = camera_ray(scene, pixel, sampler);
        ex10_naive_recursive::naive_radiance(
            scene,
            &ray,
            0,
            self.max_depth,
            self.branching,
            sampler,
        )
    }
}

/// The signature of exercise 11's `path_radiance`.
pub type PathRadianceFn = fn(&Scene, Ray, Option<u32>, u32, &mut Sampler) -> Color;

/// The signature of exercise 12's `estimate_direct`.
pub type EstimateDirectFn = fn(&Scene, &Interaction, &mut Sampler) -> Color;

/// The path tracer around a `path_radiance` (exercise 11): the student's with
/// [`StudentPathTracer::new`], or any other with the same signature (the
/// grader's fixtures).
#[derive(Clone, Copy, Debug)]
pub struct StudentPathTracer {
    pub path_radiance: PathRadianceFn,
    pub max_depth: Option<u32>,
    pub rr_depth: u32,
}

impl StudentPathTracer {
    /// The student's path tracer.
    pub fn new(max_depth: Option<u32>, rr_depth: u32) -> Self {
        StudentPathTracer {
            path_radiance: ex11_path_tracing::path_radiance,
            max_depth,
            rr_depth,
        }
    }
}

impl Integrator for StudentPathTracer {
    fn name(&self) -> &'static str {
        "student-path"
    }

    fn sample(
        &self,
        scene: &Scene,
        pixel: UVec2,
        sampler: &mut Sampler,
        _: &mut Vec<Splat>,
    ) -> Color {
        let ray = camera_ray(scene, pixel, sampler);
        (self.path_radiance)(scene, ray, self.max_depth, self.rr_depth, sampler)
    }
}

/// Direct light by next event estimation only, around an `estimate_direct`
/// (exercise 12; the student's by `Default`): emitters seen directly plus one
/// light sample at the first hit (the renderer's `PathTracer` with
/// `max_depth = 2` and `DirectStrategy::LightOnly` computes the same).
#[derive(Clone, Copy, Debug)]
pub struct StudentDirect(pub EstimateDirectFn);

impl Default for StudentDirect {
    fn default() -> Self {
        StudentDirect(ex12_nee::estimate_direct)
    }
}

impl Integrator for StudentDirect {
    fn name(&self) -> &'static str {
        "student-direct"
    }

    fn sample(
        &self,
        scene: &Scene,
        pixel: UVec2,
        sampler: &mut Sampler,
        _: &mut Vec<Splat>,
    ) -> Color {
        let ray = camera_ray(scene, pixel, sampler);
        let Some(it) = scene.intersect(&ray) else {
            return scene.escaped_radiance(ray.d);
        };
        scene.emitted(&it) + (self.0)(scene, &it, sampler)
    }
}

/// A virtual point light of instant radiosity (exercise 18): a vertex of a
/// light path and the light it stands for.
#[derive(Clone, Copy, Debug)]
pub enum Vpl {
    /// `y_0`, on a light: it sends the light's own emission,
    /// `L_e(y_0, ω)` (`Scene::emitted_by`), towards every `ω`, times
    /// `weight`, the path's throughput at its first vertex, shared by the N
    /// paths (per unit of `L_e`: it is an area, m²).
    Light {
        /// The point `y_0` on the light.
        p: Vec3A,
        /// The light's surface normal at `p` (as `Emission::n` gives it).
        n: Vec3A,
        /// The light's index in `Scene::lights` (for `Scene::emitted_by`).
        light: u32,
        weight: f32,
    },
    /// `y_k` (`k ≥ 1`), where a light path met a surface that is not a
    /// mirror or glass: it reflects the flux `power` that arrived along its
    /// incoming direction with its own BRDF.
    Surface {
        /// The hit: point, normals, `uv`, and `wo`, the unit direction back
        /// along the light path (towards `y_{k−1}`).
        it: Interaction,
        /// `Φ_y`: the path's throughput at `y_k`, shared by the N paths (W).
        power: Color,
        /// `k`: segments from the light.
        segments: u32,
    },
}

/// The signature of exercise 18's `generate_vpls`: scene, number of light
/// paths N, `max_depth`, `rr_depth`, the numbers of the light paths.
pub type GenerateVplsFn = fn(&Scene, u32, Option<u32>, u32, &mut Sampler) -> Vec<Vpl>;

/// The signature of exercise 18's `gather`: scene, camera hit, VPLs, clamp.
pub type GatherFn = fn(&Scene, &Interaction, &[Vpl], Option<f32>) -> Color;

/// Which VPLs a pixel sample of [`StudentVpl`] gathers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VplSets {
    /// One set for the whole image, traced once from `seed` (instant
    /// radiosity as the lecture shows it: every pixel sees the same VPLs, so
    /// their error is the same in every pixel and the noise does not show it).
    Shared { seed: u64 },
    /// A new set for every pixel sample, traced with the sample's own
    /// numbers: the samples are independent, so a pixel's variance includes
    /// the randomness of the VPLs (what the grader compares).
    PerSample,
}

/// Instant radiosity around `generate_vpls` and `gather` (exercise 18; the
/// student's with [`StudentVpl::new`]): at the first camera hit `x`, its own
/// emission plus the light of the VPLs, gathered at `x`. A mirror or glass
/// seen directly shows its emission only (the gather needs a BRDF to
/// evaluate); lights are area lights.
#[derive(Debug)]
pub struct StudentVpl {
    pub generate_vpls: GenerateVplsFn,
    pub gather: GatherFn,
    /// Light paths per VPL set (N).
    pub paths: u32,
    /// The bound on the geometry term (`None`: no clamping).
    pub clamp: Option<f32>,
    pub max_depth: Option<u32>,
    pub rr_depth: u32,
    pub sets: VplSets,
    /// The shared set, traced at the first sample (the integrator is built
    /// before it sees the scene).
    shared: OnceLock<Vec<Vpl>>,
}

impl StudentVpl {
    /// Instant radiosity with the given functions.
    pub fn with(
        generate_vpls: GenerateVplsFn,
        gather: GatherFn,
        paths: u32,
        clamp: Option<f32>,
        max_depth: Option<u32>,
        rr_depth: u32,
        sets: VplSets,
    ) -> Self {
        StudentVpl {
            generate_vpls,
            gather,
            paths,
            clamp,
            max_depth,
            rr_depth,
            sets,
            shared: OnceLock::new(),
        }
    }

    /// The student's instant radiosity.
    pub fn new(
        paths: u32,
        clamp: Option<f32>,
        max_depth: Option<u32>,
        rr_depth: u32,
        sets: VplSets,
    ) -> Self {
        Self::with(
            ex18_instant_radiosity::generate_vpls,
            ex18_instant_radiosity::gather,
            paths,
            clamp,
            max_depth,
            rr_depth,
            sets,
        )
    }
}

impl Integrator for StudentVpl {
    fn name(&self) -> &'static str {
        "student-vpl"
    }

    fn sample(
        &self,
        scene: &Scene,
        pixel: UVec2,
        sampler: &mut Sampler,
        _: &mut Vec<Splat>,
    ) -> Color {
        if self.max_depth == Some(0) {
            return Color::ZERO;
        }
        let ray = camera_ray(scene, pixel, sampler);
        let Some(x) = scene.intersect(&ray) else {
            return scene.escaped_radiance(ray.d);
        };
        let le = scene.emitted(&x);
        if self.max_depth.is_some_and(|d| d < 2) || scene.brdf(&x).is_delta() {
            return le;
        }
        let fresh;
        let vpls: &[Vpl] = match self.sets {
            VplSets::Shared { seed } => self.shared.get_or_init(|| {
                let mut s = Sampler::new(seed, 0, photon_sample_index(1));
                (self.generate_vpls)(scene, self.paths, self.max_depth, self.rr_depth, &mut s)
            }),
            VplSets::PerSample => {
                fresh =
                    (self.generate_vpls)(scene, self.paths, self.max_depth, self.rr_depth, sampler);
                &fresh
            }
        };
        le + (self.gather)(scene, &x, vpls, self.clamp)
    }
}

/// The renderer's instant radiosity ([`InstantRadiosity`]), its VPLs traced
/// at the first sample from the scene it is given (the integrator is built
/// before it sees the scene).
#[derive(Debug)]
pub struct LazyInstantRadiosity {
    pub settings: VplSettings,
    built: OnceLock<InstantRadiosity>,
}

impl LazyInstantRadiosity {
    pub fn new(settings: VplSettings) -> Self {
        LazyInstantRadiosity {
            settings,
            built: OnceLock::new(),
        }
    }
}

impl Integrator for LazyInstantRadiosity {
    fn name(&self) -> &'static str {
        "vpl"
    }

    fn sample(
        &self,
        scene: &Scene,
        pixel: UVec2,
        sampler: &mut Sampler,
        splats: &mut Vec<Splat>,
    ) -> Color {
        self.built
            .get_or_init(|| {
                InstantRadiosity::build(scene, self.settings, &AtomicBool::new(false))
                    .expect("instant radiosity's settings are checked where they are made")
            })
            .sample(scene, pixel, sampler, splats)
    }
}

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
    /// Exercise 12: direct light by next event estimation only.
    Direct,
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
            StudentRender::Direct => "ex12_nee",
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
            StudentRender::Vpl {
                paths,
                clamp,
                max_depth,
                rr_depth,
                seed,
            } => Box::new(LazyInstantRadiosity::new(VplSettings {
                paths: paths as u64,
                clamp: clamp.unwrap_or(0.0),
                max_depth,
                rr_depth,
                seed,
            })),
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
            StudentRender::Vpl { .. } => {
                "the renderer's instant radiosity (`--integrator vpl`) with the same number of light paths, clamp, depth and seed; it samples the light for direct light where yours gathers the VPLs on the light, and its VPL set is another draw than yours: the same mean over VPL sets, but each picture carries its own set's error, the same in every pixel, which the tile z-test does not see as noise"
            }
        }
    }
}
