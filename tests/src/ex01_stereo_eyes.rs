//! Grader of exercise 1 (stereo eye positions): exact answers.

use raytracer::camera::{Camera, CameraParams};
use raytracer::math::{Vec2, Vec3A};

use crate::stats::{close3, fmt3};

/// The signature of exercise 1.
pub type EyesFn = fn(&Camera, f32) -> (Vec3A, Vec3A);

/// The grader's own answer.
pub fn expected(camera: &Camera, s: f32) -> (Vec3A, Vec3A) {
    let half = 0.5 * s * camera.right_dir();
    (camera.position() - half, camera.position() + half)
}

/// The cameras of the test: a Cornell-like one, a tilted one, one far away.
pub fn cameras() -> Vec<(Camera, f32)> {
    let cam = |p: [f32; 3], at: [f32; 3], up: [f32; 3]| {
        Camera::new(
            CameraParams {
                position: Vec3A::from(p),
                look_at: Vec3A::from(at),
                up: Vec3A::from(up),
                vfov_deg: 40.0,
                aperture_radius: 0.0,
                focus_distance: 1.0,
                shift: Vec2::ZERO,
            },
            64,
            48,
        )
    };
    vec![
        (
            cam([0.0, 0.0, 3.9], [0.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
            0.065,
        ),
        (
            cam([1.0, 2.0, 3.0], [-2.0, 0.5, -1.0], [0.0, 1.0, 0.0]),
            0.3,
        ),
        (
            cam([10.0, -4.0, 7.0], [10.0, -4.0, 0.0], [1.0, 1.0, 0.0]),
            2.0,
        ),
    ]
}

/// Exact comparison with diagnostics.
pub fn check(f: EyesFn) -> Result<(), String> {
    for (camera, s) in cameras() {
        let (l, r) = f(&camera, s);
        let (el, er) = expected(&camera, s);
        let tol = 1e-5 * (1.0 + camera.position().abs().max_element());
        if close3(l, el, tol) && close3(r, er, tol) {
            continue;
        }
        let p = camera.position();
        let what = crate::tr!("ex01.what", position = fmt3(p), s);
        if close3(l, er, tol) && close3(r, el, tol) {
            return Err(crate::tr!("ex01.swapped", what));
        }
        let dist = (r - l).length();
        if (dist - s).abs() > 1e-4 * s {
            let why = if (dist - 2.0 * s).abs() <= 1e-4 * s {
                crate::tr!("ex01.twice")
            } else if (dist - 0.5 * s).abs() <= 1e-4 * s {
                crate::tr!("ex01.half")
            } else {
                String::new()
            };
            return Err(crate::tr!("ex01.distance", what, dist, s, why));
        }
        let mid = 0.5 * (l + r);
        if !close3(mid, p, tol) {
            return Err(crate::tr!("ex01.shifted", what, mid = fmt3(mid)));
        }
        return Err(crate::tr!(
            "ex01.direction",
            what,
            offset = fmt3((r - l) / dist),
            right = fmt3(camera.right_dir())
        ));
    }
    Ok(())
}
