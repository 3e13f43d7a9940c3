//! The scene loader: TOML text → checked [`SceneParts`].
//!
//! Lecture topic: the scenes of the lecture's pictures. Parsing (syntax,
//! unknown fields, types, finite numbers) is done by serde with the types of
//! [`super::format`]; this file then checks what serde cannot (positive
//! radii, quads with an area, a camera that does not look along its up
//! vector, known material names, …) and builds the renderer's objects. Every
//! failure is a [`SceneError`] pointing at the offending line and field.
//! Shapes and their transforms are built in the submodule `shape`.

use std::ops::Range;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use toml::Spanned;

pub mod shape;

use super::builtin::BuiltinScene;
use super::error::SceneError;
use super::format::{
    CameraDesc, ColorDesc, EnvironmentDesc, LightDesc, MaterialDesc, Real, RenderDesc, SceneFile,
    TextureDesc,
};
use super::{RenderSettings, SceneParts};
use crate::brdf::{Brdf, Glass, ImageTexture, Lambert, Mirror, Phong, Texture};
use crate::camera::CameraParams;
use crate::light::{EnvironmentLight, EnvironmentMap, Light, PointLight};
use crate::math::{Color, Vec2, Vec3A};

/// Where a scene text comes from: the name shown in errors and how the
/// files it names (meshes, textures, maps) are found.
#[derive(Clone, Debug)]
pub enum SceneOrigin {
    /// A file on disk; relative paths are resolved from `dir`.
    Dir { name: String, dir: PathBuf },
    /// A built-in scene; its files are embedded in the crate.
    Builtin(&'static BuiltinScene),
}

impl SceneOrigin {
    /// The origin of the scene file `path`: named as given, assets beside it.
    pub fn file(path: &Path) -> Self {
        SceneOrigin::Dir {
            name: path.display().to_string(),
            dir: path.parent().map(Path::to_path_buf).unwrap_or_default(),
        }
    }

