//! Recording paths: what an integrator traced for one pixel sample.
//!
//! Lecture topic: "Paths" — the pictures of the lecture that show a camera
//! ray, its bounces and shadow rays, a light path joined to the lens, two
//! subpaths and their connection `(s, t)`, or the tree of naive recursion.
//! DESIGN.md's contract "Paths can be recorded": direct lighting, the path
//! tracer, light tracer, bidirectional tracer and naive recursion hand their vertices,
//! shadow rays and connections to a [`Recorder`]; the lab's path inspector
//! and the slides' path figures both read the one [`PathRecord`] it fills.
//!
//! **Recording costs nothing when off.** Each integrator's body is generic
//! over `R: Recorder`; [`Integrator::sample`] runs it with [`NoRecorder`],
//! a zero-sized type whose [`Recorder::record`] is `None` by construction,
//! so the compiler removes every recording branch, and
//! [`Integrator::sample_recorded`] runs the same body with a [`PathRecord`].
//! Recording draws no random number and changes no arithmetic of the
//! estimate: the recorded sample is the rendered sample, bit for bit.
//!
//! **What a record holds.** Paths are chains of vertices: the camera
//! subpath (`x_0` on the lens, or `z_0 …` in bidirectional tracing), the
//! light subpath `y_0 …`, and for naive recursion one path per ray, hanging
//! from the vertex it left (its `parent`). Every vertex carries its position,
//! material, the density with which it was sampled and its measure, the
//! throughput `β` up to it, and what it added to the estimate (with the MIS
//! weight applied). Shadow rays of next event estimation and bidirectional
//! connections are segments, with their MIS weight and weighted
//! contribution; a contribution that lands on another pixel (light
//! tracing, `t = 1`) names the raster position it was splatted to. Shadow
//! rays and bidirectional connections, those to the lens (`t = 1`)
//! included, are recorded blocked or not (one that would carry nothing
//! unblocked is not). A weighted bidirectional contribution also carries
//! every strategy's weight for its path ([`super::mis_weight::mis_weights`],
//! the integrator's own MIS code), so the weights can be seen to add up to 1.
//!
//! The sum of a record's contributions is the estimate: the vertices' and
//! unsplatted segments' contributions add up to what `sample` returned, and
//! the splatted ones are its splats ([`PathRecord::pixel_sum`],
//! [`PathRecord::splats`]; `tests/record.rs` holds each integrator to it).
//!
//! **Truncation.** Naive recursion traces up to `N^D` rays per sample; a
//! record keeps the first [`MAX_RECORDED_VERTICES`] vertices (depth first,
//! the order they are traced) and says in [`PathRecord::truncated`] how many
//! rays were left out.

use serde::Serialize;

use super::Integrator;
use super::camera_connection::CameraConnection;
use super::vertex::{Vertex, VertexKind as SubpathVertexKind};
use crate::brdf::TransportMode;
use crate::camera::Camera;
use crate::film::Splat;
use crate::geometry::Interaction;
use crate::math::{Color, Ray, UVec2, Vec2, Vec3A};
use crate::sampling::Sampler;
use crate::scene::Scene;

/// The most vertices one record keeps (naive recursion's tree is cut there).
pub const MAX_RECORDED_VERTICES: usize = 2000;

/// Where an integrator hands what it traces. Integrators ask
/// [`Recorder::record`] and record only when it is `Some`.
pub trait Recorder {
    /// The record to fill, or `None` when nothing is recorded.
    fn record(&mut self) -> Option<&mut PathRecord>;
}

/// Records nothing: the recorder of an ordinary render (zero-sized, every
/// recording branch compiled away).
#[derive(Clone, Copy, Debug, Default)]
pub struct NoRecorder;

impl Recorder for NoRecorder {
    #[inline(always)]
    fn record(&mut self) -> Option<&mut PathRecord> {
        None
    }
}

impl Recorder for PathRecord {
    #[inline]
    fn record(&mut self) -> Option<&mut PathRecord> {
        Some(self)
    }
}

