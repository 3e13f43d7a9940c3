//! The renderer's own answer is not the student's: each exercise lists in
//! `info.toml` (`forbidden`) the renderer's items that compute what it asks
//! — the warp of exercise 7, the photon map's own estimate for exercise 17,
//! the whole path tracer for exercise 11 — and a solution that uses one
//! fails, with the item named, before it is graded. The student's compiled
//! file is read (comments left out); nothing else is.
//!
//! An entry is a path (`raytracer::sampling::warp::cosine_hemisphere`),
//! found where the code names it qualified (`warp::cosine_hemisphere`) or
//! imports it (`use raytracer::sampling::warp::{cosine_hemisphere, …}`,
//! `…::warp::*`), or a piece of code found as written (`Brdf::Lambert`,
//! `.radiance(`).

use exercises::Exercise;

/// The source of the exercise as compiled: the stub in `src/`, or with the
/// feature `solutions` the reference solution.
pub fn compiled_source(e: &Exercise) -> Option<String> {
    let file = if exercises::SOLUTIONS {
        e.solution_file()
    } else {
        e.file.clone()
    };
    std::fs::read_to_string(exercises::crate_dir().join(file)).ok()
}

/// `code` without its comments (`// …` to the end of the line, `/* … */`).
pub fn without_comments(code: &str) -> String {
    let mut out = String::with_capacity(code.len());
    let mut rest = code;
    while !rest.is_empty() {
        if let Some(after) = rest.strip_prefix("//") {
            rest = after.find('\n').map_or("", |i| &after[i..]);
        } else if let Some(after) = rest.strip_prefix("/*") {
            rest = after.find("*/").map_or("", |i| &after[i + 2..]);
        } else {
            let c = rest.chars().next().expect("not empty");
            out.push(c);
            rest = &rest[c.len_utf8()..];
        }
    }
    out
}

fn is_ident(c: char) -> bool {
    c.is_alphanumeric() || c == '_'
}

/// Whether `code` contains `word` with no identifier character right before
/// or after it.
fn has_token(code: &str, word: &str) -> bool {
    code.match_indices(word).any(|(i, _)| {
        let before = code[..i].chars().next_back();
        let after = code[i + word.len()..].chars().next();
        !before.is_some_and(is_ident) && !after.is_some_and(is_ident)
    })
}

/// Whether `code` (without comments) uses the forbidden `item`.
pub fn uses(code: &str, item: &str) -> bool {
    let segments: Vec<&str> = item.split("::").collect();
    if !item.starts_with("raytracer::") || segments.len() < 2 {
        return code.contains(item);
    }
    let (name, parent) = (segments[segments.len() - 1], segments[segments.len() - 2]);
    if has_token(code, &format!("{parent}::{name}")) {
        return true;
    }
    // Imported in a group, or with everything of its parent.
    code.split("use ").skip(1).any(|u| {
        let u: String = u
            .split(';')
            .next()
            .unwrap_or("")
            .chars()
            .filter(|c| !c.is_whitespace())
            .collect();
        (u.contains(&format!("{parent}::{{")) && has_token(&u, name))
            || u.contains(&format!("{parent}::*"))
    })
}

/// The failure of an exercise whose code uses one of its forbidden items.
pub fn shortcut(e: &Exercise) -> Option<String> {
    let code = without_comments(&compiled_source(e)?);
    let item = e.forbidden.iter().find(|item| uses(&code, item))?;
    Some({
        let item = item.trim_start_matches("raytracer::");
        crate::tr!("report.shortcut", item)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

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
        let code = without_comments(
            "// uses warp::cosine_hemisphere\n/* and\n warp::cosine_hemisphere */ x",
        );
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
        let src = crate::texts::raytracer_sources();
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
}
