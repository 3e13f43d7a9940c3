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
use crate::camera::{Camera, CameraParams};
use crate::geometry::{Geometry, Shape};
use crate::light::{AreaLight, AreaShape, Light};
use crate::math::{Color, Ray, Vec3A};
use crate::sampling::Distribution1D;

/// Geometry makes interactions; [`Scene::intersect`] returns them, so they
/// are named here too (the exercises import them with the scene).
pub use crate::geometry::Interaction;

/// The largest max depth D a scene file or a command line may ask for.
pub const MAX_DEPTH_LIMIT: u32 = 65_535;

/// The one rule for the max depth D of a scene file's `max_depth` and of the
/// command line's `--max-depth` alike. D is the largest number of segments
/// of a path in Mitsuba's sense: 1 = only emitters seen directly, 2 = direct
/// illumination, D = at most D − 1 bounces; `-1` = unlimited (`None`:
/// Russian roulette or an escape ends the paths). 0 (a black image) and any
/// other negative number are refused, and so is more than
/// [`MAX_DEPTH_LIMIT`].
pub fn max_depth_from(value: i64) -> Result<Option<u32>, String> {
    match value {
        -1 => Ok(None),
        d if (1..=MAX_DEPTH_LIMIT as i64).contains(&d) => Ok(Some(d as u32)),
        other => Err(format!(
            "must be -1 (unlimited) or in [1, {MAX_DEPTH_LIMIT}] (1 = emitters seen directly, \
             2 = direct light, D = at most D − 1 bounces), got {other}"
        )),
    }
}

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

/// What a shape is made of: its BRDF and, if it glows, its area light.
#[derive(Clone, Debug, PartialEq)]
pub struct ObjectInfo {
    pub name: String,
    /// Index into [`Scene::brdfs`].
    pub brdf: u32,
    /// Index into [`Scene::lights`] if the shape emits.
    pub light: Option<u32>,
}

/// How [`Scene::choose_light`] picks a light for next event estimation and
/// for the start of a light path.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum LightSelection {
    /// In proportion to the light's emitted power ([`Light::power`], the
    /// mean of its three channels): a bright lamp is chosen more often than
    /// a dim one, so each choice carries about the same light. The default.
    #[default]
    Power,
    /// Every light with probability `1/n`, as Mitsuba does.
    Uniform,
}

/// A light picked by [`Scene::choose_light`].
#[derive(Clone, Copy, Debug)]
pub struct LightChoice<'a> {
    /// Its index in [`Scene::lights`].
    pub index: u32,
    pub light: &'a Light,
    /// The probability `P(light)` with which it was picked.
    pub pmf: f32,
}

/// An emitter found by a ray ([`Scene::emitter_hit`]): the light's index,
/// the radiance it sends back along the ray, and the point and normal where
/// the ray met it (for the environment: the ray's origin and a zero normal,
/// which its pdf ignores).
#[derive(Clone, Copy, Debug)]
pub struct EmitterHit {
    pub light: u32,
    pub le: Color,
    pub p: Vec3A,
    pub n: Vec3A,
}

/// A scene ready to render: camera, geometry with its BVH, BRDFs and lights.
#[derive(Clone, Debug)]
pub struct Scene {
    /// Built-in name or file name, for messages and file names.
    pub name: String,
    pub camera: Camera,
    pub settings: RenderSettings,
    pub geometry: Geometry,
    /// One entry per shape of `geometry`, in the same order.
    pub objects: Vec<ObjectInfo>,
    pub brdf_names: Vec<String>,
    pub brdfs: Vec<Brdf>,
    /// Every light: the area lights of emitting shapes, point lights and the
    /// environment.
    pub lights: Vec<Light>,
    /// Index of the environment in `lights`, if the scene has one.
    pub environment: Option<u32>,
    /// How lights are chosen (change it with [`Scene::set_light_selection`]).
    light_selection: LightSelection,
    /// The lights' powers when they are chosen by power (`None`: uniformly).
    light_power: Option<Distribution1D>,
}

