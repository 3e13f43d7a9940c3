//! Reference solution of exercise 1 (see `src/ex01_stereo_eyes.rs` for the task).

use raytracer::camera::{Camera, CameraParams};
use raytracer::math::Vec2;

/// The camera parameters `(left, right)` of the two eyes.
pub fn stereo_eyes(
    camera: &Camera,
    stereo_separation: f32,
    convergence: f32,
) -> (CameraParams, CameraParams) {
    let p = camera.params;
    let eye = |sign: f32| {
        // The eye sits at e = sign·s/2 along rightDir. A point X to the side
        // at depth C is seen by it at (X − e)/C on its image plane at
        // distance 1, by the middle camera at X/C: sliding the window by
        // −e/C puts it on the same pixel, for every X.
        let e = 0.5 * sign * stereo_separation;
        let offset = e * camera.right_dir();
        CameraParams {
            position: p.position + offset,
            look_at: p.look_at + offset,
            shift: p.shift + Vec2::new(-e / convergence, 0.0),
            ..p
        }
    };
    (eye(-1.0), eye(1.0))
}
