//! Where the student's functions plug into the renderer: integrators and
//! image operations built from renderer pieces plus the exercises, so that
//! `lesson11 render --student` (and the grader) render with the student's code.

use std::sync::OnceLock;
use std::sync::atomic::AtomicBool;

use raytracer::brdf::Brdf;
use raytracer::camera::{Camera, CameraParams};
use raytracer::film::{Image, Splat};
use raytracer::integrator::photon::{Photon, photon_sample_index};
use raytracer::integrator::photon_map::{PhotonMap, Search, radius_for};
use raytracer::integrator::visible_point::visible_point;
use raytracer::integrator::{
    DirectStrategy, Integrator, NaiveRecursive, PathTracer, PhotonMapping, PhotonSettings,
    camera_ray, nee,
};
use raytracer::math::{Color, Ray, UVec2};
use raytracer::sampling::Sampler;
use raytracer::scene::{Interaction, Scene};

use crate::{
    ex01_stereo_eyes, ex02_anaglyph, ex10_naive_recursive, ex11_path_tracing, ex12_nee,
    ex17_photon_mapping,
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

/// The signature of exercise 17's `trace_photon_path`.
pub type TracePhotonPathFn = fn(&Scene, u64, u32, &mut Sampler, &mut Vec<Photon>);

/// The signature of exercise 17's `photon_radiance`.
pub type PhotonRadianceFn = fn(&PhotonMap, &Interaction, &Brdf, Search) -> Color;

/// The photons of `paths` light paths traced by `trace` (exercise 17's
/// `trace_photon_path`): path `i` draws from `Sampler::new(seed, i,
/// photon_sample_index(0))`, as the renderer's photon paths do.
pub fn trace_photons_with(
    scene: &Scene,
    trace: TracePhotonPathFn,
    paths: u64,
    rr_depth: u32,
    seed: u64,
) -> Vec<Photon> {
    let mut photons = Vec::new();
    for i in 0..paths {
        let mut sampler = Sampler::new(seed, i, photon_sample_index(0));
        trace(scene, paths, rr_depth, &mut sampler, &mut photons);
    }
    photons
}

/// Photon mapping around exercise 17 (the student's functions by
/// [`StudentPhotonMapping::new`]): the photons of `settings.photons` light
/// paths traced by `trace` (unlimited depth, roulette from
/// `settings.rr_depth`, seed `settings.seed`), those of 2 or more segments
/// kept in one map (built at the first sample, for the scene rendered);
/// each pixel sample follows the camera ray through mirrors and glass to a
/// diffuse or glossy point x, and adds the emission seen on the way, one
/// light sample at x (direct light) and `estimate` at x (caustics and
/// indirect light) — the terms of the renderer's `PhotonMapping` without
/// final gathering, with the caustic and global maps in one (the same
/// estimate with `settings.radius`; with the k nearest, the renderer
/// searches its two maps apart).
pub struct StudentPhotonMapping {
    pub trace: TracePhotonPathFn,
    pub estimate: PhotonRadianceFn,
    pub settings: PhotonSettings,
    map: OnceLock<(PhotonMap, Search)>,
}

impl StudentPhotonMapping {
    /// The student's photon mapping.
    pub fn new(settings: PhotonSettings) -> Self {
        Self::with(
            ex17_photon_mapping::trace_photon_path,
            ex17_photon_mapping::photon_radiance,
            settings,
        )
    }

    /// Photon mapping around any functions with the signatures of exercise 17.
    pub fn with(
        trace: TracePhotonPathFn,
        estimate: PhotonRadianceFn,
        settings: PhotonSettings,
    ) -> Self {
        StudentPhotonMapping {
            trace,
            estimate,
            settings,
            map: OnceLock::new(),
        }
    }

    /// The map (traced and built at the first call) and its search.
    pub fn map(&self, scene: &Scene) -> &(PhotonMap, Search) {
        self.map.get_or_init(|| {
            let s = &self.settings;
            let mut photons = trace_photons_with(scene, self.trace, s.photons, s.rr_depth, s.seed);
            // Direct light comes from the light sample, not from photons.
            photons.retain(|p| p.segments >= 2);
            let search = match s.radius {
                Some(r) => Search::Radius(r),
                None => Search::Nearest {
                    k: s.k,
                    max_radius: radius_for(&photons, s.k, 2.0),
                },
            };
            (PhotonMap::build(photons, search.max_radius()), search)
        })
    }
}

impl Integrator for StudentPhotonMapping {
    fn name(&self) -> &'static str {
        "student-photon"
    }

    fn sample(
        &self,
        scene: &Scene,
        pixel: UVec2,
        sampler: &mut Sampler,
        _: &mut Vec<Splat>,
    ) -> Color {
        let (map, search) = self.map(scene);
        let vp = visible_point(scene, pixel, sampler, None);
        let Some(it) = vp.hit else {
            return vp.le;
        };
        let brdf = scene.brdf(&it);
        let direct = nee::sample_light(scene, &it, brdf, sampler, false);
        vp.le + vp.beta * (direct + (self.estimate)(map, &it, brdf, *search))
    }
}

/// The renderer's photon mapping, its maps built at the first sample (for
/// the scene rendered).
pub struct LazyPhotonMapping {
    pub settings: PhotonSettings,
    built: OnceLock<PhotonMapping>,
}

impl LazyPhotonMapping {
    pub fn new(settings: PhotonSettings) -> Self {
        LazyPhotonMapping {
            settings,
            built: OnceLock::new(),
        }
    }
}

impl Integrator for LazyPhotonMapping {
    fn name(&self) -> &'static str {
        "photon"
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
                PhotonMapping::build(scene, self.settings, &AtomicBool::new(false))
                    .expect("photon settings checked by the caller")
            })
            .sample(scene, pixel, sampler, splats)
    }
}

/// Exercise 17's settings in [`StudentRender::Photon`]: no depth limit, no
/// final gathering; `radius_bits` is `f32::to_bits` of the fixed radius.
pub fn photon_settings(
    photons: u64,
    k: usize,
    radius_bits: Option<u32>,
    rr_depth: u32,
    seed: u64,
) -> PhotonSettings {
    PhotonSettings {
        photons,
        k,
        radius: radius_bits.map(f32::from_bits),
        final_gather: 0,
        max_depth: None,
        rr_depth,
        seed,
    }
}

/// What `lesson11 render --student` renders: one of the exercises that are
/// whole integrators, with the renderer's integrator that computes the same
/// estimator beside it, so that the two pictures compare like with like
/// (the same expected value *and* the same kind of noise).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
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
    /// Exercise 17: photon mapping (no depth limit, no final gathering);
    /// the fixed radius as `f32::to_bits` (see [`photon_settings`]).
    Photon {
        photons: u64,
        k: usize,
        radius_bits: Option<u32>,
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
            StudentRender::Photon { .. } => "ex17_photon_mapping",
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
            StudentRender::Photon {
                photons,
                k,
                radius_bits,
                rr_depth,
                seed,
            } => Box::new(LazyPhotonMapping::new(photon_settings(
                photons,
                k,
                radius_bits,
                rr_depth,
                seed,
            ))),
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
            StudentRender::Direct => {
                "the renderer's direct light by light sampling only (path-nee at max depth 2), the estimator exercise 12 asks for; `--integrator direct` adds BRDF sampling under MIS: the same mean, less noise"
            }
        }
    }
}