impl Scene {
    /// A built-in scene by name (`lesson11 scenes` lists them).
    pub fn builtin(name: &str) -> Result<Scene, SceneError> {
        Ok(Scene::build(name, builtin::load_builtin(name)?))
    }

    /// A scene file (TOML, see `raytracer/scenes/README.md`).
    pub fn load(path: &std::path::Path) -> Result<Scene, SceneError> {
        let name = path
            .file_stem()
            .map_or_else(|| "scene".into(), |s| s.to_string_lossy().into_owned());
        Ok(Scene::build(&name, load::load_file(path)?))
    }

    /// Assembles checked parts: emitting shapes become area lights, every
    /// shape goes into one BVH, the environment learns the scene's bounds.
    pub fn build(name: &str, parts: SceneParts) -> Scene {
        let mut lights = Vec::new();
        let mut objects = Vec::with_capacity(parts.objects.len());
        let mut shapes = Vec::with_capacity(parts.objects.len());
        for object in parts.objects {
            let light = object.emitter.and_then(|e| {
                let shape = match &object.shape {
                    Shape::Quad(q) => AreaShape::Quad(*q),
                    Shape::Sphere(s) => AreaShape::Sphere(*s),
                    // The loader only lets quads and spheres emit.
                    Shape::Mesh(_) => return None,
                };
                lights.push(Light::Area(AreaLight {
                    shape,
                    radiance: e.radiance,
                    two_sided: e.two_sided,
                }));
                Some(lights.len() as u32 - 1)
            });
            objects.push(ObjectInfo {
                name: object.name,
                brdf: object.brdf,
                light,
            });
            shapes.push(object.shape);
        }
        let geometry = Geometry::new(shapes);
        let bounds = geometry.bounds();
        let (center, radius) = if bounds.is_empty() {
            (Vec3A::ZERO, 1.0)
        } else {
            let c = bounds.centroid();
            (c, (bounds.max - c).length().max(1e-3))
        };
        let mut environment = None;
        for mut light in parts.lights {
            if let Light::Environment(env) = &mut light {
                env.set_scene_bounds(center, radius);
                environment = Some(lights.len() as u32);
            }
            lights.push(light);
        }
        let settings = parts.settings;
        let mut scene = Scene {
            name: name.to_string(),
            camera: Camera::new(parts.camera, settings.width, settings.height),
            settings,
            geometry,
            objects,
            brdf_names: parts.brdf_names,
            brdfs: parts.brdfs,
            lights,
            environment,
            light_selection: LightSelection::default(),
            light_power: None,
        };
        scene.set_light_selection(LightSelection::default());
        scene
    }

    /// Chooses lights by power (the default) or uniformly from now on.
    pub fn set_light_selection(&mut self, selection: LightSelection) {
        self.light_selection = selection;
        self.light_power =
            (selection == LightSelection::Power && !self.lights.is_empty()).then(|| {
                let power: Vec<f32> = self
                    .lights
                    .iter()
                    .map(|l| l.power().element_sum() / 3.0)
                    .collect();
                Distribution1D::new(&power)
            });
    }

    /// How lights are chosen.
    pub fn light_selection(&self) -> LightSelection {
        self.light_selection
    }

    /// Changes the image size (and the camera's aspect ratio with it).
    pub fn set_resolution(&mut self, width: u32, height: u32) {
        self.settings.width = width;
        self.settings.height = height;
        self.camera = Camera::new(self.camera.params, width, height);
    }

    /// The first surface along `ray`, with everything shading needs.
    #[inline]
    pub fn intersect(&self, ray: &Ray) -> Option<Interaction> {
        self.geometry.interaction(ray)
    }

    /// Whether nothing blocks `ray` before its `t_max` (a shadow ray).
    #[inline]
    pub fn unoccluded(&self, ray: &Ray) -> bool {
        !self.geometry.occluded(ray)
    }

