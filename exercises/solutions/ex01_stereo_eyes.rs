//! Reference solution of exercise 1 (see `src/ex01_stereo_eyes.rs` for the task).

use raytracer::camera::Camera;
use raytracer::math::Vec3A;

/// The positions `(left, right)` of the two eyes.
pub fn stereo_eyes(camera: &Camera, stereo_separation: f32) -> (Vec3A, Vec3A) {
    let half = 0.5 * stereo_separation * camera.right_dir();
    (camera.position() - half, camera.position() + half)
}
