//! The shapes of a scene file: spheres, quads, Mitsuba's rectangles and
//! cubes, and OBJ meshes, placed by `translate · rotate · scale`.
//!
//! Lecture topic: the scenes of the lecture's pictures (the Cornell box's
//! walls, light and boxes are built here). Part of [`super`], the loader.

use std::ops::Range;
use std::sync::Arc;

use toml::Spanned;

use super::{Context, Result, SceneOrigin, span_of};
use crate::geometry::{Mesh, Quad, Shape, Sphere, Transform};
use crate::math::{Color, Vec3, Vec3A};
use crate::scene::format::{ShapeDesc, Vec3Desc};
use crate::scene::{Emitter, SceneObject};

impl Context<'_> {
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
    pub fn transform(&self, s: &ShapeDesc) -> Result<Transform> {
        let mut t = Transform::identity();
        if let Some(scale) = &s.scale {
            let v = scale.get_ref().0;
            if v.abs().min_element() == 0.0 {
                return Err(self.error(scale.span(), format!("scale must not be zero, got {v}")));
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

    pub(super) fn shape(
        &self,
        i: usize,
        desc: &Spanned<ShapeDesc>,
        names: &[String],
    ) -> Result<SceneObject> {
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
                self.unused(
                    &what,
                    &[&sphere_fields[..], &quad_fields, &file_field].concat(),
                )?;
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
                self.unused(
                    &what,
                    &[&sphere_fields[..], &quad_fields, &file_field].concat(),
                )?;
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
}
