//! Integrators: the algorithms that solve the rendering equation.
//!
//! Lecture topic: global illumination algorithms. Each integrator estimates
//! the radiance of one camera sample; the render loop ([`crate::render`])
//! averages many of them per pixel.
//!
//! The integrators share their steps, one file each: [`nee`] (light
//! sampling and its MIS weight), [`continuation`] (the BRDF sample that
//! continues a path), [`roulette`] (Russian roulette), and for light and
//! bidirectional tracing [`vertex`], [`subpath`], [`camera_connection`],
//! [`mis_weight`] and [`shading_normals`] (the adjoint correction of
//! importance transport). [`dimensions`] names every random number they draw and
//! gives each integrator's layout. [`record`] is the path recorder: what one
//! sample traced, for the lab's inspector and the slides' path figures.

use crate::film::Splat;
use crate::math::{Color, UVec2};
use crate::sampling::Sampler;
use crate::scene::Scene;
use record::PathRecord;

/// An algorithm that estimates pixel values.
pub trait Integrator: Sync {
    /// A short name for file names and tables ("direct", "path", ...).
    fn name(&self) -> &'static str;

    /// One sample of pixel `pixel`: returns its radiance estimate and may add
    /// contributions to other pixels to `splats` (light tracing). All random
    /// numbers come from `sampler`.
    fn sample(
        &self,
        scene: &Scene,
        pixel: UVec2,
        sampler: &mut Sampler,
        splats: &mut Vec<Splat>,
    ) -> Color;

    /// The same sample as [`Integrator::sample`] (the same random numbers,
    /// the same result bit for bit), with what it traced handed to `record`
    /// ([`record`]). An integrator that does not record says so in the
    /// record and computes the sample as usual.
    fn sample_recorded(
        &self,
        scene: &Scene,
        pixel: UVec2,
        sampler: &mut Sampler,
        splats: &mut Vec<Splat>,
        record: &mut PathRecord,
    ) -> Color {
        record.truncated = Some(format!(
            "the {} integrator does not record its paths",
            self.name()
        ));
        self.sample(scene, pixel, sampler, splats)
    }
}

mod ao;
pub mod bdpt;
pub mod camera_connection;
pub mod continuation;
pub mod dimensions;
mod direct;
pub mod grid;
pub mod irradiance_cache;
mod light_tracing;
pub mod mis_weight;
pub mod naive;
pub mod nee;
mod path;
pub mod photon;
pub mod photon_map;
mod photon_mapping;
pub mod record;
pub mod roulette;
pub mod shading_normals;
pub mod stop;
pub mod subpath;
pub mod vertex;
pub mod visible_point;
pub mod vpl;

pub use ao::AmbientOcclusion;
pub use bdpt::{Bdpt, StrategyFilter};
pub use direct::Direct;
pub use irradiance_cache::{IrradianceCache, IrradianceCacheSettings};
pub use light_tracing::LightTracer;
pub use naive::NaiveRecursive;
pub use path::{DirectStrategy, PathTracer};
pub use photon_mapping::{PhotonMapping, PhotonSettings, PhotonStats};
pub use vpl::{InstantRadiosity, VplSettings};

/// Mitsuba's maximum depth `D` (`None`: unlimited) as the most segments a
/// path may have: a path of `k` segments may add another only while
/// `k < max_segments(D)` (D = 1: only emitters seen directly). The one place
/// where "unlimited" becomes a number; every integrator counts depth in
/// segments from the lens, as Mitsuba does.
#[inline]
pub fn max_segments(max_depth: Option<u32>) -> u32 {
    max_depth.unwrap_or(u32::MAX)
}

/// The primary ray of a pixel sample: a uniform point in the pixel (a box
/// filter: each sample counts fully for its own pixel) and a point on the lens.
/// Draws [`FILM`](dimensions::FILM) and [`LENS`](dimensions::LENS), the
/// sampler's next four numbers.
#[inline]
pub fn camera_ray(scene: &Scene, pixel: UVec2, sampler: &mut Sampler) -> crate::math::Ray {
    let film = dimensions::FILM.draw(sampler);
    let lens = dimensions::LENS.draw(sampler);
    scene.camera.generate_ray(pixel.as_vec2() + film, lens)
}
