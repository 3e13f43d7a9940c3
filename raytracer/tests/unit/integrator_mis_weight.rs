//! Unit tests of `integrator/mis_weight.rs`.

use raytracer::brdf::{Brdf, Lambert, Mirror, Phong, Texture};
use raytracer::camera::CameraParams;
use raytracer::frame::Frame;
use raytracer::geometry::{Interaction, Quad, Shape, Sphere};
use raytracer::integrator::mis_weight::*;
use raytracer::integrator::vertex::Vertex;
use raytracer::integrator::vertex::{VertexKind, pdf_w_to_a};
use raytracer::light::{Light, PointLight};
use raytracer::math::{Color, Ray, Vec2, Vec3A};
use raytracer::scene::Scene;
use raytracer::scene::{Emitter, RenderSettings, SceneObject, SceneParts};

/// Shapes, in order: floor (Lambert), back wall (Phong n = 10), mirror
/// wall, a quad lamp facing down, a sphere lamp, and a point light;
/// lights 0, 1, 2 in that order. Lights are chosen by power, so their
/// probabilities differ.
fn scene() -> Scene {
    let quad = |origin: Vec3A, e1: Vec3A, e2: Vec3A| Shape::Quad(Quad { origin, e1, e2 });
    let object = |name: &str, shape, brdf, emission: Option<f32>| SceneObject {
        name: name.into(),
        shape,
        brdf,
        emitter: emission.map(|e| Emitter {
            radiance: Color::splat(e),
            two_sided: false,
        }),
    };
    let objects = vec![
        object(
            "floor",
            quad(Vec3A::new(-3.0, 0.0, 3.0), 6.0 * Vec3A::X, -6.0 * Vec3A::Z),
            0,
            None,
        ),
        object(
            "back",
            quad(Vec3A::new(-3.0, 0.0, -2.0), 6.0 * Vec3A::X, 4.0 * Vec3A::Y),
            1,
            None,
        ),
        object(
            "mirror",
            quad(Vec3A::new(2.0, 0.0, 3.0), 4.0 * Vec3A::Y, -6.0 * Vec3A::Z),
            2,
            None,
        ),
        object(
            "lamp",
            quad(Vec3A::new(-0.5, 2.5, -0.5), Vec3A::X, Vec3A::Z),
            0,
            Some(8.0),
        ),
        object(
            "ball",
            Shape::Sphere(Sphere {
                center: Vec3A::new(-1.0, 1.5, -0.5),
                radius: 0.3,
            }),
            0,
            Some(20.0),
        ),
    ];
    let brdfs = vec![
        Brdf::Lambert(Lambert {
            albedo: Texture::Constant(Color::splat(0.7)),
        }),
        Brdf::Phong(Phong {
            albedo: Color::splat(0.6),
            exponent: 10.0,
        }),
        Brdf::Mirror(Mirror {
            reflectance: Color::ONE,
        }),
    ];
    Scene::build(
        "mis",
        SceneParts {
            camera: CameraParams {
                position: Vec3A::new(0.0, 1.0, 4.0),
                look_at: Vec3A::new(0.0, 0.5, 0.0),
                up: Vec3A::Y,
                vfov_deg: 60.0,
                aperture_radius: 0.0,
                focus_distance: 4.0,
                shift: Vec2::ZERO,
            },
            settings: RenderSettings::default(),
            brdf_names: vec!["lambert".into(), "phong".into(), "mirror".into()],
            brdfs,
            objects,
            lights: vec![Light::Point(PointLight {
                position: Vec3A::new(1.0, 2.0, 0.0),
                intensity: Color::splat(5.0),
            })],
        },
    )
}

/// A point of a path: its position, the shape it lies on and its normal
/// (`None`: the lens or the point light).
#[derive(Clone, Copy)]
struct Point {
    p: Vec3A,
    shape: Option<(u32, Vec3A)>,
}

fn surface(shape: u32, p: Vec3A, n: Vec3A) -> Point {
    Point {
        p,
        shape: Some((shape, n)),
    }
}

/// The vertex at `x[i]` as a subpath that came from `x[from]` makes it.
fn vertex(scene: &Scene, x: &[Point], i: usize, from: usize) -> Vertex {
    let (shape, n) = x[i].shape.unwrap();
    let it = Interaction {
        p: x[i].p,
        ng: n,
        frame: Frame::from_normal(n),
        uv: Vec2::ZERO,
        wo: (x[from].p - x[i].p).normalize_or_zero(),
        t: 1.0,
        shape,
        p_error: Vec3A::ZERO,
    };
    Vertex::surface(scene, it, Color::ONE)
}

/// The light-end vertex `y_0` at `x[k]` (light `light`).
fn light_vertex(scene: &Scene, x: &[Point], k: usize, light: u32) -> Vertex {
    let n = x[k].shape.map_or(Vec3A::ZERO, |(_, n)| n);
    let mut y = Vertex::light(light, x[k].p, n, Color::ONE, 0.0);
    y.pdf_fwd_a = y.pdf_light_origin_a(scene);
    y
}