/// Everything recorded for one pixel sample.
#[derive(Clone, Debug, Default, Serialize)]
pub struct PathRecord {
    /// The integrator's name (`path`, `bdpt`, …).
    pub integrator: String,
    pub pixel: [u32; 2],
    /// The sample index k: its random numbers are those of
    /// `Sampler::new(seed, y·width + x, k)`, as in the render.
    pub sample: u32,
    /// What the integrator returned for this sample (linear RGB).
    pub estimate: [f32; 3],
    pub paths: Vec<RecordedPath>,
    pub segments: Vec<Segment>,
    /// Set when the record was cut short or the integrator records nothing,
    /// saying what was left out.
    pub truncated: Option<String>,
    /// Vertices not recorded (past [`MAX_RECORDED_VERTICES`]).
    #[serde(skip)]
    dropped: u64,
}

/// A chain of vertices: a camera or light subpath, or one ray of naive
/// recursion.
#[derive(Clone, Debug, Serialize)]
pub struct RecordedPath {
    pub role: PathRole,
    /// The vertex this path continues from (a ray of naive recursion leaves
    /// a vertex of its parent's path); `None` for a path that starts on the
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
    /// camera sees it: [`PathRecord::project`] fills it in.
    pub raster: Option<[f32; 2]>,
    pub kind: VertexKind,
    /// The material's name in the scene (its BRDF), for surface vertices.
    pub brdf: Option<String>,
    /// The density with which this vertex was sampled, and its measure.
    pub pdf: Option<Pdf>,
    /// The path's throughput β up to this vertex (linear RGB), the factor
    /// of this vertex itself excluded.
    pub throughput: [f32; 3],
    /// The MIS weight of the contribution made here, if any.
    pub mis_weight: Option<f32>,
    /// For a bidirectional path that hit a light here (`s = 0`): every
    /// strategy's weight for that path (see [`Segment::strategy_weights`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub strategy_weights: Option<Vec<f32>>,
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
    /// The ray left the scene (the environment, or nothing); its position
    /// is a point far along the ray, outside the scene's bounds.
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

impl Pdf {
    /// A direction's density: per unit solid angle, or discrete for a delta lobe.
    pub fn direction(pdf_w: f32, is_delta: bool) -> Pdf {
        Pdf {
            value: pdf_w,
            measure: if is_delta {
                Measure::Discrete
            } else {
                Measure::SolidAngle
            },
        }
    }
}

/// A shadow ray of next event estimation, or a connection of bidirectional
/// tracing (light tracing's connection to the lens is one too).
#[derive(Clone, Debug, Serialize)]
pub struct Segment {
    pub kind: SegmentKind,
    pub from: VertexRef,
    /// The other end: a vertex of the record, or a point sampled on a light
    /// or on the lens.
    pub to: SegmentEnd,
    /// Blocked by geometry: nothing was added.
    pub occluded: bool,
    /// (s, t): light and camera vertices of a bidirectional strategy.
    pub strategy: Option<[u32; 2]>,
    pub mis_weight: Option<f32>,
    /// For a weighted bidirectional connection `(s, t)`: entry `i` is the
    /// MIS weight strategy `(i, s + t − i)` has for the same path, as the
    /// integrator computes them ([`super::mis_weight::mis_weights`]); entry
    /// `s` is `mis_weight`, and they add up to 1.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub strategy_weights: Option<Vec<f32>>,
    /// What it added (linear RGB, weighted).
    pub contribution: [f32; 3],
    /// The raster position its contribution was splatted to, when it lands
    /// on another pixel than the sample's own (connections to the lens).
    pub splat: Option<[f32; 2]>,
}

impl Segment {
    /// A bidirectional connection `(s, t)` that contributed `c` (weighted by
    /// `w`), splatted at `splat` if it lands on another pixel.
    pub fn connection(
        from: VertexRef,
        to: SegmentEnd,
        strategy: [usize; 2],
        w: Option<f32>,
        c: Color,
        splat: Option<Vec2>,
    ) -> Segment {
        Segment {
            kind: SegmentKind::Connection,
            from,
            to,
            occluded: false,
            strategy: Some(strategy.map(|n| n as u32)),
            mis_weight: w,
            strategy_weights: None,
            contribution: c.to_array(),
            splat: splat.map(|r| r.to_array()),
        }
    }

