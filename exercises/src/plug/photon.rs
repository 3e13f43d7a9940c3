//! Exercise 17: photon mapping around the student's photon tracer and density
//! estimate.

use std::sync::OnceLock;

use raytracer::brdf::Brdf;
use raytracer::film::Splat;
use raytracer::integrator::photon::{Photon, photon_sample_index};
use raytracer::integrator::photon_map::{PhotonMap, Search, radius_for};
use raytracer::integrator::visible_point::visible_point;
use raytracer::integrator::{Integrator, PhotonSettings, nee};
use raytracer::math::{Color, UVec2};
use raytracer::sampling::Sampler;
use raytracer::scene::{Interaction, Scene};

use crate::ex17_photon_mapping;

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
