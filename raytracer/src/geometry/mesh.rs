//! Triangle meshes, loaded from OBJ files or generated (cube, icosphere).
//!
//! Lecture topic: none of its own (scene description). OBJ files go through
//! the `tobj` crate, triangulated and with one index per vertex (a vertex
//! with two normals in the file becomes two vertices).

use std::collections::HashMap;
use std::fmt::Write as _;
use std::io::BufRead;

use crate::math::{Vec2, Vec3, Vec3A};

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

/// The largest OBJ file [`Mesh::load_obj`] reads: 256 MiB, some 5 million
/// triangles, which take a few GiB with their BVH (tobj's arrays, the mesh
/// and the BVH need up to about 20 bytes of memory per byte of OBJ text).
pub const MAX_OBJ_FILE_BYTES: u64 = 256 << 20;

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
    ///
    /// All objects and groups of the file are merged into one mesh; faces are
    /// triangulated as fans; materials are ignored. Normals (uvs) are kept
    /// only when every vertex has one; otherwise the mesh is flat shaded
    /// (untextured).
    ///
    /// Only a regular file of at most [`MAX_OBJ_FILE_BYTES`] is read (a
    /// folder, a device such as `/dev/zero` or a huge file is refused before
    /// anything is read into memory).
    pub fn load_obj(path: &std::path::Path) -> Result<Mesh, MeshError> {
        use std::io::Read;
        let name = path.display().to_string();
        let err = |message: String| MeshError {
            path: name.clone(),
            message,
        };
        let file =
            std::fs::File::open(path).map_err(|e| err(format!("cannot open the OBJ file: {e}")))?;
        let meta = file
            .metadata()
            .map_err(|e| err(format!("cannot read the OBJ file: {e}")))?;
        if meta.is_dir() {
            return Err(err("is a folder, not an OBJ file".into()));
        }
        if !meta.is_file() {
            return Err(err(
                "is not a regular file (a device, a pipe or a socket), not an OBJ file".into(),
            ));
        }
        if meta.len() > MAX_OBJ_FILE_BYTES {
            return Err(err(format!(
                "the OBJ file has {} MiB, more than the {} MiB a mesh file may have",
                meta.len() >> 20,
                MAX_OBJ_FILE_BYTES >> 20
            )));
        }
        // `take`: a file that grows while it is read stays bounded too.
        let bounded = file.take(MAX_OBJ_FILE_BYTES);
        Self::from_obj_reader(&mut std::io::BufReader::new(bounded), &name)
    }

    /// Parses OBJ text (for meshes that ship inside the crate); `name` is used in errors.
    pub fn from_obj_str(text: &str, name: &str) -> Result<Mesh, MeshError> {
        Self::from_obj_reader(&mut std::io::Cursor::new(text.as_bytes()), name)
    }

    fn from_obj_reader(reader: &mut impl BufRead, name: &str) -> Result<Mesh, MeshError> {
        let err = |message: String| MeshError {
            path: name.to_string(),
            message,
        };
        // `..Default::default()` covers fields that optional tobj features
        // add (another crate of the workspace might enable them).
        #[allow(clippy::needless_update)]
        let options = tobj::LoadOptions {
            single_index: true,
            triangulate: true,
            ignore_points: true,
            ignore_lines: true,
            ..Default::default()
        };
        let (models, _materials) =
            tobj::load_obj_buf(reader, &options, |_| Err(tobj::LoadError::GenericFailure))
                .map_err(|e| err(format!("not a valid OBJ file ({e})")))?;

        let mut mesh = Mesh::default();
        let mut all_normals = true;
        let mut all_uvs = true;
        for model in &models {
            let m = &model.mesh;
            let nv = m.positions.len() / 3;
            all_normals &= m.normals.len() == 3 * nv;
            all_uvs &= m.texcoords.len() == 2 * nv;
        }
        for model in &models {
            let m = &model.mesh;
            let base = mesh.positions.len();
            let nv = m.positions.len() / 3;
            mesh.positions.extend(
                m.positions
                    .chunks_exact(3)
                    .map(|p| Vec3::new(p[0], p[1], p[2])),
            );
            if all_normals {
                mesh.normals.extend(
                    m.normals
                        .chunks_exact(3)
                        .map(|n| Vec3::new(n[0], n[1], n[2])),
                );
            }
            if all_uvs {
                mesh.uvs
                    .extend(m.texcoords.chunks_exact(2).map(|t| Vec2::new(t[0], t[1])));
            }
            for tri in m.indices.chunks_exact(3) {
                if tri.iter().any(|&i| i as usize >= nv) {
                    return Err(err(format!(
                        "object '{}': vertex index out of range ({} vertices)",
                        model.name, nv
                    )));
                }
                mesh.indices.push([
                    base as u32 + tri[0],
                    base as u32 + tri[1],
                    base as u32 + tri[2],
                ]);
            }
        }
        if mesh.indices.is_empty() {
            return Err(err("the OBJ file contains no triangles".into()));
        }
        if let Some(i) = mesh.positions.iter().position(|p| !p.is_finite()) {
            return Err(err(format!(
                "vertex {} has a non-finite position {}",
                i + 1,
                mesh.positions[i]
            )));
        }
        // Zero or non-finite normals cannot be normalized: fall back to flat.
        if mesh
            .normals
            .iter()
            .any(|n| !n.is_finite() || n.length_squared() == 0.0)
        {
            mesh.normals.clear();
        } else {
            mesh.normals.iter_mut().for_each(|n| *n = n.normalize());
        }
        if mesh.uvs.iter().any(|t| !t.is_finite()) {
            mesh.uvs.clear();
        }
        Ok(mesh)
    }

    /// The cube `[-1, 1]³` with outward normals (flat shading): 24 vertices
    /// (4 per face, so each face has its own uvs `[0,1]²`), 12 triangles.
    pub fn cube() -> Mesh {
        let mut mesh = Mesh::default();
        for axis in 0..3 {
            for sign in [-1.0f32, 1.0] {
                // Outward normal n; tangents u, v with u × v = n, so the
                // corners n ± u ± v in this order run counter-clockwise
                // seen from outside.
                let mut n = Vec3::ZERO;
                n[axis] = sign;
                let mut u = Vec3::ZERO;
                u[(axis + 1) % 3] = 1.0;
                let v = n.cross(u);
                let base = mesh.positions.len() as u32;
                for (a, b) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
                    mesh.positions.push(n + a * u + b * v);
                    mesh.uvs.push(Vec2::new(0.5 * (a + 1.0), 0.5 * (b + 1.0)));
                }
                mesh.indices.push([base, base + 1, base + 2]);
                mesh.indices.push([base, base + 2, base + 3]);
            }
        }
        mesh
    }

    /// The unit sphere approximated by a subdivided icosahedron: each level
    /// splits every triangle into four at its edge midpoints, which are
    /// pushed out onto the sphere. `20·4^level` triangles (level 6: 81,920;
    /// level 8: 1,310,720); the vertex normals are the exact sphere normals.
    pub fn icosphere(level: u32) -> Mesh {
        let g = (1.0 + 5f32.sqrt()) / 2.0;
        let mut positions: Vec<Vec3> = [
            (-1.0, g, 0.0),
            (1.0, g, 0.0),
            (-1.0, -g, 0.0),
            (1.0, -g, 0.0),
            (0.0, -1.0, g),
            (0.0, 1.0, g),
            (0.0, -1.0, -g),
            (0.0, 1.0, -g),
            (g, 0.0, -1.0),
            (g, 0.0, 1.0),
            (-g, 0.0, -1.0),
            (-g, 0.0, 1.0),
        ]
        .iter()
        .map(|&(x, y, z)| Vec3::new(x, y, z).normalize())
        .collect();
        let mut indices: Vec<[u32; 3]> = vec![
            [0, 11, 5],
            [0, 5, 1],
            [0, 1, 7],
            [0, 7, 10],
            [0, 10, 11],
            [1, 5, 9],
            [5, 11, 4],
            [11, 10, 2],
            [10, 7, 6],
            [7, 1, 8],
            [3, 9, 4],
            [3, 4, 2],
            [3, 2, 6],
            [3, 6, 8],
            [3, 8, 9],
            [4, 9, 5],
            [2, 4, 11],
            [6, 2, 10],
            [8, 6, 7],
            [9, 8, 1],
        ];
        for _ in 0..level {
            let mut midpoints: HashMap<u64, u32> = HashMap::with_capacity(indices.len() * 3 / 2);
            let mut midpoint = |a: u32, b: u32, positions: &mut Vec<Vec3>| -> u32 {
                let key = (a.min(b) as u64) << 32 | a.max(b) as u64;
                *midpoints.entry(key).or_insert_with(|| {
                    let m = (positions[a as usize] + positions[b as usize]).normalize();
                    positions.push(m);
                    positions.len() as u32 - 1
                })
            };
            let mut next = Vec::with_capacity(indices.len() * 4);
            for &[a, b, c] in &indices {
                let ab = midpoint(a, b, &mut positions);
                let bc = midpoint(b, c, &mut positions);
                let ca = midpoint(c, a, &mut positions);
                next.extend([[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]);
            }
            indices = next;
        }
        Mesh {
            normals: positions.clone(),
            positions,
            uvs: Vec::new(),
            indices,
        }
    }

    /// This mesh with `transform` applied to positions and normals (normals by
    /// the inverse transpose). A mirroring transform also reverses the
    /// winding, so the geometric normal keeps pointing to the same side of
    /// the surface as the vertex normals.
    pub fn transformed(&self, transform: &super::Transform) -> Mesh {
        let nm = transform.normal_matrix();
        let mut indices = self.indices.clone();
        if transform.flips_handedness() {
            indices.iter_mut().for_each(|t| t.swap(1, 2));
        }
        Mesh {
            positions: self
                .positions
                .iter()
                .map(|&p| transform.apply_point(p.into()).into())
                .collect(),
            normals: self.normals.iter().map(|&n| (nm * n).normalize()).collect(),
            uvs: self.uvs.clone(),
            indices,
        }
    }

    /// The mesh as OBJ text (`v`, `vn`, `vt` and `f` lines). Numbers are
    /// written in Rust's shortest round-trip form, so loading the text back
    /// gives the same floats.
    pub fn to_obj_string(&self) -> String {
        let mut s = String::with_capacity(self.positions.len() * 40 + self.indices.len() * 40);
        let _ = writeln!(
            s,
            "# {} vertices, {} triangles",
            self.positions.len(),
            self.indices.len()
        );
        for p in &self.positions {
            let _ = writeln!(s, "v {} {} {}", p.x, p.y, p.z);
        }
        for n in &self.normals {
            let _ = writeln!(s, "vn {} {} {}", n.x, n.y, n.z);
        }
        for t in &self.uvs {
            let _ = writeln!(s, "vt {} {}", t.x, t.y);
        }
        let (hn, ht) = (!self.normals.is_empty(), !self.uvs.is_empty());
        for tri in &self.indices {
            s.push('f');
            for &i in tri {
                let i = i + 1; // OBJ indices start at 1
                let _ = match (ht, hn) {
                    (false, false) => write!(s, " {i}"),
                    (true, false) => write!(s, " {i}/{i}"),
                    (false, true) => write!(s, " {i}//{i}"),
                    (true, true) => write!(s, " {i}/{i}/{i}"),
                };
            }
            s.push('\n');
        }
        s
    }

    /// Total surface area `Σ ½|e1 × e2|`.
    pub fn area(&self) -> f32 {
        self.indices
            .iter()
            .map(|&[a, b, c]| {
                let p0 = Vec3A::from(self.positions[a as usize]);
                let e1 = Vec3A::from(self.positions[b as usize]) - p0;
                let e2 = Vec3A::from(self.positions[c as usize]) - p0;
                0.5 * e1.cross(e2).length() as f64
            })
            .sum::<f64>() as f32
    }
}