/// The two subpaths of strategy `(s, t)` for the path `x` (lens first,
/// light last), with the densities a random walk records: every
/// vertex's forward density from its predecessors, and the reverse
/// density of all but the last two (which `mis_weight` sets), and the
/// resampled vertex of `s = 1` or `t = 1`.
fn subpaths(
    scene: &Scene,
    x: &[Point],
    light: u32,
    s: usize,
    t: usize,
) -> (Vec<Vertex>, Vec<Vertex>, Option<Vertex>) {
    let n = x.len();
    let mut camera = vec![Vertex::camera(x[0].p, Color::ONE)];
    for i in 1..t {
        let mut v = vertex(scene, x, i, i - 1);
        v.pdf_fwd_a = if i == 1 {
            let pdf_w = scene
                .camera
                .pdf_we(&Ray::new(x[0].p, (x[1].p - x[0].p).normalize()))
                .pdf_w;
            pdf_w_to_a(pdf_w, &camera[0], &v)
        } else {
            camera[i - 1].pdf_a(scene, Some(&camera[i - 2]), &v)
        };
        camera.push(v);
    }
    for i in 0..t.saturating_sub(2) {
        camera[i].pdf_rev_a = camera[i + 1].pdf_a(scene, camera.get(i + 2), &camera[i]);
    }
    let mut path: Vec<Vertex> = Vec::new();
    for j in 0..s {
        let k = n - 1 - j;
        let mut v = if j == 0 {
            light_vertex(scene, x, k, light)
        } else {
            vertex(scene, x, k, k + 1)
        };
        if j >= 1 {
            v.pdf_fwd_a =
                path[j - 1].pdf_a(scene, if j >= 2 { Some(&path[j - 2]) } else { None }, &v);
        }
        path.push(v);
    }
    for j in 0..s.saturating_sub(2) {
        path[j].pdf_rev_a = path[j + 1].pdf_a(scene, path.get(j + 2), &path[j]);
    }
    for v in camera.iter_mut().chain(path.iter_mut()) {
        v.delta = v.kind == VertexKind::Surface && scene.brdf(&v.it).is_delta();
    }
    let sampled = if t == 1 {
        Some(Vertex::camera(x[0].p, Color::ZERO))
    } else if s == 1 {
        Some(light_vertex(scene, x, n - 1, light))
    } else {
        None
    };
    (path, camera, sampled)
}

/// The density of the whole path under strategy `s` (`t = n − s`), as
/// a product over its vertices, each with the density of the subpath
/// that made it: camera vertices from the lens on, light vertices from
/// the light on, and `y_0` with next event estimation's density if
/// `s = 1` and the path is longer than two vertices (the lens point is
/// common to every strategy and left out). Zero for `s = 0` with a point
/// light (no ray hits it).
fn path_density(scene: &Scene, x: &[Point], light: u32, s: usize) -> f64 {
    let n = x.len();
    let is_point = scene.lights[light as usize].is_delta();
    if s == 0 && is_point {
        return 0.0;
    }
    let on = |i: usize, from: usize| {
        if i == n - 1 {
            let mut y = light_vertex(scene, x, i, light);
            y.it.wo = (x[from].p - x[i].p).normalize();
            y
        } else if i == 0 {
            Vertex::camera(x[0].p, Color::ONE)
        } else {
            vertex(scene, x, i, from)
        }
    };
    let mut p = 1.0f64;
    // Camera side: x_1 … x_{t−1}.
    for i in 1..n - s {
        let v = on(i, i - 1);
        p *= if i == 1 {
            let pdf_w = scene
                .camera
                .pdf_we(&Ray::new(x[0].p, (x[1].p - x[0].p).normalize()))
                .pdf_w;
            pdf_w_to_a(pdf_w, &on(0, 0), &v) as f64
        } else {
            on(i - 1, i - 2).pdf_a(scene, Some(&on(i - 2, i - 2)), &v) as f64
        };
    }
    // Light side: x_{n−1} … x_{n−s}.
    for j in 0..s {
        let k = n - 1 - j;
        p *= match j {
            0 if s == 1 && n > 2 => on(k, k - 1).pdf_light_point_a(scene, &on(k - 1, k - 2)) as f64,
            0 => on(k, k - 1).pdf_light_origin_a(scene) as f64,
            1 => on(k + 1, k).pdf_light_a(scene, &on(k, k + 1)) as f64,
            _ => on(k + 1, k + 2).pdf_a(scene, Some(&on(k + 2, k + 2)), &on(k, k + 1)) as f64,
        };
    }
    p
}