    /// Picks a light for next event estimation, or to start a light path,
    /// with the number `u`: in proportion to its power by default, or
    /// uniformly (see [`LightSelection`]). `None` if the scene has no light.
    #[inline]
    pub fn choose_light(&self, u: f32) -> Option<LightChoice<'_>> {
        let n = self.lights.len();
        if n == 0 {
            return None;
        }
        let (i, pmf) = match &self.light_power {
            // One light (the Cornell box): no search.
            _ if n == 1 => (0, 1.0),
            Some(power) => power.sample_discrete(u),
            None => (((u * n as f32) as usize).min(n - 1), 1.0 / n as f32),
        };
        Some(LightChoice {
            index: i as u32,
            light: &self.lights[i],
            pmf,
        })
    }

    /// Probability that [`Self::choose_light`] picks light `index` (0 for
    /// an index that is not a light).
    #[inline]
    pub fn light_pmf(&self, index: u32) -> f32 {
        let n = self.lights.len();
        match &self.light_power {
            _ if index as usize >= n => 0.0,
            _ if n == 1 => 1.0,
            Some(power) => power.discrete_pdf(index as usize),
            None => 1.0 / n as f32,
        }
    }

    /// Radiance arriving along a ray that left the scene (the environment, or black).
    #[inline]
    pub fn escaped_radiance(&self, d: Vec3A) -> Color {
        match self.environment.map(|i| &self.lights[i as usize]) {
            Some(Light::Environment(env)) => env.environment_radiance(d),
            _ => Color::ZERO,
        }
    }

    /// The BRDF at a hit.
    #[inline]
    pub fn brdf(&self, it: &Interaction) -> &Brdf {
        &self.brdfs[self.objects[it.shape as usize].brdf as usize]
    }

    /// The index in [`Scene::lights`] of the area light of the shape hit, if
    /// it emits.
    #[inline]
    pub fn area_light(&self, it: &Interaction) -> Option<u32> {
        self.objects[it.shape as usize].light
    }

    /// `L_e` that light `light` sends from its point with normal `n` in the
    /// direction `w` (pointing away from the light); for a point light its
    /// intensity `I` (W/sr), which plays the same role where a light path
    /// starts (no ray hits a point light, so a surface never asks for it).
    /// The one place emission is looked up: [`Scene::emitted`] and
    /// [`Scene::emitter_hit`] ask it, and the vertices of light and
    /// bidirectional tracing too.
    #[inline]
    pub fn emitted_by(&self, light: u32, n: Vec3A, w: Vec3A) -> Color {
        match &self.lights[light as usize] {
            Light::Point(l) => l.intensity,
            l => l.le(n, w),
        }
    }

    /// Radiance emitted by the hit surface towards `it.wo` (zero unless it is a light).
    #[inline]
    pub fn emitted(&self, it: &Interaction) -> Color {
        self.area_light(it)
            .map_or(Color::ZERO, |light| self.emitted_by(light, it.ng, it.wo))
    }

    /// What emitter, if any, `ray` reached: the area light of the surface
    /// `hit`, or the environment if the ray escaped (`hit` is `None`). `None`
    /// if no light was reached or it sends nothing back.
    #[inline]
    pub fn emitter_hit(&self, ray: &Ray, hit: Option<&Interaction>) -> Option<EmitterHit> {
        let found = match hit {
            Some(it) => self.area_light(it).map(|light| EmitterHit {
                light,
                le: self.emitted_by(light, it.ng, it.wo),
                p: it.p,
                n: it.ng,
            }),
            None => self.environment.map(|light| EmitterHit {
                light,
                le: self.escaped_radiance(ray.d),
                p: ray.o,
                n: Vec3A::ZERO,
            }),
        };
        found.filter(|e| e.le != Color::ZERO)
    }
}
