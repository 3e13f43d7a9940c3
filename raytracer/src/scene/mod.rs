//! Scenes: what is rendered, from a text file or built in.
//!
//! Lecture topic: the scenes of the lecture's pictures — the Cornell box
//! (numerically identical to Mitsuba 3's, so an independent renderer can check
//! ours), furnaces with known answers, a caustic, a room lit through a door.

pub mod builtin;
pub mod error;
pub mod format;
pub mod load;

pub use builtin::{BUILTIN_SCENES, BuiltinScene, builtin, load_builtin, write_builtin};
pub use error::SceneError;
pub use load::{SceneOrigin, load_file, load_str};

use crate::brdf::Brdf;
use crate::camera::CameraParams;
use crate::geometry::Shape;
use crate::light::Light;
use crate::math::Color;

/// How to render a scene unless the command line says otherwise.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RenderSettings {
    pub width: u32,
    pub height: u32,
    /// Samples per pixel.
    pub spp: u32,
    /// Maximum path depth in Mitsuba's convention: 1 = only emitters seen
    /// directly, 2 = direct illumination, D = at most D − 1 bounces;
    /// `None` = unlimited (Russian roulette ends the paths).
    pub max_depth: Option<u32>,
    /// Depth from which Russian roulette may end a path (Mitsuba's `rr_depth`).
    pub rr_depth: u32,
    pub seed: u64,
}

impl Default for RenderSettings {
    fn default() -> Self {
        RenderSettings {
            width: 256,
            height: 256,
            spp: 16,
            max_depth: None,
            rr_depth: 5,
            seed: 0,
        }
    }
}

/// Light emitted by a shape: it becomes an area light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Emitter {
    pub radiance: Color,
    pub two_sided: bool,
}

/// A shape with its BRDF (an index into [`SceneParts::brdfs`]) and emission.
#[derive(Clone, Debug)]
pub struct SceneObject {
    pub name: String,
    pub shape: Shape,
    pub brdf: u32,
    pub emitter: Option<Emitter>,
}

/// Everything a scene description contains, checked and ready to build.
#[derive(Clone, Debug)]
pub struct SceneParts {
    pub camera: CameraParams,
    pub settings: RenderSettings,
    /// Names parallel to `brdfs` (the material names of the file).
    pub brdf_names: Vec<String>,
    pub brdfs: Vec<Brdf>,
    pub objects: Vec<SceneObject>,
    /// Lights that are not shapes: point lights and the environment.
    pub lights: Vec<Light>,
}
pub struct Scene {
    pub parts: SceneParts,
}
