//! Exercise 18: instant radiosity around the student's VPL generation and
//! gather.

use std::sync::OnceLock;

use raytracer::film::Splat;
use raytracer::integrator::photon::photon_sample_index;
use raytracer::integrator::{Integrator, camera_ray};
use raytracer::math::{Color, UVec2, Vec3A};
use raytracer::sampling::Sampler;
use raytracer::scene::{Interaction, Scene};

use crate::ex18_instant_radiosity;

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
