//! Geometry: the shapes of a scene and the acceleration structure that finds
//! the first surface a ray meets.
//!
//! Lecture topic: none of its own (ray-surface intersection is the subject of
//! the earlier lectures); every algorithm of Lecture 11 is built on
//! [`Geometry::intersect`] and [`Geometry::occluded`].
//!
//! All primitives of a scene (triangles of every mesh, spheres, quads) live in
//! one binned-SAH BVH ([`bvh`], traversed four-wide by [`bvh4`], or by ray
//! packets). Triangles use a watertight test ([`triangle`]): rays do not
//! slip through the shared edges of a mesh. A [`Hit`] is what traversal returns (distance, primitive,
//! two surface parameters); [`Geometry::surface_point`] turns it into a
//! [`SurfacePoint`] with position, normals and texture coordinates only for the
//! hit that is finally kept.

pub mod aabb;
pub mod bvh;
pub mod bvh4;
pub mod interaction;
pub mod mesh;
mod packet;
pub mod primitive;
pub mod quad;
pub mod sphere;
pub mod stream;
pub mod transform;
pub mod triangle;

use std::sync::Arc;

use rayon::prelude::*;

use crate::math::{Ray, Vec2, Vec3A, gamma};

pub use aabb::Aabb;
pub use bvh::Bvh;
pub use bvh4::Bvh4;
pub use interaction::Interaction;
pub use mesh::{Mesh, MeshError};
pub use quad::Quad;
pub use sphere::Sphere;
pub use transform::Transform;

/// One shape of a scene, as the scene description lists it.
#[derive(Clone, Debug)]
pub enum Shape {
    Sphere(Sphere),
    Quad(Quad),
    /// A triangle mesh, already transformed to world space.
    Mesh(Arc<Mesh>),
}

/// The closest intersection found by traversal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// Distance along the ray (the ray's direction is unit, so metres).
    pub t: f32,
    /// Index of the primitive in [`Geometry`]'s own order.
    pub prim: u32,
    /// Surface parameters of the hit: barycentrics `(b1, b2)` of a triangle,
    /// `(a, b)` of a quad's edges; unused for spheres.
    pub uv: Vec2,
}

/// Everything shading needs to know about a hit point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfacePoint {
    /// Position in world space.
    pub p: Vec3A,
    /// Geometric normal, unit, oriented as the shape defines it (outwards for
    /// spheres, `e1 × e2` for quads, counter-clockwise winding for triangles).
    /// It is *not* flipped towards the ray; integrators decide sides.
    pub ng: Vec3A,
    /// Shading normal (interpolated vertex normal of a smooth mesh; equal to
    /// `ng` otherwise), on the same side as `ng`.
    pub ns: Vec3A,
    /// Texture coordinates in `[0,1]²` (from the OBJ file, the quad's edges,
    /// or the sphere's longitude and latitude).
    pub uv: Vec2,
    /// Index of the [`Shape`] hit, in the order given to [`Geometry::new`].
    pub shape: u32,
    /// Bound on the rounding error of each coordinate of `p` (pbrt's
    /// `pError`): how far the computed point may lie from the true surface,
    /// which rays leaving it must clear ([`crate::math::offset_ray_origin`]).
    pub p_error: Vec3A,
}

/// Where a primitive comes from: shape index and, for a mesh, triangle index.
#[derive(Clone, Copy, Debug)]
struct PrimSource {
    shape: u32,
    local: u32,
}

/// The shapes of a scene with one BVH over all their primitives (every
/// triangle of every mesh, every sphere, every quad).
///
/// The binary SAH tree ([`Bvh`]) is collapsed into a four-wide one
/// ([`Bvh4`]) for single rays; coherent rays can also be traced four or
/// sixteen at a time through the binary tree ([`Geometry::intersect4`],
/// [`Geometry::intersect16`]). What each gains is measured in the README's
/// performance section (`lesson11 bench`).
///
/// Primitive data is stored in BVH leaf order ([`primitive::PrimRecord`]); a
/// [`Hit::prim`] is an index into that order, and [`Geometry::surface_point`]
/// maps it back to the shape.
#[derive(Clone, Debug)]
pub struct Geometry {
    shapes: Vec<Shape>,
    bounds: Aabb,
    /// The binary tree (its `order` dropped), traversed by ray packets.
    binary: Bvh,
    pub bvh: Bvh4,
    pub prims: Vec<primitive::PrimRecord>,
    sources: Vec<PrimSource>,
}

