//! Geometry: the shapes of a scene and the acceleration structure that finds
//! the first surface a ray meets.
//!
//! Lecture topic: none of its own (ray-surface intersection is the subject of
//! the earlier lectures); every algorithm of Lecture 11 is built on
//! [`Geometry::intersect`] and [`Geometry::occluded`].
//!
//! All primitives of a scene (triangles of every mesh, spheres, quads) live in
//! one binned-SAH BVH. A [`Hit`] is what traversal returns (distance, primitive,
//! two surface parameters); [`Geometry::surface_point`] turns it into a
//! [`SurfacePoint`] with position, normals and texture coordinates only for the
//! hit that is finally kept.

pub mod aabb;
pub mod bvh;
pub mod mesh;
pub mod quad;
pub mod sphere;
pub mod transform;

use std::sync::Arc;

use crate::math::{Vec2, Vec3A};

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
}