    /// Light tracing's connection of light vertex `from` (`y_{s−1}`) to the
    /// lens, `t = 1`: splatted where it lands, or blocked (adding nothing).
    pub fn lens_connection(
        from: VertexRef,
        c: &CameraConnection,
        s: usize,
        occluded: bool,
    ) -> Segment {
        let to = SegmentEnd::point(c.camera.p_lens);
        if occluded {
            return Segment {
                occluded,
                ..Segment::connection(from, to, [s, 1], None, Color::ZERO, None)
            };
        }
        Segment::connection(from, to, [s, 1], None, c.value, Some(c.camera.raster))
    }
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

impl SegmentEnd {
    /// A sampled point (on a light or the lens), not a vertex of the record.
    pub fn point(p: Vec3A) -> SegmentEnd {
        SegmentEnd::Point {
            position: p.to_array(),
            raster: None,
        }
    }
}

impl PathVertex {
    fn new(p: Vec3A, kind: VertexKind, beta: Color) -> PathVertex {
        PathVertex {
            position: p.to_array(),
            raster: None,
            kind,
            brdf: None,
            pdf: None,
            throughput: beta.to_array(),
            mis_weight: None,
            strategy_weights: None,
            contribution: [0.0; 3],
        }
    }

    /// A camera vertex on the lens.
    pub fn camera(p: Vec3A, beta: Color) -> PathVertex {
        PathVertex::new(p, VertexKind::Camera, beta)
    }

    /// A surface hit with its material; a light if the surface emits.
    pub fn surface(scene: &Scene, it: &Interaction, pdf: Pdf, beta: Color) -> PathVertex {
        let kind = if scene.area_light(it).is_some() {
            VertexKind::Light
        } else {
            VertexKind::Surface
        };
        let mut v = PathVertex::new(it.p, kind, beta);
        v.brdf = Some(material_name(scene, it));
        v.pdf = Some(pdf);
        v
    }

    /// What `ray` found: the surface `hit`, or nothing.
    pub fn hit(
        scene: &Scene,
        ray: &Ray,
        hit: Option<&Interaction>,
        pdf: Pdf,
        beta: Color,
    ) -> PathVertex {
        match hit {
            Some(it) => PathVertex::surface(scene, it, pdf, beta),
            None => PathVertex::escaped(scene, ray, Some(pdf), beta),
        }
    }

    /// A ray that hit nothing, drawn to a point beyond the scene's bounds.
    pub fn escaped(scene: &Scene, ray: &Ray, pdf: Option<Pdf>, beta: Color) -> PathVertex {
        let reach = scene.geometry.bounds().diagonal().length().max(1.0);
        let mut v = PathVertex::new(ray.o + ray.d * reach, VertexKind::Escaped, beta);
        v.pdf = pdf;
        v
    }