/// A primitive's box, padded by a few ulps of its size and position: quads
/// accept edge parameters a hair outside `[0, 1]` (see `QUAD_EPS`), a quad's
/// corners `origin + e1 + e2` are rounded, and slab tests round too; hits
/// near the edges must still lie inside the boxes traversal tests.
pub fn padded_bounds(r: &primitive::PrimRecord) -> Aabb {
    let a = Vec3A::from_vec4(r.a);
    let b = Vec3A::from_vec4(r.b);
    let c = Vec3A::from_vec4(r.c);
    let bounds = match r.kind() {
        primitive::KIND_SPHERE => Aabb::new(a - Vec3A::splat(r.b.x), a + Vec3A::splat(r.b.x)),
        primitive::KIND_QUAD => {
            let mut bb = Aabb::new(a, a + b);
            bb.grow(a + c);
            bb.grow(a + b + c);
            bb
        }
        _ => {
            let mut bb = Aabb::new(a, b);
            bb.grow(c);
            bb
        }
    };
    let pad = 4e-6
        * (bounds.diagonal().max_element() + bounds.min.abs().max(bounds.max.abs()).max_element());
    Aabb {
        min: bounds.min - Vec3A::splat(pad),
        max: bounds.max + Vec3A::splat(pad),
    }
}

impl Geometry {
    /// Builds the BVH over all primitives of `shapes`.
    pub fn new(shapes: Vec<Shape>) -> Geometry {
        let mut records = Vec::new();
        let mut sources = Vec::new();
        for (s, shape) in shapes.iter().enumerate() {
            let shape_id = s as u32;
            match shape {
                Shape::Sphere(sp) => {
                    records.push(primitive::PrimRecord::sphere(sp.center, sp.radius));
                    sources.push(PrimSource {
                        shape: shape_id,
                        local: 0,
                    });
                }
                Shape::Quad(q) => {
                    records.push(primitive::PrimRecord::quad(q.origin, q.e1, q.e2));
                    sources.push(PrimSource {
                        shape: shape_id,
                        local: 0,
                    });
                }
                Shape::Mesh(m) => {
                    let p = &m.positions;
                    records.par_extend(m.indices.par_iter().map(|&[a, b, c]| {
                        primitive::PrimRecord::triangle(
                            p[a as usize].into(),
                            p[b as usize].into(),
                            p[c as usize].into(),
                        )
                    }));
                    sources.par_extend((0..m.indices.len() as u32).into_par_iter().map(|local| {
                        PrimSource {
                            shape: shape_id,
                            local,
                        }
                    }));
                }
            }
        }
        let bounds: Vec<Aabb> = records.par_iter().map(padded_bounds).collect();
        let mut binary = Bvh::build(&bounds);
        let prims = binary
            .order
            .par_iter()
            .map(|&i| records[i as usize])
            .collect();
        let sources = binary
            .order
            .par_iter()
            .map(|&i| sources[i as usize])
            .collect();
        let bvh = Bvh4::from_binary(&binary);
        binary.order = Vec::new();
        Geometry {
            shapes,
            bounds: binary.bounds(),
            binary,
            bvh,
            prims,
            sources,
        }
    }

    /// The shapes, in the order given to [`Geometry::new`].
    pub fn shapes(&self) -> &[Shape] {
        &self.shapes
    }

    /// A box around every primitive (empty without primitives).
    pub fn bounds(&self) -> Aabb {
        self.bounds
    }

    /// Number of primitives (triangles + spheres + quads).
    pub fn primitive_count(&self) -> usize {
        self.prims.len()
    }

    /// Number of (four-wide) BVH nodes.
    pub fn node_count(&self) -> usize {
        self.bvh.nodes.len()
    }

    /// The closest hit with `t ∈ (0, ray.t_max)`.
    #[inline]
    pub fn intersect(&self, ray: &Ray) -> Option<Hit> {
        let (o, d) = (ray.o, ray.d);
        let prims = &self.prims[..];
        let mut best: Option<Hit> = None;
        self.bvh.traverse(o, d, ray.t_max, |first, count, t_max| {
            let leaf = &prims[first as usize..(first + count) as usize];
            for (k, prim) in leaf.iter().enumerate() {
                if let Some((t, uv)) = prim.intersect(o, d, *t_max) {
                    *t_max = t;
                    best = Some(Hit {
                        t,
                        prim: first + k as u32,
                        uv,
                    });
                }
            }
            false
        });
        best
    }

