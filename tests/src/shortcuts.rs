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
pub fn has_token(code: &str, word: &str) -> bool {
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
