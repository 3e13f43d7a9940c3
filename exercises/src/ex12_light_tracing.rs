//! Exercise 12 — light tracing: connecting a light-path vertex to the camera.
//!
//! Slides: "Light tracing" and "Light tracing (II)": paths start at a light;
//! every vertex `p` of a light path is connected to the camera's lens and
//! adds its contribution to whatever pixel it lands on (a "splat").
//!
//! Task: the splat of the vertex `p` (normal `n`), reached with throughput
//! `beta`, whose BRDF sends light towards a direction `w` with `f_r(w)`
//! (`w` points from `p` towards the camera). Use
//! `camera.sample_wi(p, u_lens)`: it returns `None` if `p` is behind the camera
//! or off the film, else a [`raytracer::camera::CameraSample`] with the raster
//! position, the direction `wi` from `p` to the lens, the camera's
//! importance `we` (`W_e`) and `pdf_w`, the density of `wi` per solid angle at
//! `p`. The splat's value is
//! `beta · f_r(wi) · |cos θ_p| · W_e / pdf_w`, θ_p between `n` and `wi`.
//! (Equivalently `beta · f_r · W_e · G(p, lens)` with the geometry term of
//! exercise 13.) Occlusion is the caller's job.
//!
//! Receives: the camera, the vertex, its throughput, its BRDF as a function
//! of the direction to the camera, the lens sample. Returns: the splat.

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
    // TODO: camera.sample_wi, then the value; do not forget the importance.
    todo!()
}
