//! Grader of exercise 14 (light tracing's connection to the camera): exact
//! values against the grader's formula (pinhole and thin lens), with vertices
//! facing the camera and facing away, a BRDF that is not symmetric under
//! `w → −w`, and points the camera cannot see (`None`); then a furnace: a
//! camera inside a sphere that emits L_e = 0.5 inwards, seen only through the
//! student's splats, must show 0.5 in every tile.

use raytracer::camera::{Camera, CameraParams};
use raytracer::film::Splat;
use raytracer::math::{Color, PI, Vec2, Vec3A};
use raytracer::sampling::Sampler;
use raytracer::sampling::warp::uniform_sphere;

use crate::stats::{Z_MAX, close3, fmt3};

/// The signature of exercise 14.
pub type SplatFn = fn(&Camera, Vec3A, Vec3A, Color, &dyn Fn(Vec3A) -> Color, Vec2) -> Option<Splat>;

/// The grader's own connection.
pub fn expected(
    camera: &Camera,
    p: Vec3A,
    n: Vec3A,
    beta: Color,
    f_r: &dyn Fn(Vec3A) -> Color,
    u: Vec2,
) -> Option<Splat> {
    let s = camera.sample_wi(p, u)?;
    Some(Splat {
        raster: s.raster,
        value: beta * f_r(s.wi) * (n.dot(s.wi).abs() * s.we / s.pdf_w),
    })
}

fn camera(aperture: f32, position: Vec3A, look_at: Vec3A, size: u32, fov: f32) -> Camera {
    Camera::new(
        CameraParams {
            position,
            look_at,
            up: Vec3A::Y,
            vfov_deg: fov,
            aperture_radius: aperture,
            focus_distance: 3.9,
            shift: Vec2::ZERO,
        },
        size,
        size,
    )
}

/// Paths of the furnace check; the film is 16×16 in 4×4 tiles.
pub const PATHS: u64 = 1 << 17;

pub fn check(f: SplatFn) -> Result<(), String> {
    // Not symmetric under w → −w: f_r(−wi) instead of f_r(wi) shows.
    let f_r = |w: Vec3A| Color::new(0.3, 0.5, 0.7) * (1.5 + w.x + 0.5 * w.y);
    for aperture in [0.0, 0.05] {
        let cam = camera(aperture, Vec3A::new(0.0, 0.0, 3.9), Vec3A::ZERO, 64, 39.3);
        let points = [
            (Vec3A::new(0.6, -0.3, -1.0), Vec3A::Z),
            (Vec3A::new(-0.7, 0.8, 0.1), Vec3A::new(0.6, -0.8, 0.0)),
            (Vec3A::new(0.5, -1.0, 0.5), Vec3A::Y),
            // Facing away from the camera (a light path may reach the back
            // of a surface): n·wi < 0.
            (
                Vec3A::new(-0.8, -0.5, -0.5),
                Vec3A::new(0.3, 0.2, -1.0).normalize(),
            ),
            (Vec3A::new(0.9, 0.7, 0.3), Vec3A::X),
            // Not seen: behind the camera, and off the film (outside the
            // field of view).
            (Vec3A::new(0.0, 0.0, 5.0), Vec3A::Z),
            (Vec3A::new(3.0, 0.2, 0.0), Vec3A::Z),
        ];
        for (p, n) in points {
            let beta = Color::new(2.0, 1.0, 0.5);
            let u = Vec2::new(0.3, 0.7);
            let got = f(&cam, p, n, beta, &f_r, u);
            let want = expected(&cam, p, n, beta, &f_r, u);
            let what = format!(
                "vertex {} (normal {}), aperture {aperture}",
                fmt3(p),
                fmt3(n)
            );
            match (got, want) {
                (None, None) => {}
                (Some(g), None) => {
                    return Err(format!(
                        "{what}: the camera cannot see this point (behind it or off the film), so camera.sample_wi returns None and so must you — your splat lands at {}",
                        g.raster
                    ));
                }
                (None, Some(_)) => {
                    return Err(format!(
                        "{what}: you returned None, but the point is seen by the camera (camera.sample_wi returns a sample)"
                    ));
                }
                (Some(g), Some(w)) => {
                    if (g.raster - w.raster).length() > 1e-3 {
                        return Err(format!(
                            "{what}: your splat lands at {}, expected at the raster position of camera.sample_wi, {}",
                            g.raster, w.raster
                        ));
                    }
                    if !close3(g.value, w.value, 1e-3) {
                        let s = cam.sample_wi(p, u).expect("seen");
                        let cos_p = n.dot(s.wi);
                        let base = beta * f_r(s.wi) * (cos_p.abs() * s.we / s.pdf_w);
                        let cos_lens = (-s.wi).dot(cam.forward());
                        let named: [(Color, &str); 7] = [
                            (
                                base * cos_p.signum(),
                                "your value is negative: a signed cos θ_p — this vertex's normal faces away from the camera, and the cosine at the vertex is |n·wi|",
                            ),
                            (
                                Color::ZERO,
                                "your value is 0: cos θ_p clamped at 0 — this vertex's normal faces away from the camera, and the cosine at the vertex is |n·wi|",
                            ),
                            (
                                beta * f_r(-s.wi) * (cos_p.abs() * s.we / s.pdf_w),
                                "f_r(−wi): the BRDF takes the direction from the vertex towards the camera, s.wi, both pointing away from the surface",
                            ),
                            (
                                base / s.we,
                                "you left out the camera's importance W_e (s.we)",
                            ),
                            (base / cos_p.abs(), "you left out |cos θ_p| at the vertex"),
                            (base * s.pdf_w * s.pdf_w, "divide by pdf_w, do not multiply"),
                            (
                                base * (cos_lens / cos_p.abs()),
                                "the cosine belongs at the vertex, |n·wi|, not at the lens (the lens's cosine is already inside pdf_w and W_e)",
                            ),
                        ];
                        let why = named
                            .iter()
                            .find(|(v, _)| close3(g.value, *v, 1e-3))
                            .map_or(
                                "value = beta · f_r(wi) · |n·wi| · W_e / pdf_w",
                                |(_, why)| why,
                            );
                        return Err(format!(
                            "{what}: your splat's value is {}, expected {} — {why}",
                            fmt3(g.value),
                            fmt3(w.value)
                        ));
                    }
                }
            }
        }
    }
    furnace(f)
}

