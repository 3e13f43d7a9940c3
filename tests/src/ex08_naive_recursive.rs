//! Grader of exercise 8 (naive recursion): furnace scenes, where the answer
//! is known in closed form, z-tested with the student's own variance.
//!
//! The emitting furnace (`furnace`): a closed sphere of albedo ρ = 0.5
//! emitting L_e = 0.5 inside, so with depth limit D every pixel is
//! `L_e (1 + ρ + … + ρ^{D−1}) = 1 − 0.5^D`. The white furnace: a white
//! Lambert sphere under a sky of 1, every pixel 1 for D ≥ 2.

use raytracer::integrator::camera_ray;
use raytracer::math::{Color, Ray, UVec2};
use raytracer::sampling::Sampler;
use raytracer::scene::Scene;

use crate::stats::MeanVar;

/// The signature of exercise 8.
pub type NaiveFn = fn(&Scene, &Ray, u32, u32, u32, &mut Sampler) -> Color;

/// Camera rays per case.
pub const ESTIMATES: u64 = 1500;

/// A small built-in scene (8×8 pixels: the camera rays cover the image).
pub fn small_scene(name: &str) -> Result<Scene, String> {
    let mut s = Scene::builtin(name).map_err(|e| format!("grader: {e}"))?;
    s.set_resolution(8, 8);
    Ok(s)
}

/// Mean and variance of `estimate` over camera rays through all pixels.
pub fn camera_estimates(
    scene: &Scene,
    seed: u64,
    n: u64,
    mut estimate: impl FnMut(Ray, &mut Sampler) -> Color,
) -> MeanVar {
    let mut stats = MeanVar::default();
    let (w, h) = (scene.camera.width as u64, scene.camera.height as u64);
    for i in 0..n {
        let pixel = UVec2::new((i % w) as u32, ((i / w) % h) as u32);
        let mut sampler = Sampler::new(seed, i, 0);
        let ray = camera_ray(scene, pixel, &mut sampler);
        stats.add(estimate(ray, &mut sampler));
    }
    stats
}

pub fn check(f: NaiveFn) -> Result<(), String> {
    let furnace = small_scene("furnace")?;
    for (d, n) in [(1u32, 3u32), (2, 3), (3, 3), (4, 2)] {
        let exact = 1.0 - 0.5f32.powi(d as i32);
        let stats = camera_estimates(&furnace, 80 + d as u64, ESTIMATES, |ray, s| {
            f(&furnace, &ray, 0, d, n, s)
        });
        stats.check(
            &format!("emitting furnace (L_e = 0.5, ρ = 0.5), max_depth {d}, branching {n}: L = L_e(1 + ρ + … + ρ^(D−1))"),
            Color::splat(exact),
            |r| {
                Some(if d == 1 {
                    "with max_depth = 1 only the emitters seen directly count: L = L_e".to_string()
                } else if r > 1.0 {
                    "too bright: is the sum of the branches divided by N? are the weights f·|cos θ|/pdf?".to_string()
                } else {
                    "too dark: does every level add its emission, and does the recursion go deep enough (stop when depth + 1 >= max_depth)?".to_string()
                })
            },
        )?;
    }
    let white = small_scene("white-furnace")?;
    let stats = camera_estimates(&white, 88, ESTIMATES, |ray, s| f(&white, &ray, 0, 3, 2, s));
    stats.check(
        "white furnace (white Lambert sphere under a sky of 1), max_depth 3, branching 2",
        Color::ONE,
        |_| Some("rays that escape must return scene.escaped_radiance(ray.d)".to_string()),
    )
}
