//! The grader's bidirectional test bed (exercise 15): a small scene with a
//! Lambert floor, a Phong back wall whose normal faces away from the room, a
//! mirror wall and three kinds of light (a quad, a sphere, a point), and
//! random paths across it with every vertex's area density from the camera
//! side and from the light side, computed by the renderer's own density
//! functions ([`Vertex::pdf_a`] and the light's), in f64. From a path the
//! grader gets each strategy's density as a product over the vertices (the
//! expected MIS weights) and the two subpaths that strategy would have
//! grown (what the student's weight receives).

use raytracer::brdf::{Brdf, Lambert, Mirror, Phong, Texture};
use raytracer::camera::CameraParams;
use raytracer::frame::Frame;
use raytracer::geometry::{Interaction, Quad, Shape, Sphere};
use raytracer::integrator::vertex::{Vertex, pdf_w_to_a};
use raytracer::light::{Light, PointLight};
use raytracer::math::{Color, Ray, Vec2, Vec3A};
use raytracer::sampling::Sampler;
use raytracer::scene::{Emitter, RenderSettings, Scene, SceneObject, SceneParts};

// ── The test scene ───────────────────────────────────────────────────────

const FLOOR: u32 = 0;
const BACK: u32 = 1;
const MIRROR: u32 = 2;
const LAMP: u32 = 3;
const BALL: u32 = 4;
const BALL_CENTER: Vec3A = Vec3A::new(-1.0, 1.5, -0.5);
const BALL_RADIUS: f32 = 0.3;

