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
    fn transform(&self, s: &ShapeDesc) -> Result<Transform> {
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

#[cfg(test)]
mod tests {
    use super::super::{load_file, load_str};
    use super::*;
    use crate::math::Mat4;

    fn origin() -> SceneOrigin {
        SceneOrigin::Dir {
            name: "test.toml".into(),
            dir: ".".into(),
        }
    }

    const CAMERA: &str = "[camera]\nposition = [0, 0, 5]\nlook_at = [0, 0, 1]\nfov = 40\n";

    /// The transform of a shape given as TOML (only its placement fields).
    fn transform_of(fields: &str) -> Mat4 {
        let desc: ShapeDesc =
            toml::from_str(&format!("type = \"cube\"\nmaterial = \"m\"\n{fields}")).unwrap();
        let o = origin();
        let cx = Context {
            text: "",
            origin: &o,
            name: String::new(),
        };
        cx.transform(&desc).unwrap().matrix
    }

    fn assert_mat(m: Mat4, rows: [[f32; 4]; 3]) {
        for (r, row) in rows.iter().enumerate() {
            for (c, &want) in row.iter().enumerate() {
                let got = m.col(c)[r];
                assert!(
                    (got - want).abs() < 1e-6,
                    "m[{r}][{c}] = {got}, want {want}"
                );
            }
        }
    }

    /// Scale, then rotate, then translate, exactly as Mitsuba's `to_world`
    /// of the Cornell box's boxes (matrices from
    /// raytracer/tests/data/cornell_box_mitsuba.txt).
    #[test]
    fn transforms_compose_as_mitsuba() {
        let small =
            transform_of("translate = [0.335, -0.7, 0.38]\nrotate = [0, 1, 0, -17]\nscale = 0.3");
        assert_mat(
            small,
            [
                [0.286_891, 0.0, -0.087_711_5, 0.335],
                [0.0, 0.3, 0.0, -0.7],
                [0.087_711_5, 0.0, 0.286_891, 0.38],
            ],
        );
        let large = transform_of(
            "translate = [-0.33, -0.4, -0.28]\nrotate = [0, 1, 0, 18.25]\nscale = [0.3, 0.61, 0.3]",
        );
        assert_mat(
            large,
            [
                [0.284_91, 0.0, 0.093_949_1, -0.33],
                [0.0, 0.61, 0.0, -0.4],
                [-0.093_949_1, 0.0, 0.284_91, -0.28],
            ],
        );
    }

    /// `rotate = [R1, R2]` applies R1 to the shape first: R = R2 · R1.
    #[test]
    fn rotations_apply_in_the_order_listed() {
        let m = transform_of("rotate = [[0, 0, 1, 90], [1, 0, 0, 90]]");
        // x → (z-rotation) y → (x-rotation) z.
        let p = m.transform_point3(Vec3::X);
        assert!((p - Vec3::Z).length() < 1e-6, "{p}");
        let one = transform_of("rotate = [0, 0, 1, 90]");
        assert!((one.transform_point3(Vec3::X) - Vec3::Y).length() < 1e-6);
    }

    /// Mitsuba's light rectangle of the Cornell box becomes the quad with its
    /// world corners and normal −y.
    #[test]
    fn rectangle_becomes_a_quad_with_mitsubas_corners() {
        let text = format!(
            "{CAMERA}[materials.m]\ntype = \"lambert\"\nalbedo = 0.5\n\
             [[shapes]]\ntype = \"rectangle\"\nmaterial = \"m\"\nemission = 2\n\
             translate = [0, 0.99, 0.01]\nrotate = [1, 0, 0, 90]\nscale = [0.23, 0.19, 0.19]\n"
        );
        let parts = load_str(&text, &origin()).unwrap();
        let Shape::Quad(q) = parts.objects[0].shape else {
            panic!("a rectangle is a quad")
        };
        let close = |a: Vec3A, b: Vec3A| (a - b).length() < 1e-6;
        assert!(
            close(q.origin, Vec3A::new(-0.23, 0.99, -0.18)),
            "{}",
            q.origin
        );
        assert!(close(q.e1, Vec3A::new(0.46, 0.0, 0.0)), "{}", q.e1);
        assert!(close(q.e2, Vec3A::new(0.0, 0.0, 0.38)), "{}", q.e2);
        assert!(close(q.e1.cross(q.e2).normalize(), -Vec3A::Y));
        assert_eq!(
            parts.objects[0].emitter,
            Some(Emitter {
                radiance: Color::splat(2.0),
                two_sided: false
            })
        );
    }

    #[test]
    fn a_mesh_next_to_the_scene_file_is_loaded_and_placed() {
        let dir = std::env::temp_dir().join(format!("scenefmt-mesh-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("tri.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").unwrap();
        let path = dir.join("s.toml");
        std::fs::write(
            &path,
            format!(
                "{CAMERA}[materials.m]\ntype = \"lambert\"\nalbedo = 0.5\n\
                 [[shapes]]\ntype = \"mesh\"\nfile = \"tri.obj\"\nmaterial = \"m\"\ntranslate = [0, 0, 2]\n"
            ),
        )
        .unwrap();
        let parts = load_file(&path).unwrap();
        let Shape::Mesh(mesh) = &parts.objects[0].shape else {
            panic!("a mesh")
        };
        assert_eq!(mesh.indices.len(), 1);
        assert_eq!(mesh.positions[1], Vec3::new(1.0, 0.0, 2.0));
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