    /// A vertex of a camera or light subpath (bidirectional machinery), with
    /// its forward area density (see [`subpath_pdf`] for the measures a
    /// whole subpath's vertices are labelled with).
    pub fn subpath(scene: &Scene, v: &Vertex) -> PathVertex {
        let kind = match v.kind {
            SubpathVertexKind::Camera => VertexKind::Camera,
            SubpathVertexKind::Light => VertexKind::Light,
            SubpathVertexKind::Surface if scene.area_light(&v.it).is_some() => VertexKind::Light,
            SubpathVertexKind::Surface => VertexKind::Surface,
        };
        let mut r = PathVertex::new(v.p(), kind, v.beta);
        if v.kind == SubpathVertexKind::Surface {
            r.brdf = Some(material_name(scene, &v.it));
        }
        r.pdf = Some(Pdf {
            value: v.pdf_fwd_a,
            measure: Measure::Area,
        });
        r
    }
}

/// The density of subpath vertex `i`, in the measure the path tracer's
/// record uses for the same kind of vertex. Most vertices are sampled per
/// unit area (`pdf_fwd_a`). Three are not, and the MIS machinery's area
/// densities would mislabel them: a pinhole's lens point and a point
/// light's position are fixed (discrete: probability 1, times the light's
/// choice probability), and a vertex reached through a delta lobe (mirror,
/// glass) was chosen with the lobe's probability (discrete; the machinery
/// stores 0 there, pbrt's convention for MIS). A thin lens's point is
/// uniform on the lens, `1/A_lens` per unit area.
fn subpath_pdf(scene: &Scene, path: &[Vertex], i: usize) -> Pdf {
    let v = &path[i];
    let per_area = |value| Pdf {
        value,
        measure: Measure::Area,
    };
    let discrete = |value| Pdf {
        value,
        measure: Measure::Discrete,
    };
    match v.kind {
        SubpathVertexKind::Camera => {
            let r = scene.camera.params.aperture_radius;
            if r > 0.0 {
                per_area(1.0 / (std::f32::consts::PI * r * r))
            } else {
                discrete(1.0)
            }
        }
        SubpathVertexKind::Light if v.is_delta_light(scene) => discrete(v.pdf_fwd_a),
        _ if i > 0 && path[i - 1].delta => discrete(delta_lobe_probability(scene, &path[i - 1], v)),
        _ => per_area(v.pdf_fwd_a),
    }
}

/// The probability with which the delta lobe at `at` that leads to `next`
/// was chosen: 1 for a mirror, Fresnel's `F` or `1 − F` for glass's
/// reflection or refraction (the BRDF's own sampling, asked for that lobe).
fn delta_lobe_probability(scene: &Scene, at: &Vertex, next: &Vertex) -> f32 {
    let it = &at.it;
    let wo = it.frame.to_local(it.wo);
    let wi = it.frame.to_local((next.p() - at.p()).normalize_or_zero());
    // Glass reflects when u_lobe < F: 0 asks for reflection, the largest
    // number below 1 for refraction.
    let u_lobe = if wo.z * wi.z > 0.0 {
        0.0
    } else {
        1.0 - f32::EPSILON / 2.0
    };
    scene
        .brdf(it)
        .sample(wo, it.uv, u_lobe, Vec2::ZERO, TransportMode::Radiance)
        .map_or(0.0, |s| s.pdf_w)
}

/// The scene's name of the material at `it`.
fn material_name(scene: &Scene, it: &Interaction) -> String {
    let brdf = scene.objects[it.shape as usize].brdf as usize;
    scene
        .brdf_names
        .get(brdf)
        .cloned()
        .unwrap_or_else(|| format!("brdf {brdf}"))
}

impl PathRecord {
    /// An empty record of pixel `pixel`, sample `sample`.
    pub fn new(integrator: &str, pixel: UVec2, sample: u32) -> PathRecord {
        PathRecord {
            integrator: integrator.to_string(),
            pixel: pixel.to_array(),
            sample,
            ..PathRecord::default()
        }
    }

    fn vertex_count(&self) -> usize {
        self.paths.iter().map(|p| p.vertices.len()).sum()
    }

    /// Starts a path whose first vertex is `first`; `None` (and the vertex
    /// counted as left out) when the record is full or the parent was not
    /// recorded.
    pub fn start_path(
        &mut self,
        role: PathRole,
        parent: Option<VertexRef>,
        first: PathVertex,
    ) -> Option<VertexRef> {
        let orphan = role == PathRole::Branch && parent.is_none();
        if orphan || self.vertex_count() >= MAX_RECORDED_VERTICES {
            self.dropped += 1;
            return None;
        }
        self.paths.push(RecordedPath {
            role,
            parent,
            vertices: vec![first],
        });
        Some(VertexRef {
            path: self.paths.len() - 1,
            vertex: 0,
        })
    }

    /// Records a camera or light subpath of the bidirectional machinery as
    /// one path; returns its index (`None` if empty or the record is full).
    pub fn push_subpath(
        &mut self,
        scene: &Scene,
        role: PathRole,
        path: &[Vertex],
    ) -> Option<usize> {
        let vertex = |i: usize| PathVertex {
            pdf: Some(subpath_pdf(scene, path, i)),
            ..PathVertex::subpath(scene, &path[i])
        };
        if path.is_empty() {
            return None;
        }
        let mut at = self.start_path(role, None, vertex(0));
        for i in 1..path.len() {
            at = self.push_vertex(at, vertex(i));
        }
        at.map(|r| r.path)
    }

    /// Appends `v` to the path of `after` (a path's vertices are in order).
    pub fn push_vertex(&mut self, after: Option<VertexRef>, v: PathVertex) -> Option<VertexRef> {
        let Some(after) = after else {
            self.dropped += 1;
            return None;
        };
        if self.vertex_count() >= MAX_RECORDED_VERTICES {
            self.dropped += 1;
            return None;
        }
        let path = &mut self.paths[after.path].vertices;
        path.push(v);
        Some(VertexRef {
            path: after.path,
            vertex: path.len() - 1,
        })
    }

