//! Bidirectional path tracing (Veach and Guibas 1994; Veach's thesis, ch. 10).
//!
//! Lecture topic: "Bidirectional path tracing". Each pixel sample builds a
//! camera subpath `z_0 … z_{n_C−1}` and a light subpath `y_0 … y_{n_L−1}` and
//! joins every prefix pair: the strategy `(s, t)` uses `s` light and `t`
//! camera vertices and forms the path `y_0 … y_{s−1} z_{t−1} … z_0`:
//!
//! - `s = 0`: the camera subpath itself hits a light (what a path tracer
//!   without next event estimation does);
//! - `s = 1`: next event estimation — the light vertex is *resampled* from
//!   `z_{t−1}` by the path tracer's own light sampling
//!   ([`nee::sample_light_point`]; pbrt does the same: it is a better point
//!   than `y_0`);
//! - `t = 1`: light tracing — `y_{s−1}` joined to a new lens point and
//!   splatted where it lands ([`super::camera_connection::connect_to_camera`]);
//! - otherwise: `y_{s−1}` and `z_{t−1}` joined by a shadow ray; the edge
//!   brings the scattering at both of its ends and its geometry term.
//!
//! Each contribution is unweighted: the path's measurement contribution over
//! the strategy's density (area measure). Every one is weighted by the power
//! heuristic over all strategies that could have generated the same path
//! ([`mis_weight`]), so the sum over `(s, t)` is an unbiased estimate that
//! keeps the best of each: NEE for small lights, light tracing for caustics
//! seen through diffuse surfaces, hitting for large lights and glossy paths.
//!
//! Depth: paths of at most `D + 1` vertices for Mitsuba's `max_depth = D`, so
//! `s + t ≤ D + 1`; the camera subpath keeps at most `D + 1` vertices, the
//! light subpath at most `D`.
//!
//! For the lesson, a [`StrategyFilter`] keeps the contribution of one
//! `(s, t)` alone, weighted or unweighted (pbrt's `visualizestrategies`);
//! [`crate::render::render_strategies`] renders every strategy's image.

use super::Integrator;
use super::camera_connection::{join_lens, sees_lens};
use super::dimensions::LENS;
use super::mis_weight::{mis_weight, mis_weights};
use super::nee::{self, LightPoint};
use super::record::{
    NoRecorder, PathRecord, PathRole, PathVertex, Recorder, Segment, SegmentEnd, VertexRef,
};
use super::subpath::{EscapedRay, camera_subpath, light_subpath};
use super::vertex::{Vertex, path_vertices, visible, with_subpaths};
use crate::film::Splat;
use crate::math::{Color, Ray, UVec2, Vec2};
use crate::sampling::{Sampler, Stream};
use crate::scene::Scene;

/// Which contributions a [`Bdpt`] keeps (for the per-strategy images).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StrategyFilter {
    /// Light vertices.
    pub s: u32,
    /// Camera vertices.
    pub t: u32,
    /// Multiply by the MIS weight (false: the strategy's own unweighted
    /// estimate of all paths it can generate).
    pub weighted: bool,
}

/// Bidirectional path tracing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bdpt {
    /// Maximum depth (Mitsuba's convention); `None` = unlimited.
    pub max_depth: Option<u32>,
    /// Russian roulette starts once this many bounces have been made.
    pub rr_depth: u32,
    /// `None`: the full estimator. `Some`: only one strategy (lesson images).
    pub strategy_images: Option<StrategyFilter>,
}

impl Default for Bdpt {
    fn default() -> Self {
        Bdpt {
            max_depth: None,
            rr_depth: 5,
            strategy_images: None,
        }
    }
}

/// The value of one connection: its unweighted contribution, where it lands
/// (`Some` raster position for `t = 1`, which is splatted) and the resampled
/// vertex that replaces `y_0` (`s = 1`) or `z_0` (`t = 1`) in the MIS weight.
/// An `occluded` connection adds nothing: it is returned only to be recorded
/// (the inspector shows blocked connections as it shows blocked shadow rays).
struct Connection {
    value: Color,
    raster: Option<Vec2>,
    sampled: Option<Vertex>,
    occluded: bool,
}

