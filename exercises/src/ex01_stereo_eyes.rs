//! Exercise 1 — the two eyes of a stereo camera.
//!
//! Slides: "Stereoscopic rendering" ("Стереоскопично рендериране"),
//! "stereoSeparation" ("stereoSeparation").
//!
//! The lecture renders two frames from two viewpoints moved apart along the
//! camera's `rightDir`; the distance between the two virtual cameras is
//! `stereoSeparation`.
//!
//! Task: given the (middle) camera and `stereo_separation`, return the
//! positions of the left and the right eye. The middle camera sits halfway
//! between the eyes; the left eye is the one on the side of −rightDir.
//!
//! Receives: the camera (`Camera::position`, `Camera::right_dir`) and the
//! separation in metres. Returns: `(left_eye, right_eye)`.
//!
//! The renderer calls it to build the two cameras of a stereo pair
//! (`exercises::plug::stereo_cameras`).

use raytracer::camera::Camera;
use raytracer::math::Vec3A;

/// The positions `(left, right)` of the two eyes.
pub fn stereo_eyes(camera: &Camera, stereo_separation: f32) -> (Vec3A, Vec3A) {
    // TODO: place the two eyes on the line along the camera's rightDir.
    todo!()
}
