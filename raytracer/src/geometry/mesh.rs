//! Triangle meshes, loaded from OBJ files or generated (cube, icosphere).

use crate::math::{Vec2, Vec3};

/// An indexed triangle mesh in world space. Vertex arrays use the compact
/// 12-byte `Vec3`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    pub positions: Vec<Vec3>,
    /// Per-vertex normals for smooth shading, or empty (flat shading).
    pub normals: Vec<Vec3>,
    /// Per-vertex texture coordinates, or empty.
    pub uvs: Vec<Vec2>,
    /// Three vertex indices per triangle, counter-clockwise seen from the front.
    pub indices: Vec<[u32; 3]>,
}

/// Why a mesh could not be loaded.
#[derive(Debug)]
pub struct MeshError {
    pub path: String,
    pub message: String,
}

impl std::fmt::Display for MeshError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.path, self.message)
    }
}

impl std::error::Error for MeshError {}

impl Mesh {
    /// Loads an OBJ file (positions, and normals and uvs where present).
    pub fn load_obj(path: &std::path::Path) -> Result<Mesh, MeshError> {
        let _ = path;
        todo!("geometry helper")
    }

    /// Parses OBJ text (for meshes that ship inside the crate); `name` is used in errors.
    pub fn from_obj_str(text: &str, name: &str) -> Result<Mesh, MeshError> {
        let _ = (text, name);
        todo!("geometry helper")
    }

    /// The cube `[-1, 1]³` with outward normals (flat shading).
    pub fn cube() -> Mesh {
        todo!("geometry helper")
    }

    /// This mesh with `transform` applied to positions and normals.
    pub fn transformed(&self, transform: &super::Transform) -> Mesh {
        let _ = transform;
        todo!("geometry helper")
    }
}
