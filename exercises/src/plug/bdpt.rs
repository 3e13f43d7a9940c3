//! Exercise 15: bidirectional path tracing: the library grows the two subpaths,
//! the student's `connect` and `mis_weight` join and weigh them.

use raytracer::film::Splat;
use raytracer::integrator::Integrator;
use raytracer::integrator::subpath::{camera_subpath, light_subpath};
use raytracer::integrator::vertex::{Vertex, path_vertices, with_subpaths};
use raytracer::math::{Color, UVec2, Vec2};
use raytracer::sampling::Sampler;
use raytracer::scene::Scene;

use crate::ex15_bdpt;

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