    /// The name shown in errors (`builtin:NAME` for a built-in scene).
    pub fn name(&self) -> String {
        match self {
            SceneOrigin::Dir { name, .. } => name.clone(),
            SceneOrigin::Builtin(scene) => format!("builtin:{}", scene.name),
        }
    }
}

/// The brightest radiance (or intensity) a scene may give: 10¹². Light paths
/// multiply it by a light's area, 1/pdf and cosines in 32-bit floats (to
/// 3.4·10³⁸), and an `emission = 3e38` made light tracing black and
/// bidirectional tracing 6× too dark; the sun's luminance is about 1.6·10⁹.
pub const MAX_RADIANCE: f32 = 1e12;

/// Loads and checks the scene file `path`.
///
/// Only a regular file of at most [`MAX_SCENE_FILE_BYTES`] is read: a
/// folder, a device such as `/dev/zero` or a pipe is refused before it is
/// opened.
pub fn load_file(path: &Path) -> Result<SceneParts, SceneError> {
    use std::io::Read;
    let error = |message: String| SceneError::whole_file(path.display().to_string(), message);
    let meta = std::fs::metadata(path).map_err(|e| error(format!("cannot read: {e}")))?;
    if meta.is_dir() {
        return Err(error("is a folder, not a scene file".into()));
    }
    if !meta.is_file() {
        return Err(error(
            "is not a regular file (a device, a pipe or a socket), not a scene file".into(),
        ));
    }
    if meta.len() > MAX_SCENE_FILE_BYTES {
        return Err(error(format!(
            "has {} MiB; a scene file may have at most {} MiB (put big meshes in OBJ files)",
            meta.len() >> 20,
            MAX_SCENE_FILE_BYTES >> 20
        )));
    }
    let mut text = String::new();
    std::fs::File::open(path)
        .and_then(|f| f.take(MAX_SCENE_FILE_BYTES).read_to_string(&mut text))
        .map_err(|e| error(format!("cannot read: {e}")))?;
    load_str(&text, &SceneOrigin::file(path))
}

/// The largest scene file [`load_file`] reads: 16 MiB, far more than a
/// hand-written scene (meshes live in OBJ files of their own).
pub const MAX_SCENE_FILE_BYTES: u64 = 16 << 20;

/// Loads and checks the scene text `text`.
pub fn load_str(text: &str, origin: &SceneOrigin) -> Result<SceneParts, SceneError> {
    let file = parse(text, origin)?;
    build(text, origin, &file)
}

/// Parses the text into the format's types (syntax, fields, types, numbers).
pub fn parse(text: &str, origin: &SceneOrigin) -> Result<SceneFile, SceneError> {
    toml::from_str(text).map_err(|e| SceneError::from_toml(&origin.name(), text, &e))
}

/// Checks a parsed file and builds the scene's parts.
pub fn build(text: &str, origin: &SceneOrigin, file: &SceneFile) -> Result<SceneParts, SceneError> {
    let cx = Context {
        text,
        origin,
        name: origin.name(),
    };
    let camera = cx.camera(&file.camera)?;
    let settings = cx.render(&file.render)?;

    // Materials in the order of the file (the map sorts them by name).
    let mut materials: Vec<_> = file.materials.iter().collect();
    materials.sort_by_key(|(name, _)| name.span().start);
    let mut brdf_names = Vec::with_capacity(materials.len());
    let mut brdfs = Vec::with_capacity(materials.len());
    for (name, desc) in materials {
        brdf_names.push(name.get_ref().clone());
        brdfs.push(cx.material(name.get_ref(), desc)?);
    }

    let objects = file
        .shapes
        .iter()
        .enumerate()
        .map(|(i, shape)| cx.shape(i, shape, &brdf_names))
        .collect::<Result<Vec<_>, _>>()?;

    let mut lights = file
        .lights
        .iter()
        .enumerate()
        .map(|(i, light)| cx.light(i, light))
        .collect::<Result<Vec<_>, _>>()?;
    if let Some(env) = &file.environment {
        lights.push(cx.environment(env)?);
    }

    Ok(SceneParts {
        camera,
        settings,
        brdf_names,
        brdfs,
        objects,
        lights,
    })
}

/// The text being loaded, to turn byte ranges into errors.
pub struct Context<'a> {
    pub text: &'a str,
    pub origin: &'a SceneOrigin,
    pub name: String,
}

pub type Result<T, E = SceneError> = std::result::Result<T, E>;