/// Points uniform on the unit sphere around the camera (p_A = 1/(4π), so
/// β = 4π), whose "BRDF" towards the camera is the emitted L_e = 0.5: the
/// splats alone form the picture of the sphere's inside, 0.5 everywhere. Each
/// tile's mean is `(W·H/N) Σ_paths Y/P` (P pixels per tile), z-tested with
/// the variance of the per-path contributions; the threshold is
/// [`Z_MAX`] per tile (16 tiles: false failure < 1e-6).
fn furnace(f: SplatFn) -> Result<(), String> {
    let (size, tile) = (16u32, 4u32);
    let cam = camera(0.0, Vec3A::ZERO, Vec3A::new(0.0, 0.0, -1.0), size, 60.0);
    let tiles = (size / tile) as usize;
    let le = |_: Vec3A| Color::splat(0.5);
    let beta = Color::splat(4.0 * PI);
    let mut sum = vec![0.0f64; tiles * tiles];
    let mut sum2 = vec![0.0f64; tiles * tiles];
    for i in 0..PATHS {
        let mut s = Sampler::new(12, i, 0);
        let y = uniform_sphere(s.next_2d());
        let Some(splat) = f(&cam, y, -y, beta, &le, s.next_2d()) else {
            continue;
        };
        let (px, py) = (splat.raster.x as i64, splat.raster.y as i64);
        if !(0..size as i64).contains(&px) || !(0..size as i64).contains(&py) {
            return Err(format!("a splat landed off the film at {}", splat.raster));
        }
        let t = (py as usize / tile as usize) * tiles + px as usize / tile as usize;
        let v = splat.value.x as f64;
        sum[t] += v;
        sum2[t] += v * v;
    }
    let n = PATHS as f64;
    // Tile mean = c · E[Y] with c = W·H / P (P = tile² pixels per tile).
    let c = (size * size) as f64 / (tile * tile) as f64;
    for t in 0..tiles * tiles {
        let mean = c * sum[t] / n;
        let var_y = (sum2[t] / n - (sum[t] / n).powi(2)) * n / (n - 1.0);
        let se = c * (var_y / n).sqrt();
        let z = (mean - 0.5).abs() / se.max(1e-12);
        if !z.is_finite() || z > Z_MAX {
            return Err(format!(
                "furnace (camera inside a sphere emitting L_e = 0.5, seen only by light tracing): tile {t} averages {mean:.4}, expected 0.5 ({}) — check W_e / pdf_w and the cosine at the vertex",
                crate::stats::deviation(mean, 0.5, se)
            ));
        }
    }
    Ok(())
}
