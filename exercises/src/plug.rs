//! Where the student's functions plug into the renderer: integrators and
//! image operations built from renderer pieces plus the exercises, so that
//! `lesson11 render --student` (and the grader) render with the student's code.

use std::sync::OnceLock;
use std::sync::atomic::AtomicBool;

use raytracer::brdf::Brdf;
use raytracer::camera::{Camera, CameraParams};
use raytracer::film::{Film, Image, Splat};
use raytracer::integrator::photon::{Photon, photon_sample_index};
use raytracer::integrator::photon_map::{PhotonMap, Search, radius_for};
use raytracer::integrator::subpath::{camera_subpath, light_subpath};
use raytracer::integrator::vertex::{Vertex, path_vertices, with_subpaths};
use raytracer::integrator::visible_point::visible_point;
use raytracer::integrator::{
    Bdpt, DirectStrategy, InstantRadiosity, Integrator, LightTracer, NaiveRecursive, PathTracer,
    PhotonMapping, PhotonSettings, VplSettings, camera_ray, nee,
};
use raytracer::math::{Color, Ray, UVec2, Vec2, Vec3A};
use raytracer::render::metropolis::chain::{PathSample, evaluate};
use raytracer::sampling::{PrimarySample, Sampler};
use raytracer::scene::{Interaction, Scene};

use crate::{
    ex01_stereo_eyes, ex02_anaglyph, ex10_naive_recursive, ex11_path_tracing, ex12_nee, ex13_mis,
    ex14_light_tracing, ex15_bdpt, ex17_photon_mapping, ex18_instant_radiosity,
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

/// The signature of exercise 11's `path_radiance` (and of exercise 12's
/// `path_radiance_nee` and exercise 13's `path_radiance_mis`).
pub type PathRadianceFn = fn(&Scene, Ray, Option<u32>, u32, &mut Sampler) -> Color;

/// The signature of exercise 12's `estimate_direct`.
pub type EstimateDirectFn = fn(&Scene, &Interaction, &mut Sampler) -> Color;

/// The path tracer around a `path_radiance` (exercise 11): the student's with
/// [`StudentPathTracer::new`], or any other with the same signature (the
/// student's NEE and MIS path tracers of exercises 12 and 13, the grader's
/// fixtures).
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

/// A point on the camera's lens, where light tracing joins a light-path
/// vertex to the camera (exercise 14).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LensPoint {
    /// The point, in world space.
    pub p: Vec3A,
    /// Its density per unit area of the lens. A pinhole is a single point,
    /// taken as a lens of area 1 (density 1), as [`Camera::we`] counts it.
    pub pdf_a: f32,
}

/// A lens point chosen by `u_lens`, uniformly on the lens disk of a thin-lens
/// camera (the centre of a pinhole). The lens faces along `Camera::forward`.
pub fn sample_lens(camera: &Camera, u_lens: Vec2) -> LensPoint {
    // The lens point of any primary ray drawn with u_lens: the one through
    // the film's centre.
    let centre = Vec2::new(camera.width as f32, camera.height as f32) * 0.5;
    let ray = camera.generate_ray(centre, u_lens);
    LensPoint {
        p: ray.o,
        pdf_a: camera.pdf_we(&ray).pdf_a,
    }
}

/// The signature of exercise 14's `trace_light_path`.
pub type LightPathFn = fn(&Scene, &mut Sampler, Option<u32>, u32, &mut Vec<Splat>);

/// The light tracer around a `trace_light_path` (exercise 14; the student's
/// with [`StudentLightTracer::new`]): every pixel sample traces one light
/// path and returns 0 — everything it finds, the lights seen directly
/// included, reaches the film as splats, which the film scales by `W·H/M`
/// (M pixel samples in all), as for the renderer's `LightTracer`.
#[derive(Clone, Copy, Debug)]
pub struct StudentLightTracer {
    pub trace_light_path: LightPathFn,
    pub max_depth: Option<u32>,
    pub rr_depth: u32,
}

impl StudentLightTracer {
    /// The student's light tracer.
    pub fn new(max_depth: Option<u32>, rr_depth: u32) -> Self {
        StudentLightTracer {
            trace_light_path: ex14_light_tracing::trace_light_path,
            max_depth,
            rr_depth,
        }
    }
}

impl Integrator for StudentLightTracer {
    fn name(&self) -> &'static str {
        "student-light"
    }

    fn sample(
        &self,
        scene: &Scene,
        _: UVec2,
        sampler: &mut Sampler,
        splats: &mut Vec<Splat>,
    ) -> Color {
        (self.trace_light_path)(scene, sampler, self.max_depth, self.rr_depth, splats);
        Color::ZERO
    }
}