/// For fixed paths of 2 to 6 vertices (1 to 5 segments) ending on each
/// kind of light — a quad (NEE samples it by area, as a light path
/// starts), a sphere (NEE samples the cone it subtends: another density
/// for `s = 1`) and a point light (no strategy can hit it) — over
/// Lambert and Phong vertices: the weight `mis_weight` gives each
/// strategy, computed from that strategy's own two subpaths, equals the
/// power heuristic `p_s² / Σ_i p_i²` of the strategies' path densities,
/// each a product over the vertices (relative 1e-3), and the weights sum
/// to 1 (1e-4). With a mirror vertex in the path, the strategies that
/// would connect at it or next to it are skipped, and the others still
/// sum to 1.
///
/// What it catches: the resampled light point of `s = 1` weighted with
/// the area density of a light path's origin although next event
/// estimation picks a sphere light's point in its cone — the weights
/// still summed to 1 (every strategy used the same wrong density), but
/// were not the power heuristic of the densities used: strategy (0, 3)
/// of a path onto the sphere got 0.0016 instead of 0.0006. Also any
/// error in the running ratios or in the four reverse densities that a
/// connection changes. (The strategy-images test only adds images up,
/// which holds for any weights that sum to 1.)
#[test]
fn weights_sum_to_one() {
    let scene = scene();
    let eye = Point {
        p: scene.camera.position(),
        shape: None,
    };
    let middle = [
        surface(0, Vec3A::new(0.2, 0.0, 0.5), Vec3A::Y),
        surface(1, Vec3A::new(-0.3, 0.8, -2.0), Vec3A::Z),
        surface(0, Vec3A::new(0.6, 0.0, -0.8), Vec3A::Y),
        surface(1, Vec3A::new(0.5, 1.4, -2.0), Vec3A::Z),
    ];
    let ball = Vec3A::new(-1.0, 1.5, -0.5);
    for light in 0..3u32 {
        for k in 0..=middle.len() {
            let mut x = vec![eye];
            x.extend_from_slice(&middle[..k]);
            let last = x.last().unwrap().p;
            x.push(match light {
                0 => surface(3, Vec3A::new(0.1, 2.5, -0.2), -Vec3A::Y),
                1 => {
                    // On the cap the previous point sees, off its axis.
                    let n = ((last - ball).normalize() + Vec3A::new(0.2, -0.1, 0.15)).normalize();
                    surface(4, ball + 0.3 * n, n)
                }
                _ => Point {
                    p: Vec3A::new(1.0, 2.0, 0.0),
                    shape: None,
                },
            });
            let n = x.len();
            let densities: Vec<f64> = (0..n).map(|s| path_density(&scene, &x, light, s)).collect();
            let total: f64 = densities.iter().map(|p| p * p).sum();
            let mut sum = 0.0;
            for (s, &density) in densities.iter().enumerate() {
                let t = n - s;
                if s == 0 && light == 2 {
                    continue;
                }
                let (mut l, mut c, sampled) = subpaths(&scene, &x, light, s, t);
                let w = mis_weight(&scene, &mut l, &mut c, s, t, sampled) as f64;
                // What the inspector shows: every strategy's weight for
                // this path, the integrator's own one bit for bit.
                let all = mis_weights(&scene, &mut l, &mut c, s, t, sampled);
                assert_eq!(all[s] as f64, w);
                for (i, &wi) in all.iter().enumerate() {
                    let e = densities[i] * densities[i] / total;
                    assert!(
                        (wi as f64 - e).abs() <= 1e-3 * e.max(1e-3),
                        "({s}, {t}): {all:?}"
                    );
                }
                let expected = density * density / total;
                assert!(
                    (w - expected).abs() <= 1e-3 * expected.max(1e-3),
                    "light {light}, {n} vertices, strategy ({s}, {t}): weight {w}, expected {expected}"
                );
                sum += w;
            }
            assert!(
                (sum - 1.0).abs() < 1e-4,
                "light {light}, {n} vertices: weights sum to {sum}"
            );
        }
    }
    // A mirror in the middle: x_2 on the mirror wall.
    let x = [
        eye,
        middle[0],
        surface(2, Vec3A::new(2.0, 1.0, -0.5), -Vec3A::X),
        middle[1],
        surface(3, Vec3A::new(0.1, 2.5, -0.2), -Vec3A::Y),
    ];
    let n = x.len();
    let mut sum = 0.0;
    for s in 0..n {
        let t = n - s;
        // (s, t) connects x_{t−1} to x_t: not at the mirror x_2.
        if t - 1 == 2 || t == 2 {
            continue;
        }
        let (mut l, mut c, sampled) = subpaths(&scene, &x, 0, s, t);
        sum += mis_weight(&scene, &mut l, &mut c, s, t, sampled) as f64;
    }
    assert!(
        (sum - 1.0).abs() < 1e-4,
        "with a mirror: weights sum to {sum}"
    );
}
