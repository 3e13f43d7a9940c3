//! Unit tests of `plots/path_figure.rs`.

use lesson11::plots::path_figure::*;
use raytracer::integrator::PathTracer;
use raytracer::math::UVec2;
use raytracer::scene::Scene;

/// A path-tracing sample of a small Cornell box: a polyline per path
/// segment and a dot per vertex, the shadow rays dashed, the picture
/// embedded, the labels in subscript.
#[test]
fn a_recorded_path_is_drawn_over_its_picture() {
    let mut scene = Scene::builtin("cornell").unwrap();
    scene.set_resolution(32, 32);
    let pt = PathTracer {
        max_depth: Some(4),
        ..PathTracer::default()
    };
    let record = pick_sample(&pt, &scene, UVec2::new(16, 20), 1, |r| {
        r.paths[0].vertices.len() as u32
    });
    let vertices = record.paths[0].vertices.len();
    assert_eq!(vertices, 5, "D = 4 segments: the lens and four hits");
    let svg = path_figure_svg(&record, b"png", (32, 32), Labels::Subpaths);
    assert!(svg.contains("data:image/png;base64,cG5n"));
    assert_eq!(svg.matches("<circle").count(), vertices - 1);
    let shadow = record.segments.len();
    assert_eq!(svg.matches("stroke-dasharray").count(), shadow);
    for label in ["x₀", "x₁", "x₂"] {
        assert!(svg.contains(label), "{label}");
    }
    assert_eq!(subscript(12), "₁₂");
}