    /// Sets every strategy's weight for the path that ends at vertex `at`
    /// (a bidirectional camera path that hit a light).
    pub fn strategy_weights(&mut self, at: Option<VertexRef>, weights: Vec<f32>) {
        if let Some(at) = at {
            self.paths[at.path].vertices[at.vertex].strategy_weights = Some(weights);
        }
    }

    /// Adds `c` with MIS weight `w` to what vertex `at` contributed.
    pub fn contribute(&mut self, at: Option<VertexRef>, c: Color, w: Option<f32>) {
        let Some(at) = at else { return };
        let v = &mut self.paths[at.path].vertices[at.vertex];
        v.contribution = (Color::from_array(v.contribution) + c).to_array();
        if w.is_some() {
            v.mis_weight = w;
        }
    }

    /// Adds a shadow ray or connection that leaves the recorded vertex `from`.
    pub fn push_segment(
        &mut self,
        from: Option<VertexRef>,
        segment: impl FnOnce(VertexRef) -> Segment,
    ) {
        if let Some(from) = from {
            self.segments.push(segment(from));
        }
    }

    /// The sum of the contributions to the sample's own pixel: the
    /// vertices' and the segments' that were not splatted. Equals the
    /// estimate up to the order of the additions.
    pub fn pixel_sum(&self) -> Color {
        let vertices = self
            .paths
            .iter()
            .flat_map(|p| &p.vertices)
            .map(|v| Color::from_array(v.contribution));
        let segments = self
            .segments
            .iter()
            .filter(|s| s.splat.is_none())
            .map(|s| Color::from_array(s.contribution));
        vertices.chain(segments).sum()
    }

    /// The splatted contributions, in the order they were made.
    pub fn splats(&self) -> Vec<Splat> {
        self.segments
            .iter()
            .filter_map(|s| {
                Some(Splat {
                    raster: Vec2::from_array(s.splat?),
                    value: Color::from_array(s.contribution),
                })
            })
            .collect()
    }

    /// Fills in where each vertex and sampled point lies in the picture of
    /// `camera` (as seen from the lens centre; also off the film, where a
    /// drawing clips it; `None` behind the camera).
    pub fn project(&mut self, camera: &Camera) {
        let raster = |p: [f32; 3]| {
            camera
                .raster_beyond_film(Vec3A::from_array(p), camera.position())
                .map(|r| r.to_array())
        };
        for path in &mut self.paths {
            for v in &mut path.vertices {
                v.raster = raster(v.position);
            }
        }
        for s in &mut self.segments {
            if let SegmentEnd::Point {
                position,
                raster: r,
            } = &mut s.to
            {
                *r = raster(*position);
            }
        }
    }

    /// The vertex `r` refers to.
    pub fn vertex(&self, r: VertexRef) -> &PathVertex {
        &self.paths[r.path].vertices[r.vertex]
    }

    fn finish(&mut self, estimate: Color) {
        self.estimate = estimate.to_array();
        if self.dropped > 0 {
            self.truncated = Some(format!(
                "the first {MAX_RECORDED_VERTICES} vertices are recorded, {} more rays were \
                 traced and left out",
                self.dropped
            ));
        }
    }
}

/// Records pixel `pixel`'s sample `k` of a render with seed `seed`: the
/// random numbers are the render's (`Sampler::new(seed, y·width + x, k)`),
/// so the record is of the very sample the render averaged. Returns the
/// record (with its estimate) and the sample's splats.
pub fn record_sample(
    integrator: &dyn Integrator,
    scene: &Scene,
    pixel: UVec2,
    seed: u64,
    k: u32,
) -> (PathRecord, Vec<Splat>) {
    let index = pixel.y as u64 * scene.camera.width as u64 + pixel.x as u64;
    let mut sampler = Sampler::new(seed, index, k as u64);
    let mut record = PathRecord::new(integrator.name(), pixel, k);
    let mut splats = Vec::new();
    let estimate = integrator.sample_recorded(scene, pixel, &mut sampler, &mut splats, &mut record);
    record.finish(estimate);
    (record, splats)
}
