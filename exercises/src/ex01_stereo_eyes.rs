//! Exercise 1 — the two eyes of a stereo camera, converged on the screen.
//!
//! Slides: "Stereoscopic rendering" ("Стереоскопично рендериране"),
//! "Result" ("Резултат"), "stereoSeparation" ("stereoSeparation").
//!
//! The lecture renders two frames from two viewpoints moved apart along the
//! camera's `rightDir`; the distance between the two virtual cameras is
//! `stereoSeparation`. Here both eyes keep the middle camera's view
//! direction (a parallel rig: no eye is turned towards anything), so their
//! image planes stay parallel and a point lands at the same height in both
//! frames. Left alone, two parallel eyes see a point at the same place in
//! both frames only if it is infinitely far away: everything in the scene
//! would float in front of the screen. The screen should lie at the
//! convergence distance `C` (measured along the view direction) instead.
//!
//! Each eye therefore slides its image window sideways, within its own
//! image plane, by `CameraParams::shift` (an off-axis, asymmetric frustum).
//! The shift is measured on the image plane at distance 1 in front of the
//! eye, in the units of that plane (as `raytracer::camera` documents its
//! image window), `x` along `rightDir`. Derive how far, and which way, each
//! window must slide so that every point on the plane at depth `C` lands on
//! the same pixel in both eyes' frames, and on the pixel where the middle
//! camera sees it.
//!
//! Task: from the (middle) camera, `stereo_separation` `s` and the
//! convergence distance `C > 0`, return the parameters of the left and the
//! right eye's cameras:
//! - the middle camera sits halfway between the eyes, the left eye on the
//!   side of −rightDir;
//! - both eyes look in the middle camera's direction, with its `up`;
//! - each eye's window shift is the middle camera's own `shift` (its window
//!   may already be off-centre) plus the eye's sideways slide; nothing
//!   moves up or down;
//! - the lens and the field of view stay as they are.
//!
//! Receives: the camera (`Camera::params`, `Camera::position`,
//! `Camera::right_dir`, `Camera::forward`), `s` in metres, `C` in metres.
//! Returns: `(left, right)` camera parameters.
//!
//! The renderer builds a stereo pair with it
//! (`exercises::plug::stereo_cameras`).

use raytracer::camera::{Camera, CameraParams};

/// The camera parameters `(left, right)` of the two eyes.
pub fn stereo_eyes(
    camera: &Camera,
    stereo_separation: f32,
    convergence: f32,
) -> (CameraParams, CameraParams) {
    // TODO: move each eye along rightDir, keep the view direction, and slide
    // each window so that depth `convergence` has zero parallax.
    todo!()
}
