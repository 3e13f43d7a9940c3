//! Reference solution of exercise 14 (see `src/ex14_light_tracing.rs` for the task).

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
    let s = camera.sample_wi(p, u_lens)?;
    let value = beta * f_r(s.wi) * (n.dot(s.wi).abs() * s.we / s.pdf_w);
    Some(Splat {
        raster: s.raster,
        value,
    })
}
