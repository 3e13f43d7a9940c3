//! Grader of exercise 1 (stereo eyes with off-axis windows): exact answers.
//!
//! The eyes' positions are compared with the closed form; the windows by
//! what they do: the depth at which the two frames agree (zero parallax)
//! and whether the pair stays centred on the middle camera's picture.

use raytracer::camera::{Camera, CameraParams};
use raytracer::math::{Vec2, Vec3A};

use crate::stats::{close3, fmt3};

/// The signature of exercise 1.
pub type EyesFn = fn(&Camera, f32, f32) -> (CameraParams, CameraParams);

/// The grader's own answer: eyes at `∓s/2` along rightDir, looking the
/// same way, each window slid by `±s/(2C)` (left `+`).
pub fn expected(camera: &Camera, s: f32, c: f32) -> (CameraParams, CameraParams) {
    let p = camera.params;
    let eye = |sign: f32| {
        let offset = 0.5 * sign * s * camera.right_dir();
        CameraParams {
            position: p.position + offset,
            look_at: p.look_at + offset,
            shift: p.shift - Vec2::new(0.5 * sign * s / c, 0.0),
            ..p
        }
    };
    (eye(-1.0), eye(1.0))
}

/// The cameras of the test `(camera, s, C)`: a Cornell-like one, a tilted
/// one, one far away and rolled, one whose own window is off-centre. No
/// convergence distance is 1 (a shift not divided by C would pass there).
pub fn cameras() -> Vec<(Camera, f32, f32)> {
    let cam = |p: [f32; 3], at: [f32; 3], up: [f32; 3], shift: Vec2| {
        Camera::new(
            CameraParams {
                position: Vec3A::from(p),
                look_at: Vec3A::from(at),
                up: Vec3A::from(up),
                vfov_deg: 40.0,
                aperture_radius: 0.0,
                focus_distance: 1.0,
                shift,
            },
            64,
            48,
        )
    };
    vec![
        (
            cam(
                [0.0, 0.0, 3.9],
                [0.0, 0.0, 0.0],
                [0.0, 1.0, 0.0],
                Vec2::ZERO,
            ),
            0.065,
            3.9,
        ),
        (
            cam(
                [1.0, 2.0, 3.0],
                [-2.0, 0.5, -1.0],
                [0.0, 1.0, 0.0],
                Vec2::ZERO,
            ),
            0.3,
            2.5,
        ),
        (
            cam(
                [10.0, -4.0, 7.0],
                [10.0, -4.0, 0.0],
                [1.0, 1.0, 0.0],
                Vec2::ZERO,
            ),
            2.0,
            7.0,
        ),
        (
            cam(
                [0.5, 1.0, 4.0],
                [0.5, 1.0, 0.0],
                [0.0, 1.0, 0.0],
                Vec2::new(0.05, -0.02),
            ),
            0.1,
            1.6,
        ),
    ]
}

/// Both eyes' parameters are usable: finite, a view direction that is
/// neither zero nor along `up` (else the camera has no frame).
fn usable(p: &CameraParams) -> bool {
    let forward = p.look_at - p.position;
    let finite = p.position.is_finite() && p.look_at.is_finite() && p.shift.is_finite();
    finite && forward.length() > 1e-6 && forward.normalize().cross(p.up).length() > 1e-4
}

/// Exact comparison with diagnostics.
pub fn check(f: EyesFn) -> Result<(), String> {
    for (camera, s, c) in cameras() {
        let (lp, rp) = f(&camera, s, c);
        let (el, er) = expected(&camera, s, c);
        let base = camera.params;
        let p = camera.position();
        let what = crate::tr!("ex01.what", position = fmt3(p), s, c);
        let tol = 1e-5 * (1.0 + p.abs().max_element());
        if !(usable(&lp) && usable(&rp)) {
            return Err(crate::tr!("ex01.degenerate", what));
        }
        // 1. Where the eyes are.
        let (l, r) = (lp.position, rp.position);
        if !(close3(l, el.position, tol) && close3(r, er.position, tol)) {
            if close3(l, er.position, tol) && close3(r, el.position, tol) {
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
        // 2. Which way they look, and through which lens.
        let (lc, rc) = (
            Camera::new(lp, camera.width, camera.height),
            Camera::new(rp, camera.width, camera.height),
        );
        for eye in [&lc, &rc] {
            let same_frame = close3(eye.forward(), camera.forward(), 1e-5)
                && close3(eye.right_dir(), camera.right_dir(), 1e-5);
            if !same_frame {
                return Err(crate::tr!("ex01.turned", what));
            }
            let q = eye.params;
            if q.vfov_deg != base.vfov_deg
                || q.aperture_radius != base.aperture_radius
                || q.focus_distance != base.focus_distance
            {
                return Err(crate::tr!("ex01.lens", what));
            }
        }
        // 3. The windows: nothing vertical, zero parallax at depth C, and the
        // pair centred on the middle camera's picture.
        let (sl, sr) = (lp.shift - base.shift, rp.shift - base.shift);
        let stol = 1e-6 + 1e-4 * (0.5 * s / c);
        if sl.y.abs() > stol || sr.y.abs() > stol {
            return Err(crate::tr!("ex01.vertical", what));
        }
        if (sl.x - el.shift.x + base.shift.x).abs() <= stol
            && (sr.x - er.shift.x + base.shift.x).abs() <= stol
        {
            continue;
        }
        // A point X to the side at depth z: the left eye sees it at
        // (X + s/2)/z − sl.x, the right one at (X − s/2)/z − sr.x; they
        // agree where s/z = sl.x − sr.x.
        let spread = sl.x - sr.x;
        if spread.abs() <= stol {
            return Err(crate::tr!("ex01.no_slide", what));
        }
        if spread < 0.0 {
            return Err(crate::tr!("ex01.wrong_way", what));
        }
        let z0 = s / spread;
        if (z0 - c).abs() > 1e-3 * c {
            let why = if (z0 - 1.0).abs() < 1e-3 {
                crate::tr!("ex01.at_one")
            } else {
                String::new()
            };
            return Err(crate::tr!("ex01.screen_at", what, z0, c, why));
        }
        return Err(crate::tr!(
            "ex01.off_centre",
            what,
            side = if sl.x + sr.x > 0.0 {
                "+rightDir"
            } else {
                "−rightDir"
            }
        ));
    }
    Ok(())
}
