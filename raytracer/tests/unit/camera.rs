//! Unit tests of `camera.rs`.

use raytracer::camera::*;
use raytracer::math::{RayPdf, Vec2, Vec3A};

fn cornell_camera(aperture: f32) -> Camera {
    Camera::new(
        CameraParams {
            position: Vec3A::new(0.0, 0.0, 3.9),
            look_at: Vec3A::ZERO,
            up: Vec3A::Y,
            vfov_deg: 39.3077,
            aperture_radius: aperture,
            focus_distance: 3.9,
            shift: Vec2::ZERO,
        },
        256,
        256,
    )
}

#[test]
fn image_right_is_world_plus_x_in_the_cornell_box() {
    let c = cornell_camera(0.0);
    assert!((c.right_dir() - Vec3A::X).length() < 1e-6);
    // Mitsuba's reference: direction normalize((2u−1)·t, (1−2v)·t, −1), t = tan(fov/2).
    let t = 0.357_143_37f32;
    let r = c.generate_ray(Vec2::new(0.25 * 256.0, 0.1 * 256.0), Vec2::ZERO);
    let expected = Vec3A::new(-0.5 * t, 0.8 * t, -1.0).normalize();
    assert!((r.d - expected).length() < 1e-5, "{} vs {}", r.d, expected);
}

#[test]
fn raster_of_inverts_generate_ray() {
    for aperture in [0.0, 0.05] {
        let c = cornell_camera(aperture);
        for (x, y, lx, ly) in [
            (10.5, 20.25, 0.3, 0.9),
            (200.0, 128.0, 0.5, 0.5),
            (255.9, 0.1, 0.1, 0.2),
        ] {
            let ray = c.generate_ray(Vec2::new(x, y), Vec2::new(lx, ly));
            for depth in [1.0, 3.9, 7.0] {
                let p = ray.at(depth);
                let r = c.raster_of(p, ray.o).expect("on film");
                assert!((r - Vec2::new(x, y)).length() < 2e-3, "{r} vs ({x},{y})");
            }
        }
    }
    let c = cornell_camera(0.0);
    assert!(
        c.raster_of(Vec3A::new(0.0, 0.0, 5.0), c.position())
            .is_none(),
        "behind the camera"
    );
    assert!(
        c.raster_of(Vec3A::new(10.0, 0.0, 0.0), c.position())
            .is_none(),
        "off the film"
    );
}

/// `W_e` is normalized: ∫_film W_e cos θ dω = 1 for a pinhole. Estimated
/// on a 200×200 grid of directions through the image window, where
/// `dω = cos³θ dA` (exact up to the grid's quadrature error, < 1e-3).
#[test]
fn importance_integrates_to_one() {
    let c = cornell_camera(0.0);
    let n = 200;
    let mut sum = 0.0f64;
    for j in 0..n {
        for i in 0..n {
            let raster = Vec2::new(
                (i as f32 + 0.5) / n as f32 * 256.0,
                (j as f32 + 0.5) / n as f32 * 256.0,
            );
            let ray = c.generate_ray(raster, Vec2::ZERO);
            let cos = ray.d.dot(c.forward());
            let d_area = c.image_area / (n * n) as f32;
            let d_omega = d_area * cos * cos * cos;
            sum += (c.we(&ray) * cos * d_omega) as f64;
            let RayPdf { pdf_a, pdf_w } = c.pdf_we(&ray);
            assert_eq!(pdf_a, 1.0);
            assert!((pdf_w * d_omega * (n * n) as f32 - 1.0).abs() < 1e-3);
        }
    }
    assert!((sum - 1.0).abs() < 1e-3, "∫ W_e cos dω = {sum}");
}

#[test]
fn sample_wi_finds_the_pixel_of_a_point() {
    let c = cornell_camera(0.0);
    let p = Vec3A::new(0.2, -0.3, -1.0);
    let s = c.sample_wi(p, Vec2::ZERO).expect("visible");
    let ray = c.generate_ray(s.raster, Vec2::ZERO);
    assert!((ray.d + s.wi).length() < 1e-5);
    assert!((s.dist - (c.position() - p).length()).abs() < 1e-5);
}
