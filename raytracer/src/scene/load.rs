//! The scene loader: TOML text → checked [`SceneParts`].
//!
//! Lecture topic: the scenes of the lecture's pictures. Parsing (syntax,
//! unknown fields, types, finite numbers) is done by serde with the types of
//! [`super::format`]; this file then checks what serde cannot (positive
//! radii, quads with an area, a camera that does not look along its up
//! vector, known material names, …) and builds the renderer's objects. Every
//! failure is a [`SceneError`] pointing at the offending line and field.

use std::ops::Range;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use toml::Spanned;

use super::builtin::BuiltinScene;
use super::error::SceneError;
use super::format::{
    CameraDesc, ColorDesc, EnvironmentDesc, LightDesc, MaterialDesc, Real, RenderDesc,
    SceneFile, ShapeDesc, TextureDesc, Vec3Desc,
};
use super::{Emitter, RenderSettings, SceneObject, SceneParts};
use crate::brdf::{Brdf, Glass, ImageTexture, Lambert, Mirror, Phong, Texture};
use crate::camera::CameraParams;
use crate::geometry::{Mesh, Quad, Shape, Sphere, Transform};
use crate::light::{EnvironmentLight, EnvironmentMap, Light, PointLight};
use crate::math::{Color, Vec2, Vec3, Vec3A};

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

/// Loads and checks the scene file `path`.
pub fn load_file(path: &Path) -> Result<SceneParts, SceneError> {
    let text = std::fs::read_to_string(path).map_err(|e| {
        SceneError::whole_file(path.display().to_string(), format!("cannot read: {e}"))
    })?;
    load_str(&text, &SceneOrigin::file(path))
}

/// Loads and checks the scene text `text`.
pub fn load_str(text: &str, origin: &SceneOrigin) -> Result<SceneParts, SceneError> {
    let file = parse(text, origin)?;
    build(text, origin, &file)
}

/// Parses the text into the format's types (syntax, fields, types, numbers).
pub(crate) fn parse(text: &str, origin: &SceneOrigin) -> Result<SceneFile, SceneError> {
    toml::from_str(text).map_err(|e| SceneError::from_toml(&origin.name(), text, &e))
}

/// Checks a parsed file and builds the scene's parts.
pub(crate) fn build(
    text: &str,
    origin: &SceneOrigin,
    file: &SceneFile,
) -> Result<SceneParts, SceneError> {
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
        brdfs.push(cx.material(desc)?);
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
        .map(|light| cx.light(light))
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
struct Context<'a> {
    text: &'a str,
    origin: &'a SceneOrigin,
    name: String,
}

