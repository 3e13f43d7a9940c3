//! Where the student's functions plug into the renderer: integrators and
//! image operations built from renderer pieces plus the exercises, so that
//! `lesson11 render --student` (and the grader) render with the student's code.

use raytracer::camera::{Camera, CameraParams};
use raytracer::film::{Image, Splat};
use raytracer::integrator::subpath::{camera_subpath, light_subpath};
use raytracer::integrator::vertex::{Vertex, path_vertices, with_subpaths};
use raytracer::integrator::{
    Bdpt, DirectStrategy, Integrator, NaiveRecursive, PathTracer, camera_ray,
};
use raytracer::math::{Color, Ray, UVec2, Vec2};
use raytracer::sampling::Sampler;
use raytracer::scene::{Interaction, Scene};

use crate::{
    ex01_stereo_eyes, ex02_anaglyph, ex10_naive_recursive, ex11_path_tracing, ex12_nee, ex15_bdpt,
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
    /// Exercise 15: bidirectional path tracing, every strategy under MIS.
    Bdpt {
        max_depth: Option<u32>,
        rr_depth: u32,
    },
}

impl StudentRender {
    /// The exercise's name in the registry.
    pub fn exercise(&self) -> &'static str {
        match self {
            StudentRender::Naive { .. } => "ex10_naive_recursive",
            StudentRender::Path { .. } => "ex11_path_tracing",
            StudentRender::Direct => "ex12_nee",
            StudentRender::Bdpt { .. } => "ex15_bdpt",
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
            StudentRender::Bdpt {
                max_depth,
                rr_depth,
            } => Box::new(StudentBdpt::new(max_depth, rr_depth)),
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
            StudentRender::Bdpt {
                max_depth,
                rr_depth,
            } => Box::new(Bdpt {
                max_depth,
                rr_depth,
                strategy_images: None,
            }),
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
            StudentRender::Bdpt { .. } => {
                "the renderer's bidirectional path tracer with the same max depth and roulette; its s = 1 strategy takes a fresh light sample where yours joins the light subpath's first vertex: the same mean, nearly the same noise"
            }
        }
    }
}