/// What exercise 15's `connect` returns: the unweighted contribution of one
/// strategy `(s, t)` and, for `t = 1`, where it lands.
#[derive(Clone, Copy, Debug)]
pub struct BdptConnection {
    /// The strategy's unweighted contribution `C_{s,t}` (radiance: a pixel
    /// value before the MIS weight).
    pub value: Color,
    /// `t = 1` only: the raster position where the light vertex is seen; the
    /// contribution is splatted there instead of being added to the pixel
    /// that made the sample. `None` for `t ≥ 2`.
    pub raster: Option<Vec2>,
    /// `t = 1` only: the lens point the connection used (built by
    /// `Vertex::camera`); it takes the place of the camera subpath's `z_0` in
    /// the MIS weight. `None` for `t ≥ 2`.
    pub lens: Option<Vertex>,
}

/// The signature of exercise 15's `connect`: scene, light subpath, camera
/// subpath, `s`, `t`, sampler.
pub type ConnectFn =
    fn(&Scene, &[Vertex], &[Vertex], usize, usize, &mut Sampler) -> Option<BdptConnection>;

/// The signature of exercise 15's `mis_weight`: scene, light subpath, camera
/// subpath, `s`, `t`, the lens point of a `t = 1` connection.
pub type BdptWeightFn = fn(&Scene, &[Vertex], &[Vertex], usize, usize, Option<Vertex>) -> f32;

/// Bidirectional path tracing around a `connect` and a `mis_weight`
/// (exercise 15; the student's with [`StudentBdpt::new`]): the library grows
/// the camera subpath (up to `D + 1` vertices) and the light subpath (up to
/// `D`), the student's code joins every prefix pair `(s, t)` with
/// `s + t ≤ D + 1` and weights it. A camera subpath that escapes adds the
/// environment with weight 1 (no other strategy makes such paths). Unlike the
/// renderer's [`Bdpt`], `s = 1` joins the light subpath's own `y_0` instead of
/// a fresh light sample: the same expected value.
#[derive(Clone, Copy, Debug)]
pub struct StudentBdpt {
    pub connect: ConnectFn,
    pub weight: BdptWeightFn,
    pub max_depth: Option<u32>,
    pub rr_depth: u32,
}

impl StudentBdpt {
    /// The student's bidirectional path tracer.
    pub fn new(max_depth: Option<u32>, rr_depth: u32) -> Self {
        StudentBdpt {
            connect: ex15_bdpt::connect,
            weight: ex15_bdpt::mis_weight,
            max_depth,
            rr_depth,
        }
    }
}

impl Integrator for StudentBdpt {
    fn name(&self) -> &'static str {
        "student-bdpt"
    }

    fn sample(
        &self,
        scene: &Scene,
        pixel: UVec2,
        sampler: &mut Sampler,
        splats: &mut Vec<Splat>,
    ) -> Color {
        let max_vertices = path_vertices(self.max_depth);
        with_subpaths(|camera, light| {
            let escaped =
                camera_subpath(scene, pixel, sampler, camera, max_vertices, self.rr_depth);
            light_subpath(scene, sampler, light, max_vertices - 1, self.rr_depth);
            let mut l = Color::ZERO;
            if let Some(e) = escaped
                && camera.len() < max_vertices
            {
                l += e.beta * scene.escaped_radiance(e.d);
            }
            for t in 1..=camera.len() {
                for s in 0..=light.len() {
                    if s + t < 2 || s + t > max_vertices {
                        continue;
                    }
                    let Some(c) = (self.connect)(scene, light, camera, s, t, sampler) else {
                        continue;
                    };
                    let value = c.value * (self.weight)(scene, light, camera, s, t, c.lens);
                    match c.raster {
                        Some(raster) => splats.push(Splat { raster, value }),
                        None => l += value,
                    }
                }
            }
            l
        })
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
            } => Box::new(LazyPhotonMapping::new(photon_settings(
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

// ── Exercise 16: Metropolis light transport in primary sample space ──

/// What one Metropolis chain is asked to do (exercise 16).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ChainSettings {
    /// The length of a state: how many uniform numbers in `[0, 1)` make
    /// one path.
    pub dimensions: usize,
    /// Independent paths of the bootstrap (at least 1).
    pub bootstrap: usize,
    /// Steps of the chain, `N` (mutations; at least 1).
    pub mutations: u64,
    /// Probability of a large step, in `[0, 1]`.
    pub large_step_probability: f32,
    /// How far a small step moves a number, a fraction of `[0, 1)` (the
    /// scale of its symmetric random offset).
    pub mutation_size: f32,
}

/// The image of one chain: for every pixel, the sum of the contributions
/// splatted into it, each times its weight. Its units are those of the
/// integral of a pixel's contributions over primary sample space (the
/// renderer multiplies by the `W·H` pixels a state can land in).
#[derive(Clone, Debug, PartialEq)]
pub struct ChainImage {
    /// One `[r, g, b]` sum per pixel, index `y·W + x`.
    pub sums: Vec<[f64; 3]>,
}

impl ChainImage {
    /// An image of `pixels` black pixels.
    pub fn new(pixels: usize) -> Self {
        ChainImage {
            sums: vec![[0.0; 3]; pixels],
        }
    }

    /// Adds every contribution of `path` to its pixel, times `weight`.
    pub fn splat(&mut self, path: &PathSample, weight: f64) {
        if weight == 0.0 {
            return;
        }
        for &(j, value) in &path.contributions {
            let s = &mut self.sums[j as usize];
            for (s, v) in s.iter_mut().zip(value.to_array()) {
                *s += weight * v as f64;
            }
        }
    }
}

/// The signature of exercise 16's `metropolis_chain`: the path function
/// (a vector of numbers to what its path brings), the settings, the
/// chain's own random numbers, the image to splat into.
pub type MetropolisChainFn =
    fn(&dyn Fn(&[f32]) -> PathSample, &ChainSettings, &mut Sampler, &mut ChainImage);

/// Primary sample space of a scene: a vector of uniform numbers is the
/// pixel (its first two numbers) and then one sample of `integrator` drawn
/// from the rest (exercise 16's path function).
pub struct PrimaryPaths<'a> {
    pub scene: &'a Scene,
    pub integrator: &'a dyn Integrator,
}

impl PrimaryPaths<'_> {
    /// Numbers a state needs for bidirectional path tracing of maximum
    /// depth `max_depth` (a bound on what one sample reads: the pixel 2, the
    /// camera subpath 4 + 4 per bounce, the light subpath 5 + 4 per bounce,
    /// a connection to the camera 2 per light vertex and a light sample 3
    /// per camera vertex; measured on `door` at depth 5: at most 54 of 79).
    pub fn bdpt_dimensions(max_depth: u32) -> usize {
        let d = max_depth as usize;
        2 + (4 + 4 * d) + (5 + 4 * d) + 2 * d + 3 * (d + 1)
    }

    /// What the path of the numbers `u` brings: its contributions to the
    /// pixels and `f`, the sum of their luminances (the scalar contribution
    /// of the lecture). An integrator that reads past `u` gets the numbers
    /// of a fixed sequence.
    ///
    /// # Panics
    /// If a number is outside `[0, 1)`: a state of primary sample space
    /// never is.
    pub fn evaluate(&self, u: &[f32]) -> PathSample {
        if let Some(bad) = u.iter().find(|v| !(0.0..1.0).contains(*v)) {
            panic!(
                "exercise 16: a state holds the number {bad}, outside [0, 1) — primary sample space is the unit hypercube"
            );
        }
        let mut sampler = Sampler::primary(PrimarySample::from_coordinates(u, 0x16, 0, 0));
        let mut path = PathSample::default();
        let mut splats = Vec::new();
        evaluate(
            self.scene,
            self.integrator,
            &mut sampler,
            &mut splats,
            &mut path,
        );
        path
    }
}