impl Context<'_> {
    fn error(&self, span: Range<usize>, message: impl Into<String>) -> SceneError {
        SceneError::at(&self.name, self.text, Some(span), message.into())
    }

    /// An error about a whole table (a missing field), with its path given.
    fn error_in(&self, span: Range<usize>, path: String, message: String) -> SceneError {
        let mut e = self.error(span, message);
        e.path = path;
        e
    }

    fn positive(&self, x: &Spanned<Real>) -> Result<f32> {
        let v = x.get_ref().0;
        if v > 0.0 {
            Ok(v)
        } else {
            Err(self.error(x.span(), format!("must be positive, got {v}")))
        }
    }

    fn non_negative(&self, x: &Spanned<Real>) -> Result<f32> {
        let v = x.get_ref().0;
        if v >= 0.0 {
            Ok(v)
        } else {
            Err(self.error(x.span(), format!("must be ≥ 0, got {v}")))
        }
    }

    /// A radiance or intensity: every component ≥ 0 and at most
    /// [`MAX_RADIANCE`].
    fn radiance(&self, c: &Spanned<ColorDesc>) -> Result<Color> {
        let v = c.get_ref().0;
        if v.max_element() > MAX_RADIANCE {
            Err(self.error(
                c.span(),
                format!(
                    "radiance {} is too bright: at most {MAX_RADIANCE:e} (brighter light overflows \
                     the renderer's 32-bit products: light tracing gave black)",
                    fmt_color(v)
                ),
            ))
        } else if v.min_element() >= 0.0 {
            Ok(v)
        } else {
            Err(self.error(
                c.span(),
                format!("radiance must not be negative, got {}", fmt_color(v)),
            ))
        }
    }

    /// An albedo or reflectance: every component in [0, 1] (a surface cannot
    /// reflect more light than it receives).
    fn albedo(&self, c: Color, span: Range<usize>) -> Result<Color> {
        if c.min_element() >= 0.0 && c.max_element() <= 1.0 {
            Ok(c)
        } else {
            Err(self.error(
                span,
                format!(
                    "must be in [0, 1] (energy conservation), got {}",
                    fmt_color(c)
                ),
            ))
        }
    }

    fn camera(&self, desc: &Spanned<CameraDesc>) -> Result<CameraParams> {
        let c = desc.get_ref();
        let position = Vec3A::from(c.position.get_ref().0);
        let look_at = Vec3A::from(c.look_at.get_ref().0);
        let up =
            c.up.as_ref()
                .map_or(Vec3A::Y, |u| Vec3A::from(u.get_ref().0));
        let up_span = c.up.as_ref().map_or(c.look_at.span(), |u| u.span());
        let forward = look_at - position;
        if forward.length() == 0.0 {
            return Err(self.error(
                c.look_at.span(),
                "the camera looks at its own position: look_at must differ from position",
            ));
        }
        if up.length() == 0.0 {
            return Err(self.error(up_span, "up must not be the zero vector"));
        }
        let sin = forward.normalize().cross(up.normalize()).length();
        if sin.is_nan() || sin <= 1e-4 {
            return Err(self.error(
                up_span,
                "the camera looks along its up vector: choose an up that is not parallel \
                 to look_at − position",
            ));
        }
        let fov = c.fov.get_ref().0;
        if !(fov > 0.0 && fov < 180.0) {
            return Err(self.error(
                c.fov.span(),
                format!("the vertical field of view must be in (0, 180) degrees, got {fov}"),
            ));
        }
        let aperture_radius = match &c.aperture_radius {
            Some(a) => self.non_negative(a)?,
            None => 0.0,
        };
        let focus_distance = match &c.focus_distance {
            Some(f) => self.positive(f)?,
            None => forward.length(),
        };
        Ok(CameraParams {
            position,
            look_at,
            up,
            vfov_deg: fov,
            aperture_radius,
            focus_distance,
            shift: Vec2::ZERO,
        })
    }

    fn render(&self, r: &RenderDesc) -> Result<RenderSettings> {
        let mut s = RenderSettings::default();
        let at_least_one = |v: &Option<Spanned<u32>>, default: u32| match v {
            Some(v) if *v.get_ref() == 0 => Err(self.error(v.span(), "must be at least 1, got 0")),
            Some(v) => Ok(*v.get_ref()),
            None => Ok(default),
        };
        s.width = at_least_one(&r.width, s.width)?;
        s.height = at_least_one(&r.height, s.height)?;
        s.spp = at_least_one(&r.spp, s.spp)?;
        if let Some(d) = &r.max_depth {
            s.max_depth =
                super::max_depth_from(*d.get_ref()).map_err(|e| self.error(d.span(), e))?;
        }
        if let Some(d) = &r.rr_depth {
            s.rr_depth = *d.get_ref();
        }
        if let Some(seed) = &r.seed {
            s.seed = *seed.get_ref();
        }
        Ok(s)
    }

    /// Refuses fields that the given `type` does not use (they would be
    /// silently ignored otherwise).
    fn unused(&self, what: &str, fields: &[(&str, Option<Range<usize>>)]) -> Result<()> {
        match fields.iter().find(|(_, span)| span.is_some()) {
            Some((field, Some(span))) => {
                Err(self.error(span.clone(), format!("`{field}` is not used by {what}")))
            }
            _ => Ok(()),
        }
    }

    fn material(&self, name: &str, desc: &Spanned<MaterialDesc>) -> Result<Brdf> {
        let brdf = self.material_model(name, desc)?;
        let Some(sides) = &desc.get_ref().sides else {
            return Ok(brdf);
        };
        match sides.get_ref().as_str() {
            "both" => Ok(brdf),
            "front" if matches!(brdf, Brdf::Glass(_)) => Err(self.error(
                sides.span(),
                "glass has two sides by nature (light enters and leaves it): `sides` is not used by a glass material",
            )),
            "front" => Ok(brdf.one_sided()),
            other => Err(self.error(
                sides.span(),
                format!("`sides` must be \"front\" (black from behind) or \"both\", got `{other}`"),
            )),
        }
    }

    /// The BRDF model of a material, before `sides`.
    fn material_model(&self, name: &str, desc: &Spanned<MaterialDesc>) -> Result<Brdf> {
        let m = desc.get_ref();
        let kind = m.kind.get_ref().as_str();
        let required = |field: &str| {
            self.error_in(
                m.kind.span(),
                format!("materials.{name}"),
                format!("a {kind} material needs `{field}`"),
            )
        };
        match kind {
            "lambert" => {
                self.unused("a lambert material", &[
                    ("exponent", span_of(&m.exponent)),
                    ("reflectance", span_of(&m.reflectance)),
                    ("ior", span_of(&m.ior)),
                    ("tint", span_of(&m.tint)),
                ])?;
                let albedo = m.albedo.as_ref().ok_or_else(|| required("albedo"))?;
                Ok(Brdf::Lambert(Lambert {
                    albedo: self.texture(albedo)?,
                }))
            }
            "phong" => {
                self.unused("a phong material", &[
                    ("reflectance", span_of(&m.reflectance)),
                    ("ior", span_of(&m.ior)),
                    ("tint", span_of(&m.tint)),
                ])?;
                let albedo = m.albedo.as_ref().ok_or_else(|| required("albedo"))?;
                let TextureDesc::Color(c) = albedo.get_ref() else {
                    return Err(self.error(
                        albedo.span(),
                        "a phong albedo must be a colour [r, g, b], not a texture",
                    ));
                };
                let exponent = m.exponent.as_ref().ok_or_else(|| required("exponent"))?;
                Ok(Brdf::Phong(Phong {
                    albedo: self.albedo(*c, albedo.span())?,
                    exponent: self.non_negative(exponent)?,
                }))
            }
            "mirror" => {
                self.unused("a mirror material", &[
                    ("albedo", span_of(&m.albedo)),
                    ("exponent", span_of(&m.exponent)),
                    ("ior", span_of(&m.ior)),
                    ("tint", span_of(&m.tint)),
                ])?;
                let reflectance = match &m.reflectance {
                    Some(r) => self.albedo(r.get_ref().0, r.span())?,
                    None => Color::ONE,
                };
                Ok(Brdf::Mirror(Mirror { reflectance }))
            }
            "glass" => {
                self.unused("a glass material", &[
                    ("albedo", span_of(&m.albedo)),
                    ("exponent", span_of(&m.exponent)),
                    ("reflectance", span_of(&m.reflectance)),
                ])?;
                let ior = match &m.ior {
                    Some(ior) => self.positive(ior)?,
                    None => 1.5,
                };
                let tint = match &m.tint {
                    Some(t) => self.albedo(t.get_ref().0, t.span())?,
                    None => Color::ONE,
                };
                Ok(Brdf::Glass(Glass { ior, tint }))
            }
            other => Err(self.error(
                m.kind.span(),
                format!(
                    "unknown material type `{other}`, expected one of: lambert, phong, mirror, glass"
                ),
            )),
        }
    }

    fn texture(&self, t: &Spanned<TextureDesc>) -> Result<Texture> {
        match t.get_ref() {
            TextureDesc::Color(c) => Ok(Texture::Constant(self.albedo(*c, t.span())?)),
            TextureDesc::Checker(ch) => Ok(Texture::Checker {
                a: self.albedo(ch.a.get_ref().0, ch.a.span())?,
                b: self.albedo(ch.b.get_ref().0, ch.b.span())?,
                scale: self.positive(&ch.scale)?,
            }),
            TextureDesc::Image(file) => {
                let path = self.asset_path(file, "image")?;
                let image = ImageTexture::load(&path)
                    .map_err(|e| self.error(file.span(), format!("cannot load the image: {e}")))?;
                Ok(Texture::Image(Arc::new(image)))
            }
        }
    }

    /// The path of a file named by the scene, which must exist. Built-in
    /// scenes embed only OBJ meshes (see [`Context::mesh_file`]).
    fn asset_path(&self, file: &Spanned<String>, what: &str) -> Result<PathBuf> {
        match self.origin {
            SceneOrigin::Dir { dir, .. } => {
                let path = dir.join(file.get_ref());
                let problem = match std::fs::metadata(&path) {
                    Ok(m) if m.is_file() => return Ok(path),
                    Ok(m) if m.is_dir() => "is a folder, not a file",
                    Ok(_) => "is not a regular file (a device, a pipe or a socket)",
                    Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
                        return Err(self.error(
                            file.span(),
                            format!("{what} file not found: {}", path.display()),
                        ));
                    }
                    Err(e) => {
                        return Err(self.error(
                            file.span(),
                            format!("cannot read the {what} file {}: {e}", path.display()),
                        ));
                    }
                };
                Err(self.error(
                    file.span(),
                    format!("the {what} file {} {problem}", path.display()),
                ))
            }
            SceneOrigin::Builtin(scene) => Err(self.error(
                file.span(),
                format!(
                    "built-in scene `{}` cannot use {what} files; write it out and load it from disk",
                    scene.name
                ),
            )),
        }
    }

    fn light(&self, i: usize, desc: &Spanned<LightDesc>) -> Result<Light> {
        let l = desc.get_ref();
        match l.kind.get_ref().as_str() {
            "point" => {
                let required = |field: &str| {
                    self.error_in(
                        l.kind.span(),
                        format!("lights[{i}]"),
                        format!("a point light needs `{field}`"),
                    )
                };
                let position = l.position.as_ref().ok_or_else(|| required("position"))?;
                let intensity = l.intensity.as_ref().ok_or_else(|| required("intensity"))?;
                Ok(Light::Point(PointLight {
                    position: Vec3A::from(position.get_ref().0),
                    intensity: self.radiance(intensity)?,
                }))
            }
            other => Err(self.error(
                l.kind.span(),
                format!(
                    "unknown light type `{other}`, expected `point` (area lights are shapes \
                     with `emission`; the sky is the [environment] table)"
                ),
            )),
        }
    }

    fn environment(&self, desc: &Spanned<EnvironmentDesc>) -> Result<Light> {
        let e = desc.get_ref();
        let radiance = match &e.radiance {
            Some(r) => self.radiance(r)?,
            None if e.map.is_some() => Color::ONE,
            None => {
                return Err(self.error_in(
                    desc.span(),
                    "environment".into(),
                    "give `radiance`, `map` or both".into(),
                ));
            }
        };
        let map = match &e.map {
            Some(file) => {
                let path = self.asset_path(file, "environment map")?;
                let map = EnvironmentMap::load(&path).map_err(|err| {
                    self.error(file.span(), format!("cannot load the map: {err}"))
                })?;
                Some(Arc::new(map))
            }
            None => None,
        };
        // The scene sets the bounding sphere once its geometry is built.
        Ok(Light::Environment(EnvironmentLight::new(radiance, map)))
    }
}

/// Where an optional field is, if it is present.
pub fn span_of<T>(field: &Option<Spanned<T>>) -> Option<Range<usize>> {
    field.as_ref().map(Spanned::span)
}

fn fmt_color(c: Color) -> String {
    format!("[{}, {}, {}]", c.x, c.y, c.z)
}
