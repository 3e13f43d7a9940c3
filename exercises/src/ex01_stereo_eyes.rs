//! Exercise 1 — the two eyes of a stereo camera.
//!
//! Slide: "Stereoscopic rendering" ("Стереоскопично рендериране"): we render
//! two frames from two viewpoints, moved apart along the camera's `rightDir`;
//! the distance between the two virtual cameras is `stereoSeparation`.
//!
//! Task: given the (middle) camera and `stereo_separation`, return the
//! positions of the left and the right eye. The eyes sit symmetrically about
//! the camera's position, on the line through it along `camera.right_dir()`,
//! `stereo_separation` apart: the left eye towards `-rightDir`, the right
//! eye towards `+rightDir`.
//!
//! Receives: the camera (`camera.position()`, `camera.right_dir()`, ...) and
//! the separation in metres. Returns: `(left_eye, right_eye)`.
//!
//! The renderer calls it to build the two cameras of a stereo pair
//! (`exercises::plug::stereo_cameras`).

use raytracer::camera::Camera;
use raytracer::math::Vec3A;

/// The positions `(left, right)` of the two eyes.
pub fn stereo_eyes(camera: &Camera, stereo_separation: f32) -> (Vec3A, Vec3A) {
    // TODO: move half the separation to each side along camera.right_dir().
    todo!()
}
