//! The connection to the camera: a light-subpath vertex joined to the lens.
//!
//! Lecture topic: "The connection to the camera" (light tracing) — the
//! strategy `t = 1` of bidirectional tracing. The camera's importance `W_e`
//! plays the role that `L_e` plays for lights; the contribution lands on the
//! pixel where the vertex is seen, so it is splatted there.

use super::vertex::{Vertex, visible};
use crate::camera::CameraSample;
use crate::math::{Color, Vec2};
use crate::scene::Scene;

/// A light-subpath vertex joined to the lens.
#[derive(Clone, Copy, Debug)]
pub struct CameraConnection {
    /// The lens point, the raster position where the vertex is seen, the
    /// importance and density of the connection.
    pub camera: CameraSample,
    /// The contribution to splat at `camera.raster`.
    pub value: Color,
}

/// The `t = 1` connection: light-subpath vertex `q` joined to a lens point
/// chosen by `u_lens`. Its contribution to the pixel at `CameraSample::raster`
/// is Veach's light tracing estimate (slide "The connection to the camera";
/// exercise 14 derives it), written with the lens density per unit solid
/// angle at `q` that `camera.sample_wi` returns, in which the lens's cosine
/// and distance cancel against the geometry term's. At a surface the BRDF is
/// the adjoint one of importance transport ([`Vertex::f_importance`]).
/// Visibility-tested.
/// `None` if the point is off the film, behind the camera or in shadow.
pub fn connect_to_camera(scene: &Scene, q: &Vertex, u_lens: Vec2) -> Option<CameraConnection> {
    join_lens(scene, q, u_lens).filter(|c| sees_lens(scene, q, c))
}

/// [`connect_to_camera`] before its visibility test: what the connection
/// would bring if nothing stood between `q` and the lens point (`None` if it
/// would bring nothing: off the film, behind the camera, a zero BRDF or
/// importance). The path recorder shows a blocked one as it shows a blocked
/// shadow ray.
pub fn join_lens(scene: &Scene, q: &Vertex, u_lens: Vec2) -> Option<CameraConnection> {
    if !q.is_connectible(scene) {
        return None;
    }
    let cs = scene.camera.sample_wi(q.p(), u_lens)?;
    let l = q.beta * q.f_importance(scene, cs.wi) * (q.abs_cos(cs.wi) * cs.we / cs.pdf_w);
    (l != Color::ZERO).then_some(CameraConnection {
        camera: cs,
        value: l,
    })
}

/// Whether nothing stands between `q` and the lens point of `c`.
pub fn sees_lens(scene: &Scene, q: &Vertex, c: &CameraConnection) -> bool {
    visible(scene, q, &Vertex::camera(c.camera.p_lens, Color::ZERO))
}
