//! Direct lighting against closed forms: a Lambertian floor under a
//! rectangular area light, whose irradiance is given exactly by Lambert's
//! polygon formula (the form factor of a polygon seen from a point).

use raytracer::brdf::{Brdf, Lambert, Texture};
use raytracer::camera::CameraParams;
use raytracer::geometry::{Quad, Shape};
use raytracer::integrator::Direct;
use raytracer::math::{Color, Vec2, Vec3A};
use raytracer::render::{RenderOptions, render};
use raytracer::scene::{Emitter, RenderSettings, Scene, SceneObject, SceneParts};

/// Irradiance at `x` (normal `n`) from a polygon of constant radiance `l`:
/// `E = (L/2) Σ_i Θ_i (n · γ_i)`, where `Θ_i` is the angle the edge
/// `v_i v_{i+1}` subtends at `x` and `γ_i` the unit normal of the plane through
/// `x` and that edge (Lambert 1760; e.g. Arvo, "Irradiance tensors", 1995).
fn polygon_irradiance(x: Vec3A, n: Vec3A, vertices: &[Vec3A], l: f32) -> f32 {
    let mut sum = 0.0f64;
    for i in 0..vertices.len() {
        let a = (vertices[i] - x).normalize();
        let b = (vertices[(i + 1) % vertices.len()] - x).normalize();
        let theta = a.dot(b).clamp(-1.0, 1.0).acos();
        let gamma = a.cross(b).normalize();
        sum += (theta * n.dot(gamma)) as f64;
    }
    (0.5 * l as f64 * sum.abs()) as f32
}

/// A 10 m floor at y = 0 (albedo ρ), a 1 m × 0.5 m light at y = h facing down,
/// and a narrow camera at height 0.2 looking straight down at `(x, 0, z)`.
fn floor_under_light(target: Vec2, rho: f32, radiance: f32, h: f32) -> (Scene, Vec<Vec3A>) {
    let light = Quad {
        origin: Vec3A::new(-0.5, h, -0.25),
        e1: Vec3A::new(1.0, 0.0, 0.0),
        e2: Vec3A::new(0.0, 0.0, 0.5),
    };
    assert!(light.e1.cross(light.e2).y < 0.0, "the light must face down");
    let floor = Quad {
        origin: Vec3A::new(-5.0, 0.0, 5.0),
        e1: Vec3A::new(10.0, 0.0, 0.0),
        e2: Vec3A::new(0.0, 0.0, -10.0),
    };
    assert!(floor.e1.cross(floor.e2).y > 0.0);
    let corners = vec![
        light.origin,
        light.origin + light.e1,
        light.origin + light.e1 + light.e2,
        light.origin + light.e2,
    ];
    let parts = SceneParts {
        camera: CameraParams {
            position: Vec3A::new(target.x, 0.2, target.y),
            look_at: Vec3A::new(target.x, 0.0, target.y),
            up: Vec3A::new(0.0, 0.0, -1.0),
            vfov_deg: 0.5,
            aperture_radius: 0.0,
            focus_distance: 0.2,
            shift: Vec2::ZERO,
        },
        settings: RenderSettings {
            width: 4,
            height: 4,
            spp: 1024,
            max_depth: Some(2),
            rr_depth: 5,
            seed: 11,
        },
        brdf_names: vec!["floor".into(), "black".into()],
        brdfs: vec![
            Brdf::Lambert(Lambert {
                albedo: Texture::Constant(Color::splat(rho)),
            }),
            Brdf::Lambert(Lambert {
                albedo: Texture::Constant(Color::ZERO),
            }),
        ],
        objects: vec![
            SceneObject {
                name: "floor".into(),
                shape: Shape::Quad(floor),
                brdf: 0,
                emitter: None,
            },
            SceneObject {
                name: "light".into(),
                shape: Shape::Quad(light),
                brdf: 1,
                emitter: Some(Emitter {
                    radiance: Color::splat(radiance),
                    two_sided: false,
                }),
            },
        ],
        lights: Vec::new(),
    };
    (Scene::build("floor-under-light", parts), corners)
}

/// The rendered radiance of the floor is `ρ/π · E(x)`. The 16 pixels cover
/// 1.7 mm of floor, over which E changes by < 0.1%. Tolerance: 5 standard
/// errors of the 16-pixel mean (from the film's own per-pixel variance) plus
/// 0.2% for the footprint: a false failure has probability < 1e-6.
#[test]
fn floor_radiance_matches_the_polygon_form_factor() {
    let (rho, radiance, h) = (0.8, 5.0, 1.0);
    for target in [
        Vec2::new(0.0, 0.0),
        Vec2::new(0.45, 0.2),
        Vec2::new(1.5, -0.7),
        Vec2::new(-3.0, 2.0),
    ] {
        let (scene, corners) = floor_under_light(target, rho, radiance, h);
        let x = Vec3A::new(target.x, 0.0, target.y);
        let expected =
            rho / std::f32::consts::PI * polygon_irradiance(x, Vec3A::Y, &corners, radiance);
        let options = RenderOptions {
            spp: 1024,
            seed: 11,
            threads: None,
            progress: false,
            ..RenderOptions::default()
        };
        let result = render(&scene, &Direct, &options);
        let image = result.film.image();
        let variance = result.film.variance_image();
        let n = image.pixels.len() as f32;
        let mean = image.pixels.iter().map(|c| c.x).sum::<f32>() / n;
        let se = (variance.pixels.iter().map(|c| c.x).sum::<f32>() / (n * n)).sqrt();
        let tolerance = 5.0 * se + 2e-3 * expected;
        assert!(
            (mean - expected).abs() <= tolerance,
            "at {target}: rendered {mean}, form factor gives {expected} (tolerance {tolerance})"
        );
        // Channels agree (grey scene).
        assert!((image.pixels[0].x - image.pixels[0].z).abs() < 1e-6);
    }
}

/// The one-sided light gives nothing to a floor above it.
#[test]
fn one_sided_light_does_not_light_its_back() {
    let (scene, _) = floor_under_light(Vec2::ZERO, 0.8, 5.0, -0.5);
    let options = RenderOptions {
        spp: 64,
        seed: 1,
        threads: None,
        progress: false,
        ..RenderOptions::default()
    };
    let image = render(&scene, &Direct, &options).film.image();
    assert!(
        image.pixels.iter().all(|c| *c == Color::ZERO),
        "light leaked through its back"
    );
}