/// Runs `chains` independent chains of `chain` (exercise 16) over
/// `integrator` on `scene`, chain `c` drawing from `Sampler::new(seed, c,
/// 0)`, each with `settings` (its own bootstrap and steps), on all cores;
/// their images in chain order, whichever thread ran them.
pub fn run_chains(
    chain: MetropolisChainFn,
    scene: &Scene,
    integrator: &dyn Integrator,
    settings: &ChainSettings,
    chains: u32,
    seed: u64,
) -> Vec<ChainImage> {
    let pixels = scene.camera.width as usize * scene.camera.height as usize;
    let paths = PrimaryPaths { scene, integrator };
    let evaluate = |u: &[f32]| paths.evaluate(u);
    let run = |c: u32| {
        let mut image = ChainImage::new(pixels);
        chain(
            &evaluate,
            settings,
            &mut Sampler::new(seed, c as u64, 0),
            &mut image,
        );
        image
    };
    let threads = std::thread::available_parallelism()
        .map_or(1, |n| n.get())
        .min(chains.max(1) as usize);
    let next = std::sync::atomic::AtomicU32::new(0);
    let mut images: Vec<(u32, ChainImage)> = std::thread::scope(|s| {
        let workers: Vec<_> = (0..threads)
            .map(|_| {
                s.spawn(|| {
                    let mut done = Vec::new();
                    loop {
                        let c = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                        if c >= chains {
                            break done;
                        }
                        done.push((c, run(c)));
                    }
                })
            })
            .collect();
        workers
            .into_iter()
            .flat_map(|t| t.join().unwrap_or_else(|e| std::panic::resume_unwind(e)))
            .collect()
    });
    images.sort_by_key(|(c, _)| *c);
    images.into_iter().map(|(_, image)| image).collect()
}

/// The film of chains' images of a `width × height` picture: one sample per
/// pixel per chain, that chain's image times `W·H` (a state lands in each
/// pixel with probability `1/(W·H)`). Its image is the render, its variance
/// image the spread of the chains over their number.
pub fn chains_film(images: &[ChainImage], width: u32, height: u32) -> Film {
    let mut film = Film::new(width, height);
    let scale = width as f64 * height as f64;
    for image in images {
        for y in 0..height {
            for x in 0..width {
                let s = image.sums[(y * width + x) as usize];
                let value = Color::new(
                    (s[0] * scale) as f32,
                    (s[1] * scale) as f32,
                    (s[2] * scale) as f32,
                );
                film.add_sample(UVec2::new(x, y), value);
            }
        }
    }
    film
}
