//! Exercise 16: Metropolis light transport in primary sample space: the paths
//! the chains run over, the chains' images and film.

use raytracer::film::Film;
use raytracer::integrator::Integrator;
use raytracer::math::{Color, UVec2};
use raytracer::render::metropolis::chain::{PathSample, evaluate};
use raytracer::sampling::{PrimarySample, Sampler};
use raytracer::scene::Scene;

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
