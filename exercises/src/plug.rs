//! Where the student's functions plug into the renderer: integrators and
//! image operations built from renderer pieces plus the exercises, so that
//! `lesson11 render --student` (and the grader) render with the student's code.

use raytracer::camera::{Camera, CameraParams};
use raytracer::film::{Film, Image, Splat};
use raytracer::integrator::{
    Bdpt, DirectStrategy, Integrator, NaiveRecursive, PathTracer, camera_ray,
};
use raytracer::math::{Color, Ray, UVec2};
use raytracer::render::metropolis::chain::{PathSample, evaluate};
use raytracer::sampling::{PrimarySample, Sampler};
use raytracer::scene::{Interaction, Scene};

use crate::{ex01_stereo_eyes, ex02_anaglyph, ex10_naive_recursive, ex11_path_tracing, ex12_nee};

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
}

impl StudentRender {
    /// The exercise's name in the registry.
    pub fn exercise(&self) -> &'static str {
        match self {
            StudentRender::Naive { .. } => "ex10_naive_recursive",
            StudentRender::Path { .. } => "ex11_path_tracing",
            StudentRender::Direct => "ex12_nee",
            StudentRender::Metropolis { .. } => "ex16_metropolis",
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
            StudentRender::Metropolis { .. } => self.reference(),
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
            StudentRender::Metropolis {
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
            StudentRender::Metropolis { .. } => {
                "the renderer's Metropolis light transport (`--integrator mlt`) over the same bidirectional path tracer: the same estimator, the same streaks; its chains share one bootstrap, yours have one each"
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
