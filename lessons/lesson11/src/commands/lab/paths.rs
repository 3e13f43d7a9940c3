//! The path inspector's data: the paths that the current integrator traced
//! for one sample of one pixel, as the page draws them over the picture and
//! lists them in a table.
//!
//! DESIGN.md's contract "Paths can be recorded": an integrator run for one
//! pixel sample hands its vertices, shadow rays and connections to a
//! recorder in `raytracer`, and the slides' path figures and this inspector
//! both come from it. Until that recorder exists, [`PathSource`] of the lab
//! is [`not_recorded`] and the endpoint answers 501 with one line saying so.
//! The shape below is the lab's wire format, kept simple so that the
//! recorder's records map onto it one to one: a path is a list of vertices
//! (camera subpaths, light subpaths, the branches of naive recursion, each
//! branch hanging from a vertex of another path), and every shadow ray or
//! bidirectional connection is a segment between two points.

// The records are made by the path recorder, which is not built yet, and by
// the tests' example record.
#![allow(dead_code)]

use serde::Serialize;

/// Everything recorded for one pixel sample.
#[derive(Clone, Debug, Serialize)]
pub struct PathRecord {
    /// The integrator's name (`path`, `bdpt`, …).
    pub integrator: String,
    pub pixel: [u32; 2],
    /// The sample index k: the sample's random numbers are those of
    /// `Sampler::new(seed, pixel index, k)`, as in the render.
    pub sample: u32,
    /// What the integrator returned for this sample (linear RGB); recording
    /// never changes it.
    pub estimate: [f32; 3],
    pub paths: Vec<RecordedPath>,
    pub segments: Vec<Segment>,
    /// Set when the record was cut short (naive recursion's tree is
    /// truncated to a few thousand vertices), saying what was left out.
    pub truncated: Option<String>,
}

/// A chain of vertices: a camera or light subpath, or one branch of naive
/// recursion.
#[derive(Clone, Debug, Serialize)]
pub struct RecordedPath {
    pub role: PathRole,
    /// The vertex this path continues from (a naive recursion branch starts
    /// at a vertex of its parent path); `None` for a path that starts on the
    /// lens or on a light.
    pub parent: Option<VertexRef>,
    pub vertices: Vec<PathVertex>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum PathRole {
    Camera,
    Light,
    Branch,
}

/// Vertex `vertex` of path `path` of the same record.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct VertexRef {
    pub path: usize,
    pub vertex: usize,
}

/// One vertex and the quantities the estimator computed there.
#[derive(Clone, Debug, Serialize)]
pub struct PathVertex {
    /// World position.
    pub position: [f32; 3],
    /// Where it lies in the picture (pixels from the top left), if the
    /// camera sees it; the lab fills this in.
    pub raster: Option<[f32; 2]>,
    pub kind: VertexKind,
    /// The material's name in the scene (its BRDF), for surface vertices.
    pub brdf: Option<String>,
    /// The density with which this vertex was sampled, and its measure.
    pub pdf: Option<Pdf>,
    /// The path's throughput up to and including this vertex (linear RGB).
    pub throughput: [f32; 3],
    /// The MIS weight of the contribution made here, if any.
    pub mis_weight: Option<f32>,
    /// What this vertex added to the estimate (linear RGB, weighted).
    pub contribution: [f32; 3],
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum VertexKind {
    /// On the lens.
    Camera,
    /// A scattering vertex on a surface.
    Surface,
    /// On a light (an emitter hit, or a light subpath's first vertex).
    Light,
    /// The path left the scene (the environment, or nothing).
    Escaped,
}

/// A density and what it is measured against.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Pdf {
    pub value: f32,
    pub measure: Measure,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Measure {
    /// Per steradian (BRDF sampling, a light sampled by direction).
    SolidAngle,
    /// Per square metre (a point sampled on a light or on the lens).
    Area,
    /// A probability (a delta lobe chosen, a point light).
    Discrete,
}

/// A shadow ray of next event estimation, or a connection of bidirectional
/// tracing (light tracing's connection to the lens is one too).
#[derive(Clone, Debug, Serialize)]
pub struct Segment {
    pub kind: SegmentKind,
    pub from: VertexRef,
    /// The other end: a vertex of the record, or a point sampled on a light.
    pub to: SegmentEnd,
    /// Blocked by geometry: nothing was added.
    pub occluded: bool,
    /// (s, t): light and camera vertices of a bidirectional strategy.
    pub strategy: Option<[u32; 2]>,
    pub mis_weight: Option<f32>,
    pub contribution: [f32; 3],
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum SegmentKind {
    ShadowRay,
    Connection,
}

#[derive(Clone, Debug, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum SegmentEnd {
    Vertex(VertexRef),
    Point {
        position: [f32; 3],
        raster: Option<[f32; 2]>,
    },
}

/// Which pixel sample to inspect, and with what.
pub struct PathQuery<'a> {
    pub scene: &'a raytracer::scene::Scene,
    pub integrator: &'a str,
    pub pixel: [u32; 2],
    pub sample: u32,
    pub seed: u64,
}

/// Where the inspector's records come from: `Err` carries the one-line
/// reason of an HTTP 501.
pub type PathSource = fn(&PathQuery) -> Result<PathRecord, String>;

/// The lab's source until the integrators record their paths.
pub fn not_recorded(_: &PathQuery) -> Result<PathRecord, String> {
    Err(
        "the path inspector needs the path recorder, which this build does not have yet \
         (the integrators do not hand their vertices to a recorder so far)"
            .into(),
    )
}

/// Fills in where each vertex and point lies in the picture.
pub fn project(record: &mut PathRecord, camera: &raytracer::camera::Camera) {
    let raster = |p: [f32; 3]| {
        camera
            .raster_of(raytracer::math::Vec3A::from_array(p), camera.position())
            .map(|r| r.to_array())
    };
    for path in &mut record.paths {
        for v in &mut path.vertices {
            v.raster = raster(v.position);
        }
    }
    for s in &mut record.segments {
        if let SegmentEnd::Point {
            position,
            raster: r,
        } = &mut s.to
        {
            *r = raster(*position);
        }
    }
}
