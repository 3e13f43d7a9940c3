//! The built-in scenes of the course, embedded in the crate.
//!
//! Lecture topic: the scenes of the lecture's pictures — the Cornell box
//! (numerically identical to Mitsuba 3's), two furnaces whose answer is
//! exactly 1, a caustic, a room lit through a door ajar, a stereo scene, a
//! BRDF gallery and Veach's scene for multiple importance sampling. Each is a TOML file in `raytracer/scenes/` (read it, it is
//! commented); [`write_builtin`] copies one out so that a student can edit it
//! and load it back with [`super::load_file`].

use std::path::{Path, PathBuf};

use super::SceneParts;
use super::error::SceneError;
use super::load::{SceneOrigin, load_str};

/// A scene that ships with the crate.
#[derive(Debug)]
pub struct BuiltinScene {
    /// The name used on the command line, e.g. `cornell`.
    pub name: &'static str,
    /// One line saying what the scene shows.
    pub description: &'static str,
    /// The scene file's text.
    pub toml: &'static str,
    /// The files it names (OBJ meshes), by the name used in the scene file.
    pub assets: &'static [BuiltinAsset],
}

/// A file a built-in scene refers to, embedded as text.
#[derive(Debug)]
pub struct BuiltinAsset {
    pub file: &'static str,
    pub text: &'static str,
}

/// Every built-in scene, in the order of the lecture.
pub const BUILTIN_SCENES: &[BuiltinScene] = &[
    BuiltinScene {
        name: "cornell",
        description: "the Cornell box, numerically identical to Mitsuba 3's mitsuba.cornell_box()",
        toml: include_str!("../../scenes/cornell.toml"),
        assets: &[],
    },
    BuiltinScene {
        name: "furnace",
        description: "camera inside an emitting sphere of albedo 0.5: every pixel is Le/(1-ρ) = 1",
        toml: include_str!("../../scenes/furnace.toml"),
        assets: &[],
    },
    BuiltinScene {
        name: "white-furnace",
        description: "a white Lambert sphere under a constant sky of radiance 1: every pixel is 1",
        toml: include_str!("../../scenes/white-furnace.toml"),
        assets: &[],
    },
    BuiltinScene {
        name: "caustic",
        description: "a point light focused by a glass ball onto the floor (light tracing finds it)",
        toml: include_str!("../../scenes/caustic.toml"),
        assets: &[],
    },
    BuiltinScene {
        name: "door",
        description: "a room lit only through a door ajar from a lamp in the next room",
        toml: include_str!("../../scenes/door.toml"),
        assets: &[],
    },
    BuiltinScene {
        name: "stereo",
        description: "near, middle and far objects and a torus mesh on a checker floor, for stereo",
        toml: include_str!("../../scenes/stereo.toml"),
        assets: &[BuiltinAsset {
            file: "torus.obj",
            text: include_str!("../../scenes/torus.obj"),
        }],
    },
    BuiltinScene {
        name: "brdf-gallery",
        description: "Lambert, Phong n = 1, 10, 100, 1000, mirror and glass balls side by side",
        toml: include_str!("../../scenes/brdf-gallery.toml"),
        assets: &[],
    },
    BuiltinScene {
        name: "veach-mis",
        description: "Veach's MIS scene: four plates of rising glossiness, four lights of rising size",
        toml: include_str!("../../scenes/veach-mis.toml"),
        assets: &[],
    },
];

/// The built-in scene called `name`.
pub fn builtin(name: &str) -> Option<&'static BuiltinScene> {
    BUILTIN_SCENES.iter().find(|s| s.name == name)
}

/// The names of the built-in scenes, comma separated (for error messages
/// and `--help`).
pub fn builtin_names() -> String {
    BUILTIN_SCENES
        .iter()
        .map(|s| s.name)
        .collect::<Vec<_>>()
        .join(", ")
}

fn unknown(name: &str) -> SceneError {
    SceneError::whole_file(
        format!("builtin:{name}"),
        format!(
            "unknown built-in scene `{name}`; the built-in scenes are: {}",
            builtin_names()
        ),
    )
}

/// Loads the built-in scene called `name`.
pub fn load_builtin(name: &str) -> Result<SceneParts, SceneError> {
    let scene = builtin(name).ok_or_else(|| unknown(name))?;
    load_str(scene.toml, &SceneOrigin::Builtin(scene))
}

/// Writes the built-in scene `name` (its TOML file, as `NAME.toml`, and the
/// files it uses) into `dir`, creating `dir` if needed, and returns the path
/// of the TOML file.
pub fn write_builtin(name: &str, dir: &Path) -> std::io::Result<PathBuf> {
    let scene = builtin(name).ok_or_else(|| {
        std::io::Error::new(std::io::ErrorKind::NotFound, unknown(name).to_string())
    })?;
    std::fs::create_dir_all(dir)?;
    for asset in scene.assets {
        std::fs::write(dir.join(asset.file), asset.text)?;
    }
    let path = dir.join(format!("{}.toml", scene.name));
    std::fs::write(&path, scene.toml)?;
    Ok(path)
}