/// The unweighted contribution of strategy `(s, t)`; `None` if it is zero
/// without a shadow ray, `occluded` if the shadow ray is blocked.
fn connect(
    scene: &Scene,
    light: &[Vertex],
    camera: &[Vertex],
    s: usize,
    t: usize,
    sampler: &mut Sampler,
) -> Option<Connection> {
    let pt = &camera[t - 1];
    if s == 0 {
        // The camera path hit an emitter.
        let value = pt.beta * pt.le_towards(scene, &camera[t - 2]);
        return (value != Color::ZERO).then_some(Connection {
            value,
            raster: None,
            sampled: None,
            occluded: false,
        });
    }
    if t == 1 {
        // Light tracing: y_{s−1} joined to the lens.
        let c = join_lens(scene, &light[s - 1], LENS.draw(sampler))?;
        return Some(Connection {
            value: c.value,
            raster: Some(c.camera.raster),
            sampled: Some(Vertex::camera(c.camera.p_lens, Color::ZERO)),
            occluded: !sees_lens(scene, &light[s - 1], &c),
        });
    }
    if !pt.is_connectible(scene) {
        return None;
    }
    if s == 1 {
        // Next event estimation: a fresh light point seen from z_{t−1}.
        let LightPoint { choice, sample: ls } = nee::sample_light_point(scene, pt.p(), sampler)?;
        if choice.light.is_environment() {
            // Not a strategy here (see `subpath`): environment light comes
            // only through escaping camera paths.
            return None;
        }
        let pdf_light_w = choice.pmf * ls.pdf_w;
        let value = pt.beta * pt.f(scene, ls.wi) * (pt.abs_cos(ls.wi) / pdf_light_w) * ls.li;
        if value == Color::ZERO {
            return None;
        }
        // The resampled point carries the density of a light path's origin,
        // P(light) p_A, like y_0 of every other strategy; `mis_weight`
        // scales this strategy by the density next event estimation really
        // had (a sphere's cone), so its weight is right by construction.
        let mut y = Vertex::light(choice.index, ls.p, ls.n, Color::ZERO, 0.0);
        y.pdf_fwd_a = y.pdf_light_origin_a(scene);
        return Some(Connection {
            value,
            raster: None,
            sampled: Some(y),
            occluded: !visible(scene, pt, &y),
        });
    }
    // General connection: both ends' scattering and the edge's geometry term.
    let qs = &light[s - 1];
    if !qs.is_connectible(scene) {
        return None;
    }
    let d = pt.p() - qs.p();
    let d2 = d.length_squared();
    if d2 == 0.0 {
        return None;
    }
    let w = d / d2.sqrt(); // from y_{s−1} towards z_{t−1}
    let g = qs.abs_cos(w) * pt.abs_cos(w) / d2;
    // The light side scatters with the adjoint BRDF (shading normals).
    let value = qs.beta * qs.f_importance(scene, w) * pt.f(scene, -w) * pt.beta * g;
    if value == Color::ZERO {
        return None;
    }
    Some(Connection {
        value,
        raster: None,
        sampled: None,
        occluded: !visible(scene, qs, pt),
    })
}

impl Bdpt {
    /// One pixel sample: builds both subpaths and sums every strategy (or the
    /// one selected by `strategy_images`).
    fn estimate<R: Recorder>(
        &self,
        scene: &Scene,
        pixel: UVec2,
        sampler: &mut Sampler,
        splats: &mut Vec<Splat>,
        rec: &mut R,
    ) -> Color {
        let max_vertices = path_vertices(self.max_depth); // D + 1
        with_subpaths(|camera, light| {
            // Each part from a stream of its own: in Metropolis light
            // transport a small step then moves the light subpath's numbers
            // a little even when it makes the camera subpath longer or
            // shorter (a hashed sampler reads them in this order all the same).
            sampler.start_stream(Stream::Camera);
            let escaped =
                camera_subpath(scene, pixel, sampler, camera, max_vertices, self.rr_depth);
            sampler.start_stream(Stream::Light);
            light_subpath(scene, sampler, light, max_vertices - 1, self.rr_depth);
            sampler.start_stream(Stream::Connection);
            self.strategies(scene, light, camera, escaped, sampler, splats, rec)
        })
    }

