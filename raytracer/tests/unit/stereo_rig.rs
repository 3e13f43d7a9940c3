//! Unit tests of `stereo/rig.rs`.

use raytracer::camera::{Camera, CameraParams};
use raytracer::integrator::Direct;
use raytracer::math::{Vec2, Vec3A};
use raytracer::render::RenderOptions;
use raytracer::scene::Scene;
use raytracer::stereo::rig::*;

fn base(aperture: f32) -> Camera {
    Camera::new(
        CameraParams {
            position: Vec3A::new(0.0, 1.2, 5.0),
            look_at: Vec3A::new(0.0, 0.7, 0.0),
            up: Vec3A::Y,
            vfov_deg: 45.0,
            aperture_radius: aperture,
            focus_distance: 4.0,
            shift: Vec2::ZERO,
        },
        400,
        300,
    )
}

#[test]
fn eyes_sit_half_the_separation_either_side_along_right_dir() {
    let c = base(0.0);
    let rig = StereoRig {
        separation: 0.3,
        ..StereoRig::default()
    };
    for toe_in in [false, true] {
        let rig = StereoRig { toe_in, ..rig };
        let [l, r] = rig.eyes(&c);
        let right = c.right_dir();
        assert!((l.position() - (c.position() - 0.15 * right)).length() < 1e-6);
        assert!((r.position() - (c.position() + 0.15 * right)).length() < 1e-6);
        assert!(((r.position() - l.position()).length() - 0.3).abs() < 1e-6);
        if !toe_in {
            // Parallel eyes keep the view direction and the frame.
            for e in [l, r] {
                assert!((e.forward() - c.forward()).length() < 1e-6);
                assert!((e.right_dir() - c.right_dir()).length() < 1e-6);
            }
        }
    }
}

#[test]
fn bad_numbers_are_reported() {
    let bad = StereoRig {
        separation: -1.0,
        ..StereoRig::default()
    };
    assert!(bad.validate().unwrap_err().0.contains("separation"));
    let bad = StereoRig {
        convergence: Some(0.0),
        ..StereoRig::default()
    };
    assert!(bad.validate().unwrap_err().0.contains("convergence"));
    assert!(StereoRig::default().validate().is_ok());
}

/// Points on the plane at the convergence distance land on the same pixel
/// in both eyes; nearer points have crossed (negative) parallax, farther
/// ones uncrossed (positive): x_right − x_left changes sign at C.
#[test]
fn zero_parallax_at_the_convergence_distance() {
    let c = base(0.0);
    for convergence in [None, Some(2.5), Some(9.0)] {
        let rig = StereoRig {
            separation: 0.2,
            convergence,
            toe_in: false,
        };
        let eyes = rig.eyes(&c);
        let d = rig.convergence_distance(&c.params);
        let on_plane = |x: f32, y: f32, depth: f32| {
            c.position() + depth * c.forward() + x * c.right_dir() + y * c.up_dir()
        };
        for (x, y) in [(0.0, 0.0), (0.5, 0.3), (-0.7, -0.2)] {
            let x = x * d / 4.0;
            let y = y * d / 4.0;
            let [a, b] = project_pair(&eyes, on_plane(x, y, d)).expect("visible");
            assert!((a - b).length() < 1e-3, "{a} vs {b} at depth {d}");
            let [a, b] = project_pair(&eyes, on_plane(x, y, 0.7 * d)).unwrap();
            assert!(b.x - a.x < -0.5, "near point: crossed parallax");
            let [a, b] = project_pair(&eyes, on_plane(x, y, 1.5 * d)).unwrap();
            assert!(b.x - a.x > 0.5, "far point: uncrossed parallax");
        }
    }
}

/// Off-axis eyes never have vertical parallax; toe-in eyes have it for
/// points off the centre (here more than a tenth of a pixel, while the
/// off-axis rig stays below float round-off).
#[test]
fn toe_in_causes_vertical_parallax_and_off_axis_does_not() {
    let c = base(0.0);
    let points = [
        Vec3A::new(1.3, 1.6, 1.0),
        Vec3A::new(-1.5, 0.1, 0.0),
        Vec3A::new(2.0, -0.2, -3.0),
    ];
    for toe_in in [false, true] {
        let rig = StereoRig {
            separation: 0.3,
            convergence: Some(4.0),
            toe_in,
        };
        let eyes = rig.eyes(&c);
        let worst = points
            .iter()
            .map(|&p| {
                let [a, b] = project_pair(&eyes, p).expect("visible");
                (a.y - b.y).abs()
            })
            .fold(0.0f32, f32::max);
        if toe_in {
            assert!(worst > 0.1, "toe-in: vertical parallax {worst} px");
        } else {
            assert!(worst < 1e-3, "off-axis: vertical parallax {worst} px");
        }
    }
    // Toe-in still converges exactly at the point on the axis.
    let rig = StereoRig {
        separation: 0.3,
        convergence: Some(4.0),
        toe_in: true,
    };
    let eyes = rig.eyes(&c);
    let [a, b] = project_pair(&eyes, c.position() + 4.0 * c.forward()).unwrap();
    assert!((a - b).length() < 1e-3);
}

/// With the thin lens, a point at the focus (= convergence) distance is
/// sharp and on the same pixel in both eyes, whatever the lens point.
#[test]
fn thin_lens_eyes_focus_on_the_zero_parallax_plane() {
    let c = base(0.1);
    let rig = StereoRig {
        separation: 0.2,
        ..StereoRig::default()
    };
    let eyes = rig.eyes(&c);
    let p = c.position() + 4.0 * c.forward() + 0.4 * c.right_dir() - 0.3 * c.up_dir();
    let centre = eyes[0].raster_of(p, eyes[0].position()).unwrap();
    for e in &eyes {
        for u in [Vec2::new(0.1, 0.9), Vec2::new(0.8, 0.3)] {
            let lens = e.generate_ray(Vec2::new(200.0, 150.0), u).o;
            let r = e.raster_of(p, lens).expect("visible");
            assert!((r - centre).length() < 2e-3, "{r} vs {centre}");
        }
    }
}

/// The same seed gives both eyes the same random sequences: with zero
/// separation the two renders are bit-identical (different seeds are not,
/// so the test can fail).
#[test]
fn both_eyes_share_their_random_numbers() {
    let mut scene = Scene::builtin("stereo").unwrap();
    scene.set_resolution(32, 24);
    let rig = StereoRig {
        separation: 0.0,
        ..StereoRig::default()
    };
    let options = RenderOptions {
        spp: 2,
        seed: 7,
        progress: false,
        ..RenderOptions::default()
    };
    let [l, r] = pair_images(&rig.render_pair(&scene, &Direct, &options));
    assert_eq!(l, r);
    let other = RenderOptions {
        seed: 8,
        ..options.clone()
    };
    let [l2, _] = pair_images(&rig.render_pair(&scene, &Direct, &other));
    assert_ne!(l, l2);
}
