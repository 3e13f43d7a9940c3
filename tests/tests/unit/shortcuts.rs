//! Unit tests of `shortcuts.rs`.

use grading::shortcuts::*;

#[test]
fn forbidden_items_are_found_qualified_imported_or_written() {
    let item = "raytracer::sampling::warp::cosine_hemisphere";
    let found = [
        "fn f(u: Vec2) -> Vec3A { raytracer::sampling::warp::cosine_hemisphere(u) }",
        "use raytracer::sampling::warp;\nfn f(u: Vec2) -> Vec3A { warp::cosine_hemisphere(u) }",
        "use raytracer::sampling::warp::{concentric_disk,\n    cosine_hemisphere};",
        "use raytracer::sampling::warp::*;",
    ];
    for code in found {
        assert!(uses(code, item), "{code}");
    }
    let not_found = [
        // The student's own functions of similar names.
        "pub fn sample_cosine_hemisphere(u: Vec2) -> Vec3A { todo!() }",
        "pub fn cosine_hemisphere_pdf(w: Vec3A) -> f32 { w.z }",
        "use raytracer::sampling::warp::{concentric_disk};",
    ];
    for code in not_found {
        assert!(!uses(code, item), "{code}");
    }
    assert!(uses(
        "let l = map.radiance(it, brdf, s, |_| true);",
        ".radiance("
    ));
    assert!(!uses(
        "let l = photon_radiance(map, it, brdf, s);",
        ".radiance("
    ));
    let code =
        without_comments("// uses warp::cosine_hemisphere\n/* and\n warp::cosine_hemisphere */ x");
    assert!(!uses(&code, item), "{code}");
    // A path's last segment is a whole token: `path` is not `path_vertices`.
    assert!(!uses(
        "use raytracer::integrator::path_vertices;",
        "raytracer::integrator::path"
    ));
    assert!(uses(
        "use raytracer::integrator::path::PathTracer;",
        "raytracer::integrator::path"
    ));
}

/// Every forbidden item names something the renderer has (a typo would
/// forbid nothing): its last segment is declared in `raytracer/src`.
#[test]
fn forbidden_items_exist() {
    let src = grading::texts::raytracer_sources();
    for e in exercises::registry() {
        for item in e.forbidden.iter().filter(|i| i.starts_with("raytracer::")) {
            let name = item.rsplit("::").next().unwrap();
            let declared = ["fn ", "struct ", "enum ", "mod ", "pub use "]
                .iter()
                .any(|kw| has_token(&src, &format!("{kw}{name}")))
                || has_token(&src, &format!("{name}("));
            assert!(declared, "{}: `{item}` is not in raytracer/src", e.name);
        }
    }
}

/// The stubs and the reference solutions use none of their forbidden items.
#[test]
fn stubs_and_solutions_take_no_shortcut() {
    for e in exercises::registry() {
        for file in [e.file.clone(), e.solution_file()] {
            let code = std::fs::read_to_string(exercises::crate_dir().join(&file)).unwrap();
            let code = without_comments(&code);
            for item in &e.forbidden {
                assert!(!uses(&code, item), "{file} uses `{item}`");
            }
        }
    }
}
