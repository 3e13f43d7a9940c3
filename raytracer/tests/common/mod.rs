//! Helpers shared by the integration tests (`use crate::common;`).

#![allow(dead_code)]

use std::sync::Arc;

use raytracer::geometry::{Shape, Transform};
use raytracer::light::Light;
use raytracer::math::{Vec3, Vec3A};
use raytracer::scene::{Scene, load_builtin};

/// The built-in scene `name` scaled by `scale` about the origin, then moved
/// by `offset`: every shape, the camera (its lens and focus distance too)
/// and point lights (whose intensity grows with `scale²`, so that what they
/// light looks the same). Radiance does not depend on the scale: the image
/// of a correct renderer does not change.
pub fn builtin_moved(name: &str, scale: f32, offset: Vec3A) -> Scene {
    let mut parts = load_builtin(name).unwrap();
    let place = |p: Vec3A| p * scale + offset;
    let transform = Transform::translate(Vec3::from(offset)) * Transform::scale(Vec3::splat(scale));
    for object in &mut parts.objects {
        match &mut object.shape {
            Shape::Quad(q) => {
                q.origin = place(q.origin);
                q.e1 *= scale;
                q.e2 *= scale;
            }
            Shape::Sphere(s) => {
                s.center = place(s.center);
                s.radius *= scale;
            }
            Shape::Mesh(m) => *m = Arc::new(m.transformed(&transform)),
        }
    }
    for light in &mut parts.lights {
        if let Light::Point(p) = light {
            p.position = place(p.position);
            p.intensity *= scale * scale;
        }
    }
    let c = &mut parts.camera;
    c.position = place(c.position);
    c.look_at = place(c.look_at);
    c.aperture_radius *= scale;
    c.focus_distance *= scale;
    Scene::build(&format!("{name} ×{scale} +{offset}"), parts)
}