/// Shapes, in order: floor (Lambert, normal up), back wall (Phong n = 10,
/// its normal facing AWAY from the room: signed cosines show), mirror wall,
/// a quad lamp facing down, a sphere lamp; lights 0 (quad), 1 (sphere), 2
/// (a point light), chosen by power. A pinhole camera.
pub fn test_scene() -> Scene {
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
            quad(Vec3A::new(-3.0, 0.0, -2.0), 4.0 * Vec3A::Y, 6.0 * Vec3A::X),
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
                center: BALL_CENTER,
                radius: BALL_RADIUS,
            }),
            0,
            Some(20.0),
        ),
    ];
    let brdfs = vec![
        Brdf::Lambert(Lambert {
            albedo: Texture::Constant(Color::new(0.7, 0.6, 0.5)),
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
        "ex15-test",
        SceneParts {
            camera: CameraParams {
                position: Vec3A::new(0.0, 1.0, 4.0),
                look_at: Vec3A::new(0.0, 0.8, 0.0),
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

/// A whole path `x_0 … x_{n−1}` (lens first, a light last) with every
/// vertex's area density from the camera side and from the light side, in
/// f64, and the same in solid angle (for the mistake of the wrong measure).
pub struct PathCase {
    /// The vertices as the camera side makes them (`x_0` the lens; the last
    /// a surface vertex on the emitter, if it is an area light).
    pub cam_side: Vec<Vertex>,
    /// The vertices as the light side makes them (`x_{n−1}` a light vertex).
    pub light_side: Vec<Vertex>,
    /// `p_cam[j]` for `j ≥ 1` (`[0]` unused), `p_light[j]` for `j ≥ 1`.
    pub p_cam: Vec<f64>,
    pub p_light: Vec<f64>,
    pub w_cam: Vec<f64>,
    pub w_light: Vec<f64>,
    /// Whether `x_j` has a delta BRDF.
    pub delta: Vec<bool>,
    pub point_light: bool,
}

impl PathCase {
    pub fn n(&self) -> usize {
        self.p_cam.len()
    }

    /// Whether strategy `s` (with `t = n − s` camera vertices) can make the path.
    pub fn possible(&self, s: usize) -> bool {
        let t = self.n() - s;
        if s == 0 {
            !self.point_light
        } else {
            !self.delta[t - 1] && !self.delta[t]
        }
    }

    /// The density of strategy `s` (with the densities `cam`, `light`): the
    /// first `t` vertices from the camera, the rest from the light; a
    /// delta's zero counts as 1 (it is common to every possible strategy).
    pub fn density(&self, s: usize, cam: &[f64], light: &[f64]) -> f64 {
        let t = self.n() - s;
        let one = |p: f64| if p != 0.0 { p } else { 1.0 };
        let mut p = 1.0;
        for (j, (&c, &l)) in cam.iter().zip(light).enumerate().skip(1) {
            p *= one(if j < t { c } else { l });
        }
        p
    }

    pub fn densities(&self) -> Vec<f64> {
        (0..self.n())
            .map(|s| self.density(s, &self.p_cam, &self.p_light))
            .collect()
    }

    /// The power heuristic of strategy `s` over `strategies`, with `p`.
    pub fn power(&self, s: usize, p: &[f64], strategies: impl Iterator<Item = usize>) -> f64 {
        let sum: f64 = strategies.map(|i| p[i] * p[i]).sum();
        p[s] * p[s] / sum
    }

    pub fn expected(&self, s: usize) -> f64 {
        if !self.possible(s) {
            return 0.0;
        }
        let p = self.densities();
        self.power(s, &p, (0..self.n()).filter(|&i| self.possible(i)))
    }

    /// The two subpaths of strategy `s` as the random walks record them:
    /// forward densities everywhere, reverse densities except at the two
    /// vertices next to the edge on each side (left stale: half the true
    /// value, as if from another path).
    pub fn subpaths(&self, s: usize) -> (Vec<Vertex>, Vec<Vertex>) {
        let n = self.n();
        let t = n - s;
        let mut camera: Vec<Vertex> = self.cam_side[..t].to_vec();
        for (j, v) in camera.iter_mut().enumerate() {
            v.pdf_fwd_a = self.p_cam[j] as f32;
            v.pdf_rev_a = if j + 2 < t {
                self.p_light[j] as f32
            } else {
                0.5 * self.p_light[j] as f32
            };
        }
        let mut light: Vec<Vertex> = (0..s).map(|k| self.light_side[n - 1 - k]).collect();
        for (k, v) in light.iter_mut().enumerate() {
            let j = n - 1 - k;
            v.pdf_fwd_a = self.p_light[j] as f32;
            v.pdf_rev_a = if k + 2 < s {
                self.p_cam[j] as f32
            } else {
                0.5 * self.p_cam[j] as f32
            };
        }
        (light, camera)
    }
}

/// A surface vertex at `p` on shape `shape` with normal `n`, arrived at from `from`.
fn surface_vertex(scene: &Scene, shape: u32, p: Vec3A, n: Vec3A, from: Vec3A) -> Vertex {
    let it = Interaction {
        p,
        ng: n,
        frame: Frame::from_normal(n),
        uv: Vec2::ZERO,
        wo: (from - p).normalize_or_zero(),
        t: 1.0,
        shape,
        p_error: Vec3A::ZERO,
    };
    let mut v = Vertex::surface(scene, it, Color::ONE);
    v.delta = scene.brdf(&it).is_delta();
    v
}

/// A random point on a shape of the test scene (not the lamps) and its
/// normal as the shape orients it.
fn random_point(shape: u32, u: Vec2) -> (Vec3A, Vec3A) {
    match shape {
        FLOOR => (
            Vec3A::new(-2.5 + 4.0 * u.x, 0.0, -1.8 + 4.0 * u.y),
            Vec3A::Y,
        ),
        BACK => (
            Vec3A::new(-2.5 + 4.0 * u.x, 0.2 + 2.0 * u.y, -2.0),
            -Vec3A::Z,
        ),
        _ => (
            Vec3A::new(2.0, 0.2 + 2.0 * u.x, -1.8 + 4.0 * u.y),
            -Vec3A::X,
        ),
    }
}

/// A random path of `n` vertices ending on light `light` (0: the quad lamp,
/// 1: the sphere, 2: the point light), `mirror`: one middle vertex on the
/// mirror. `None` if a density that should not be zero is (a Phong lobe
/// that does not reach, a point outside the picture): drawn again.
pub fn random_path(
    scene: &Scene,
    n: usize,
    light: u32,
    mirror: bool,
    sampler: &mut Sampler,
) -> Option<PathCase> {
    let eye = scene.camera.position();
    // x_1: seen through a random pixel; then other surfaces than the previous one.
    let size = Vec2::new(scene.camera.width as f32, scene.camera.height as f32);
    let ray = scene
        .camera
        .generate_ray(sampler.next_2d() * size, Vec2::ZERO);
    let mut points: Vec<(u32, Vec3A, Vec3A)> = Vec::new();
    if n > 2 {
        let hit = scene.intersect(&ray)?;
        // Not on the mirror or a lamp.
        if hit.shape >= MIRROR {
            return None;
        }
        let n0 = if hit.shape == FLOOR {
            Vec3A::Y
        } else {
            -Vec3A::Z
        };
        points.push((hit.shape, hit.p, n0));
    }
    let mirror_at = if mirror && n > 3 {
        1 + (sampler.next_1d() * (n - 3) as f32) as usize
    } else {
        0
    };
    while points.len() < n - 2 {
        let prev = points.last().map(|p| p.0).unwrap_or(u32::MAX);
        let shape = if points.len() == mirror_at && mirror_at > 0 {
            MIRROR
        } else if prev == FLOOR {
            BACK
        } else {
            FLOOR
        };
        if shape == prev {
            return None;
        }
        let (p, nn) = random_point(shape, sampler.next_2d());
        points.push((shape, p, nn));
    }
    // The light point.
    let u = sampler.next_2d();
    let (lp, ln) = match light {
        0 => (Vec3A::new(-0.5 + u.x, 2.5, -0.5 + u.y), -Vec3A::Y),
        1 => {
            let last = points.last().map_or(eye, |p| p.1);
            let n = ((last - BALL_CENTER).normalize()
                + 0.3 * Vec3A::new(u.x - 0.5, u.y - 0.5, 0.2))
            .normalize();
            (BALL_CENTER + BALL_RADIUS * n, n)
        }
        _ => (Vec3A::new(1.0, 2.0, 0.0), Vec3A::ZERO),
    };
    let light_index = light;
    let mut pos = vec![eye];
    pos.extend(points.iter().map(|p| p.1));
    pos.push(lp);
    // Vertices as each side makes them (ω_o towards the side's predecessor).
    let mut cam_side = vec![Vertex::camera(eye, Color::ONE)];
    let mut light_side = vec![Vertex::camera(eye, Color::ONE)];
    for (k, &(shape, p, nn)) in points.iter().enumerate() {
        cam_side.push(surface_vertex(scene, shape, p, nn, pos[k]));
        light_side.push(surface_vertex(scene, shape, p, nn, pos[k + 2]));
    }
    let end_shape = match light {
        0 => Some(LAMP),
        1 => Some(BALL),
        _ => None,
    };
    match end_shape {
        Some(shape) => cam_side.push(surface_vertex(scene, shape, lp, ln, pos[n - 2])),
        None => cam_side.push(Vertex::light(light_index, lp, ln, Color::ONE, 0.0)),
    }
    let mut y0 = Vertex::light(light_index, lp, ln, Color::ONE, 0.0);
    y0.pdf_fwd_a = y0.pdf_light_origin_a(scene);
    light_side.push(y0);
    let delta: Vec<bool> = cam_side.iter().map(|v| v.delta).collect();
    // Densities from the camera side.
    let mut p_cam = vec![0.0f64; n];
    let mut w_cam = vec![0.0f64; n];
    let mut p_light = vec![0.0f64; n];
    let mut w_light = vec![0.0f64; n];
    let to_w = |p_a: f64, from: &Vertex, to: &Vertex| {
        let d = to.p() - from.p();
        let cos = if to.is_on_surface() {
            to.it.ng.dot(d.normalize()).abs() as f64
        } else {
            1.0
        };
        p_a * d.length_squared() as f64 / cos
    };
    for j in 1..n {
        let target = &cam_side[j];
        let p = if j == 1 {
            let pdf_w = scene
                .camera
                .pdf_we(&Ray::new(eye, (pos[1] - eye).normalize()))
                .pdf_w;
            pdf_w_to_a(pdf_w, &cam_side[0], target)
        } else {
            cam_side[j - 1].pdf_a(scene, Some(&cam_side[j - 2]), target)
        } as f64;
        p_cam[j] = p;
        w_cam[j] = to_w(p, &cam_side[j - 1], target);
    }
    for j in (1..n).rev() {
        let target = if j == n - 1 {
            &light_side[j]
        } else {
            &cam_side[j]
        };
        let p = if j == n - 1 {
            light_side[j].pdf_light_origin_a(scene)
        } else if j == n - 2 {
            light_side[n - 1].pdf_light_a(scene, target)
        } else {
            light_side[j + 1].pdf_a(scene, Some(&light_side[j + 2]), target)
        } as f64;
        p_light[j] = p;
        w_light[j] = if j == n - 1 {
            p
        } else {
            to_w(p, &light_side[j + 1], target)
        };
    }
    // Reject paths where a density is zero that no delta explains.
    for j in 1..n {
        let delta_cam = delta[j - 1];
        let delta_light = j + 1 < n && delta[j + 1];
        if (p_cam[j] == 0.0 && !delta_cam) || (p_light[j] == 0.0 && !delta_light) {
            return None;
        }
        if !p_cam[j].is_finite() || !p_light[j].is_finite() {
            return None;
        }
    }
    Some(PathCase {
        cam_side,
        light_side,
        p_cam,
        p_light,
        w_cam,
        w_light,
        delta,
        point_light: light == 2,
    })
}
