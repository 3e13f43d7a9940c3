//! Light tracing: paths generated from the lights and joined to the camera.
//!
//! Lecture topic: "Light tracing". The adjoint of path tracing: a path
//! `x_0 … x_k` (lens first, light last) is built backwards. A light subpath
//! `y_0 y_1 …` starts on a light (`y_0` with area density `P(light) p_A`, a
//! direction with `p_ω`) and bounces with BRDF sampling, carrying
//! importance-mode throughput (glass does not scale it by `1/η²`); every
//! vertex `y_i` is joined to a lens point — the strategy `t = 1` of
//! bidirectional tracing — and contributes to the pixel it lands in:
//!
//! ```text
//!   C = β_i · f_r(y_{i−1} → y_i → lens) · |cos θ_{y_i}| · W_e(lens → y_i) / p_ω(lens)
//!   β_i = L_e(y_0 → y_1) |cos θ_{y_0}| / (P(light) p_A(y_0) p_ω(y_0 → y_1))
//!         · Π_{j=1}^{i−1} f_r |cos θ| / p_ω
//! ```
//!
//! (see [`connect_to_camera`](super::camera_connection::connect_to_camera) for the `G / p_A = |cos| / p_ω`
//! conversion). The light point itself (`i = 0`) is joined too, with `f_r`
//! replaced by `L_e(y_0 → lens)`: that is how light tracing sees lights
//! directly — a pinhole cannot be hit by a light path, so nothing else could.
//!
//! Each pixel sample traces one light path and splats every contribution; the
//! film scales splat sums by `W·H / M` (`M` pixel samples in all), which
//! together with the film-wide `W_e` (∫ W_e cos dω = 1 over the whole image)
//! gives each pixel its measurement `I_j = W·H ∫_{pixel j} W_e L cos dω`.
//!
//! Depth: a light vertex after `k` bounces joined to the lens makes a path of
//! `k + 2` vertices with `k` scattering vertices; Mitsuba's `max_depth = D`
//! allows `k ≤ D − 1`, so the light subpath keeps at most `D` vertices.
//!
//! What light tracing cannot do: paths whose camera end is a specular
//! surface (a mirror or glass seen by the camera: the connection at a delta
//! vertex has zero value), and the environment (not emitted on the light side
//! here; see [`super::subpath`]). Those pixels stay dark.

use super::Integrator;
use super::camera_connection::{join_lens, sees_lens};
use super::dimensions::LENS;
use super::record::{NoRecorder, PathRecord, PathRole, Recorder, Segment, VertexRef};
use super::subpath::light_subpath;
use super::vertex::{path_vertices, with_subpaths};
use crate::film::Splat;
use crate::math::{Color, UVec2};
use crate::sampling::Sampler;
use crate::scene::Scene;

/// The light tracer (one light path per pixel sample, all splatted).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightTracer {
    /// Maximum depth (Mitsuba's convention); `None` = unlimited.
    pub max_depth: Option<u32>,
    /// Russian roulette starts once this many bounces have been made.
    pub rr_depth: u32,
}

impl Default for LightTracer {
    fn default() -> Self {
        LightTracer {
            max_depth: None,
            rr_depth: 5,
        }
    }
}

impl Integrator for LightTracer {
    fn name(&self) -> &'static str {
        "light"
    }

    fn sample(
        &self,
        scene: &Scene,
        _pixel: UVec2,
        sampler: &mut Sampler,
        splats: &mut Vec<Splat>,
    ) -> Color {
        self.trace(scene, sampler, splats, &mut NoRecorder)
    }

    fn sample_recorded(
        &self,
        scene: &Scene,
        _pixel: UVec2,
        sampler: &mut Sampler,
        splats: &mut Vec<Splat>,
        record: &mut PathRecord,
    ) -> Color {
        self.trace(scene, sampler, splats, record)
    }
}

impl LightTracer {
    /// One light path and its connections to the lens, handed to `rec`.
    fn trace<R: Recorder>(
        &self,
        scene: &Scene,
        sampler: &mut Sampler,
        splats: &mut Vec<Splat>,
        rec: &mut R,
    ) -> Color {
        // s vertices joined to the lens give s + 1 vertices: s ≤ D.
        let max_vertices = path_vertices(self.max_depth) - 1;
        with_subpaths(|path, _| {
            light_subpath(scene, sampler, path, max_vertices, self.rr_depth);
            let recorded = rec
                .record()
                .and_then(|r| r.push_subpath(scene, PathRole::Light, path));
            for (i, q) in path.iter().enumerate() {
                let u_lens = LENS.draw(sampler);
                // connect_to_camera, its visibility test apart: a blocked
                // connection is recorded too (adding nothing).
                if let Some(c) = join_lens(scene, q, u_lens) {
                    let occluded = !sees_lens(scene, q, &c);
                    if !occluded {
                        splats.push(Splat {
                            raster: c.camera.raster,
                            value: c.value,
                        });
                    }
                    if let Some(r) = rec.record() {
                        let from = recorded.map(|p| VertexRef { path: p, vertex: i });
                        r.push_segment(from, |from| {
                            Segment::lens_connection(from, &c, i + 1, occluded)
                        });
                    }
                }
            }
        });
        // Everything went to the film as splats.
        Color::ZERO
    }
}