    /// Sums the strategies of one pixel sample's two subpaths (or the one
    /// selected by `strategy_images`), handing the subpaths and every
    /// contribution to `rec`.
    #[allow(clippy::too_many_arguments)]
    fn strategies<R: Recorder>(
        &self,
        scene: &Scene,
        light: &mut [Vertex],
        camera: &mut [Vertex],
        escaped: Option<EscapedRay>,
        sampler: &mut Sampler,
        splats: &mut Vec<Splat>,
        rec: &mut R,
    ) -> Color {
        // The recorded camera and light subpaths (`None` when not recording).
        let (z, y) = match rec.record() {
            Some(r) => (
                r.push_subpath(scene, PathRole::Camera, camera),
                r.push_subpath(scene, PathRole::Light, light),
            ),
            None => (None, None),
        };
        let max_vertices = path_vertices(self.max_depth);
        let (n_camera, n_light) = (camera.len(), light.len());
        let keep = |s: usize, t: usize| {
            self.strategy_images
                .is_none_or(|f| f.s as usize == s && f.t as usize == t)
        };
        let weighted = self.strategy_images.is_none_or(|f| f.weighted);
        let mut l = Color::ZERO;
        // The environment seen by an escaping camera path: strategy
        // (0, n_C + 1), the only one that generates such paths (weight 1).
        if let Some(EscapedRay { beta, d }) = escaped
            && n_camera < max_vertices
            && keep(0, n_camera + 1)
        {
            l += beta * scene.escaped_radiance(d);
            if let Some(r) = rec.record() {
                let last = z.map(|path| VertexRef {
                    path,
                    vertex: n_camera - 1,
                });
                let ray = Ray::new(camera[n_camera - 1].p(), d);
                let at = r.push_vertex(last, PathVertex::escaped(scene, &ray, None, beta));
                r.contribute(at, beta * scene.escaped_radiance(d), Some(1.0));
                // The only strategy that makes the path: (0, n_C + 1).
                let mut only = vec![0.0; n_camera + 1];
                only[0] = 1.0;
                r.strategy_weights(at, only);
            }
        }
        for t in 1..=n_camera {
            // s = 1 with t ≥ 2 resamples its light point (next event
            // estimation): it needs no light subpath, and is tried also when
            // none could start (the environment was chosen for it). Once it
            // was skipped then, and the sun of `stereo` under its sky lost
            // most of its direct light.
            for s in 0..=n_light.max(1) {
                if s + t < 2 || s + t > max_vertices || !keep(s, t) || (s > n_light && t == 1) {
                    continue;
                }
                let Some(c) = connect(scene, light, camera, s, t, sampler) else {
                    continue;
                };
                if c.occluded {
                    if let Some(r) = rec.record() {
                        record_connection(r, (z, y), &c, [s, t], None, Color::ZERO, None);
                    }
                    continue;
                }
                // The resampled point of s = 1 is the light subpath's only vertex.
                let mut resampled;
                let (ys, sampled): (&mut [Vertex], _) = if s == 1 && t >= 2 {
                    resampled = [c.sampled.expect("s = 1 resamples the light point")];
                    (&mut resampled, None)
                } else {
                    (&mut *light, c.sampled)
                };
                let w = if weighted {
                    mis_weight(scene, ys, camera, s, t, sampled)
                } else {
                    1.0
                };
                let value = c.value * w;
                match c.raster {
                    Some(raster) => splats.push(Splat { raster, value }),
                    None => l += value,
                }
                if let Some(r) = rec.record() {
                    // Every strategy's weight for this path, from the same MIS code.
                    let all = weighted.then(|| mis_weights(scene, ys, camera, s, t, sampled));
                    record_connection(r, (z, y), &c, [s, t], Some(w), value, all);
                }
            }
        }
        l
    }
}

/// Records strategy `(s, t)`'s weighted contribution `value` (weight `w`,
/// `None` for a blocked connection, which adds nothing; `weights`: every
/// strategy's weight for the same path) between the recorded subpaths
/// `(z, y)`: at the camera vertex that hit a light (`s = 0`), or as a
/// connection from `z_{t−1}` (from `y_{s−1}` to the lens for `t = 1`).
fn record_connection(
    r: &mut PathRecord,
    (z, y): (Option<usize>, Option<usize>),
    c: &Connection,
    [s, t]: [usize; 2],
    w: Option<f32>,
    value: Color,
    weights: Option<Vec<f32>>,
) {
    let z_at = z.map(|path| VertexRef {
        path,
        vertex: t - 1,
    });
    let y_at = y.map(|path| VertexRef {
        path,
        vertex: s.max(1) - 1,
    });
    let sampled = c.sampled.map(|v| SegmentEnd::point(v.p()));
    let segment = |from, to, splat| Segment {
        occluded: c.occluded,
        strategy_weights: weights.clone(),
        ..Segment::connection(from, to, [s, t], w, value, splat)
    };
    match (s, t) {
        (0, _) => {
            r.contribute(z_at, value, w);
            if let Some(weights) = weights.clone() {
                r.strategy_weights(z_at, weights);
            }
        }
        // A blocked connection to the lens was splatted nowhere.
        (_, 1) => r.push_segment(y_at, |from| {
            let lens = sampled.expect("t = 1 samples a lens point");
            segment(from, lens, c.raster.filter(|_| !c.occluded))
        }),
        (1, _) => r.push_segment(z_at, |from| {
            let light = sampled.expect("s = 1 resamples the light point");
            segment(from, light, None)
        }),
        _ => {
            if let Some(to) = y_at {
                r.push_segment(z_at, |from| segment(from, SegmentEnd::Vertex(to), None));
            }
        }
    }
}

impl Integrator for Bdpt {
    fn name(&self) -> &'static str {
        "bdpt"
    }

    fn sample(
        &self,
        scene: &Scene,
        pixel: UVec2,
        sampler: &mut Sampler,
        splats: &mut Vec<Splat>,
    ) -> Color {
        self.estimate(scene, pixel, sampler, splats, &mut NoRecorder)
    }

    fn sample_recorded(
        &self,
        scene: &Scene,
        pixel: UVec2,
        sampler: &mut Sampler,
        splats: &mut Vec<Splat>,
        record: &mut PathRecord,
    ) -> Color {
        self.estimate(scene, pixel, sampler, splats, record)
    }
}