    /// True when anything lies on the ray for `t ∈ (0, ray.t_max)` (stops at
    /// the first primitive found, in no particular order).
    #[inline]
    pub fn occluded(&self, ray: &Ray) -> bool {
        let (o, d) = (ray.o, ray.d);
        let prims = &self.prims[..];
        let t_max = ray.t_max;
        self.bvh.traverse_any(o, d, t_max, |first, count| {
            prims[first as usize..(first + count) as usize]
                .iter()
                .any(|prim| prim.intersect(o, d, t_max).is_some())
        })
    }

    /// The closest hit by testing every primitive (for tests and for
    /// checking the BVH).
    pub fn intersect_brute_force(&self, ray: &Ray) -> Option<Hit> {
        let mut best: Option<Hit> = None;
        let mut t_max = ray.t_max;
        for (i, prim) in self.prims.iter().enumerate() {
            if let Some((t, uv)) = prim.intersect(ray.o, ray.d, t_max) {
                t_max = t;
                best = Some(Hit {
                    t,
                    prim: i as u32,
                    uv,
                });
            }
        }
        best
    }

    /// The first surface along `ray` as an [`Interaction`]: the closest hit
    /// with its surface point, seen from the ray (`ω_o = −d`).
    #[inline]
    pub fn interaction(&self, ray: &Ray) -> Option<Interaction> {
        let hit = self.intersect(ray)?;
        let sp = self.surface_point(ray, &hit);
        Some(Interaction::new(sp, hit.t, -ray.d))
    }

    /// Position, normals, texture coordinates and shape of a hit found by
    /// [`Geometry::intersect`] for `ray`.
    pub fn surface_point(&self, ray: &Ray, hit: &Hit) -> SurfacePoint {
        let src = self.sources[hit.prim as usize];
        match &self.shapes[src.shape as usize] {
            Shape::Sphere(s) => {
                // o + t·d is off by a few ulps of t; reprojecting onto the
                // sphere removes that error.
                let p = s.reproject(ray.at(hit.t));
                let ng = s.normal(p);
                SurfacePoint {
                    p,
                    ng,
                    ns: ng,
                    uv: Sphere::uv(ng),
                    shape: src.shape,
                    // c + r·(p' − c)/|p' − c|: a normalisation and a sum
                    // (pbrt's γ₅ |p − c| for the reprojection, plus the
                    // centre's addition).
                    p_error: gamma(5) * ((p - s.center).abs() + s.center.abs()),
                }
            }
            Shape::Quad(q) => {
                let ng = q.normal();
                let (a, b) = (hit.uv.x, hit.uv.y);
                SurfacePoint {
                    p: q.point(a, b),
                    ng,
                    ns: ng,
                    uv: hit.uv,
                    shape: src.shape,
                    // origin + a·e1 + b·e2: two products, two sums.
                    p_error: gamma(3) * (q.origin.abs() + (a * q.e1).abs() + (b * q.e2).abs()),
                }
            }
            Shape::Mesh(m) => {
                let [i0, i1, i2] = m.indices[src.local as usize].map(|i| i as usize);
                let (b1, b2) = (hit.uv.x, hit.uv.y);
                let b0 = 1.0 - b1 - b2;
                let v = |i: usize| Vec3A::from(m.positions[i]);
                let (p0, p1, p2) = (v(i0), v(i1), v(i2));
                // p = b0·p0 + b1·p1 + b2·p2 lies on the triangle up to
                // rounding of the vertices, unlike o + t·d.
                let p = b0 * p0 + b1 * p1 + b2 * p2;
                let ng = (p1 - p0).cross(p2 - p0).normalize_or(Vec3A::Z);
                let ns = if m.normals.is_empty() {
                    ng
                } else {
                    let n = |i: usize| Vec3A::from(m.normals[i]);
                    let ns = (b0 * n(i0) + b1 * n(i1) + b2 * n(i2)).normalize_or(ng);
                    if ns.dot(ng) < 0.0 { -ns } else { ns }
                };
                let uv = if m.uvs.is_empty() {
                    hit.uv
                } else {
                    b0 * m.uvs[i0] + b1 * m.uvs[i1] + b2 * m.uvs[i2]
                };
                SurfacePoint {
                    p,
                    ng,
                    ns,
                    uv,
                    shape: src.shape,
                    // b0·p0 + b1·p1 + b2·p2 with b0 = 1 − b1 − b2 (pbrt's γ₇).
                    p_error: gamma(7) * ((b0 * p0).abs() + (b1 * p1).abs() + (b2 * p2).abs()),
                }
            }
        }
    }
}
