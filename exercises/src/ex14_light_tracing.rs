//! Exercise 14 — light tracing: connecting a light-path vertex to the camera.
//!
//! Slides: "Light tracing" ("Light tracing"), "The connection to the camera"
//! ("Свързването с камерата").
//!
//! Light tracing starts paths at the lights and connects every vertex to
//! the camera's lens, adding its contribution to whatever pixel it lands on
//! (a "splat"). The camera's importance `W_e` plays the role that `L_e`
//! plays for lights; the connection is the slide's `C = β f_r G W_e`.
//!
//! Task: the splat of the light-path vertex `p` (surface normal `n`),
//! reached with throughput `beta`, whose BRDF towards a direction `w`
//! (pointing away from `p`, towards the camera) is `f_r(w)`. The lens point
//! is chosen by `Camera::sample_wi`, which returns `None` if the camera
//! cannot see `p` (behind it, or off the film), or else a `CameraSample`:
//! the raster position `raster`, the unit direction `wi` from `p` towards
//! the lens point, the importance `we` (`W_e`) of that ray, and `pdf_w`, the
//! density per unit solid angle at `p` with which that lens point was drawn.
//! (`wi` is the camera's name for it, as in pbrt: the direction from which
//! importance arrives at `p`. For the BRDF at `p` it is the slide's `ω_o`,
//! the way the light leaves towards the lens.)
//! Return the splat at that raster position whose value is an unbiased
//! estimate of the vertex's contribution to the image: the slide's `C`
//! integrated over the lens, estimated with the one lens point drawn. The
//! vertex's normal may face either way (a light path can reach the back of a
//! surface). Occlusion is the caller's job.
//!
//! Returns `None` exactly when `Camera::sample_wi` does.

use raytracer::camera::Camera;
use raytracer::film::Splat;
use raytracer::math::{Color, Vec2, Vec3A};

/// The contribution of a light-path vertex to the film.
pub fn splat_light_vertex(
    camera: &Camera,
    p: Vec3A,
    n: Vec3A,
    beta: Color,
    f_r: &dyn Fn(Vec3A) -> Color,
    u_lens: Vec2,
) -> Option<Splat> {
    // TODO: camera.sample_wi, then the estimate; what does dividing by pdf_w replace?
    todo!()
}
