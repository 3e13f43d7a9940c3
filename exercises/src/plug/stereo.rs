//! Exercises 1 and 2: the stereo pair's cameras and the anaglyph, from the
//! student's eye cameras and colour mixing.

use raytracer::camera::Camera;
use raytracer::film::Image;

use crate::{ex01_stereo_eyes, ex02_anaglyph};

/// The two cameras of a stereo pair (parallel eyes, off-axis windows) from
/// exercise 1, converged at `convergence`, at the camera's resolution.
pub fn stereo_cameras(
    camera: &Camera,
    stereo_separation: f32,
    convergence: f32,
) -> (Camera, Camera) {
    let (left, right) = ex01_stereo_eyes::stereo_eyes(camera, stereo_separation, convergence);
    let eye = |params| Camera::new(params, camera.width, camera.height);
    (eye(left), eye(right))
}

/// The anaglyph of two images of the same size, pixel by pixel with exercise 2.
///
/// # Panics
/// If the images differ in size.
pub fn anaglyph_image(left: &Image, right: &Image, desaturation: f32) -> Image {
    assert!(
        left.width == right.width && left.height == right.height,
        "the two eyes' images differ in size"
    );
    Image::from_fn(left.width, left.height, |x, y| {
        ex02_anaglyph::anaglyph(left.get(x, y), right.get(x, y), desaturation)
    })
}