type Result<T, E = SceneError> = std::result::Result<T, E>;

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

    /// A radiance or intensity: every component ≥ 0.
    fn radiance(&self, c: &Spanned<ColorDesc>) -> Result<Color> {
        let v = c.get_ref().0;
        if v.min_element() >= 0.0 {
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
        let up = c.up.as_ref().map_or(Vec3A::Y, |u| Vec3A::from(u.get_ref().0));
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
        if !(sin > 1e-4) {
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
            Some(v) if *v.get_ref() == 0 => {
                Err(self.error(v.span(), "must be at least 1, got 0"))
            }
            Some(v) => Ok(*v.get_ref()),
            None => Ok(default),
        };
        s.width = at_least_one(&r.width, s.width)?;
        s.height = at_least_one(&r.height, s.height)?;
        s.spp = at_least_one(&r.spp, s.spp)?;
        if let Some(d) = &r.max_depth {
            s.max_depth = match *d.get_ref() {
                -1 => None,
                d @ 1..=0xffff => Some(d as u32),
                other => {
                    return Err(self.error(
                        d.span(),
                        format!("must be -1 (unlimited) or in [1, 65535], got {other}"),
                    ));
                }
            };
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
            Some((field, Some(span))) => Err(self.error(
                span.clone(),
                format!("`{field}` is not used by {what}"),
            )),
            _ => Ok(()),
        }
    }

    fn material(&self, desc: &Spanned<MaterialDesc>) -> Result<Brdf> {
        let m = desc.get_ref();
        let kind = m.kind.get_ref().as_str();
        let required = |name: &str| {
            self.error(
                m.kind.span(),
                format!("a {kind} material needs `{name}`"),
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
                if path.is_file() {
                    Ok(path)
                } else {
                    Err(self.error(
                        file.span(),
                        format!("{what} file not found: {}", path.display()),
                    ))
                }
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

    /// Loads an OBJ mesh from disk or from the built-in scene's embedded files.
    fn mesh_file(&self, file: &Spanned<String>) -> Result<Mesh> {
        let loaded = match self.origin {
            SceneOrigin::Builtin(scene) => {
                let asset = scene
                    .assets
                    .iter()
                    .find(|a| a.file == file.get_ref())
                    .ok_or_else(|| {
                        self.error(
                            file.span(),
                            format!(
                                "mesh file not found: built-in scene `{}` has no file `{}`",
                                scene.name,
                                file.get_ref()
                            ),
                        )
                    })?;
                Mesh::from_obj_str(asset.text, asset.file)
            }
            SceneOrigin::Dir { .. } => Mesh::load_obj(&self.asset_path(file, "mesh")?),
        };
        let mesh = loaded.map_err(|e| self.error(file.span(), format!("bad mesh: {e}")))?;
        if mesh.indices.is_empty() {
            return Err(self.error(file.span(), "the mesh has no triangles"));
        }
        Ok(mesh)
    }

    /// `translate · R_n ⋯ R_1 · scale`: scale first, then the rotations in
    /// the order listed, then the translation (Mitsuba's `to_world`).
    fn transform(&self, s: &ShapeDesc) -> Result<Transform> {
        let mut t = Transform::identity();
        if let Some(scale) = &s.scale {
            let v = scale.get_ref().0;
            if v.abs().min_element() == 0.0 {
                return Err(self.error(
                    scale.span(),
                    format!("scale must not be zero, got {v}"),
                ));
            }
            t = Transform::scale(v);
        }
        if let Some(rotate) = &s.rotate {
            for r in &rotate.get_ref().0 {
                let axis = Vec3::new(r[0], r[1], r[2]);
                if axis.length() == 0.0 {
                    return Err(self.error(rotate.span(), "a rotation axis must not be zero"));
                }
                t = Transform::rotate(axis, r[3]) * t;
            }
        }
        if let Some(translate) = &s.translate {
            t = Transform::translate(translate.get_ref().0) * t;
        }
        Ok(t)
    }

    fn shape(&self, i: usize, desc: &Spanned<ShapeDesc>, names: &[String]) -> Result<SceneObject> {
        let s = desc.get_ref();
        let kind = s.kind.get_ref().as_str();
        let here = format!("shapes[{i}]");
        let required = |field: &str| {
            self.error_in(
                s.kind.span(),
                here.clone(),
                format!("a {kind} needs `{field}`"),
            )
        };
        let placed = [
            ("translate", span_of(&s.translate)),
            ("rotate", span_of(&s.rotate)),
            ("scale", span_of(&s.scale)),
        ];
        let sphere_fields = [
            ("center", span_of(&s.center)),
            ("radius", span_of(&s.radius)),
        ];
        let quad_fields = [
            ("origin", span_of(&s.origin)),
            ("edge1", span_of(&s.edge1)),
            ("edge2", span_of(&s.edge2)),
        ];
        let file_field = [("file", span_of(&s.file))];
        let what = format!("a {kind}");
        let vec = |v: &Option<Spanned<Vec3Desc>>, name| -> Result<Vec3A> {
            v.as_ref()
                .map(|v| Vec3A::from(v.get_ref().0))
                .ok_or_else(|| required(name))
        };

        // Type, material and emission first: they fail before any file is read.
        const SHAPES: [&str; 5] = ["sphere", "quad", "rectangle", "cube", "mesh"];
        if !SHAPES.contains(&kind) {
            return Err(self.error(
                s.kind.span(),
                format!(
                    "unknown shape type `{kind}`, expected one of: {}",
                    SHAPES.join(", ")
                ),
            ));
        }
        let brdf = names
            .iter()
            .position(|n| n == s.material.get_ref())
            .ok_or_else(|| {
                let known = if names.is_empty() {
                    "no materials are defined; add a [materials.NAME] table".to_string()
                } else {
                    format!("the materials are: {}", names.join(", "))
                };
                self.error(
                    s.material.span(),
                    format!("unknown material `{}`; {known}", s.material.get_ref()),
                )
            })?;

        let emitter = self.emitter(s, kind)?;

        let shape = match kind {
            "sphere" => {
                self.unused(&what, &[&quad_fields[..], &file_field, &placed].concat())?;
                let radius = s.radius.as_ref().ok_or_else(|| required("radius"))?;
                Shape::Sphere(Sphere {
                    center: vec(&s.center, "center")?,
                    radius: self.positive(radius)?,
                })
            }
            "quad" => {
                self.unused(&what, &[&sphere_fields[..], &file_field, &placed].concat())?;
                let quad = Quad {
                    origin: vec(&s.origin, "origin")?,
                    e1: vec(&s.edge1, "edge1")?,
                    e2: vec(&s.edge2, "edge2")?,
                };
                self.check_area(&quad, s.edge2.as_ref().map_or(s.kind.span(), |e| e.span()))?;
                Shape::Quad(quad)
            }
            "rectangle" => {
                self.unused(&what, &[&sphere_fields[..], &quad_fields, &file_field].concat())?;
                // Mitsuba's rectangle: [-1, 1]² at z = 0, normal +z. Its
                // corners (-1,-1), (1,-1), (-1,1) give origin, e1 and e2, so
                // that e1 × e2 is the transformed +z (for a transform that
                // keeps orientation).
                let m = self.transform(s)?.matrix;
                let p = |x: f32, y: f32| Vec3A::from(m.transform_point3(Vec3::new(x, y, 0.0)));
                let origin = p(-1.0, -1.0);
                let quad = Quad {
                    origin,
                    e1: p(1.0, -1.0) - origin,
                    e2: p(-1.0, 1.0) - origin,
                };
                self.check_area(&quad, s.kind.span())?;
                Shape::Quad(quad)
            }
            "cube" => {
                self.unused(&what, &[&sphere_fields[..], &quad_fields, &file_field].concat())?;
                Shape::Mesh(Arc::new(Mesh::cube().transformed(&self.transform(s)?)))
            }
            "mesh" => {
                self.unused(&what, &[&sphere_fields[..], &quad_fields].concat())?;
                let file = s.file.as_ref().ok_or_else(|| required("file"))?;
                let transform = self.transform(s)?;
                Shape::Mesh(Arc::new(self.mesh_file(file)?.transformed(&transform)))
            }
            _ => unreachable!("the shape type was checked above"),
        };

        Ok(SceneObject {
            name: s.name.clone().unwrap_or_else(|| format!("{kind}#{i}")),
            shape,
            brdf: brdf as u32,
            emitter,
        })
    }

    /// A quad must have an area: `|e1 × e2| > 0`.
    fn check_area(&self, quad: &Quad, span: Range<usize>) -> Result<()> {
        let area = quad.e1.cross(quad.e2).length();
        if area > 1e-6 * quad.e1.length() * quad.e2.length() && area > 0.0 {
            Ok(())
        } else {
            Err(self.error(
                span,
                format!(
                    "the quad has no area: its edges {} and {} are parallel or zero",
                    quad.e1, quad.e2
                ),
            ))
        }
    }

    fn emitter(&self, s: &ShapeDesc, kind: &str) -> Result<Option<Emitter>> {
        let Some(emission) = &s.emission else {
            if let Some(two) = &s.two_sided {
                return Err(self.error(
                    two.span(),
                    "`two_sided` only applies to emitting shapes (add `emission`)",
                ));
            }
            return Ok(None);
        };
        if !matches!(kind, "sphere" | "quad" | "rectangle") {
            return Err(self.error(
                emission.span(),
                format!("a {kind} cannot emit; only spheres, quads and rectangles can"),
            ));
        }
        let radiance = self.radiance(emission)?;
        if radiance == Color::ZERO {
            return Ok(None);
        }
        Ok(Some(Emitter {
            radiance,
            two_sided: s.two_sided.as_ref().is_some_and(|t| *t.get_ref()),
        }))
    }

    fn light(&self, desc: &Spanned<LightDesc>) -> Result<Light> {
        let l = desc.get_ref();
        match l.kind.get_ref().as_str() {
            "point" => {
                let required = |field: &str| {
                    self.error(l.kind.span(), format!("a point light needs `{field}`"))
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
        // TODO(lead): use EnvironmentLight::new; the scene sets the bounding
        // sphere once the geometry is built.
        Ok(Light::Environment(EnvironmentLight {
            radiance,
            map,
            scene_center: Vec3A::ZERO,
            scene_radius: 0.0,
        }))
    }
}

/// Where an optional field is, if it is present.
fn span_of<T>(field: &Option<Spanned<T>>) -> Option<Range<usize>> {
    field.as_ref().map(Spanned::span)
}

fn fmt_color(c: Color) -> String {
    format!("[{}, {}, {}]", c.x, c.y, c.z)
}
