//! Arrows point down inside `raytracer`: a module uses only the modules on
//! lower layers of the order that `src/lib.rs` documents (its "Layers"
//! block), never one on its own layer or above.
//!
//! The test reads every source file, drops comments and string literals, and
//! collects each path that leaves the file's own top-level module:
//! `crate::x` (also in groups, `use crate::{x, y::z}`) and `super::` chains
//! that climb out of it. Inline modules (`mod m { … }`) count as one more
//! level for `super::`. The unit tests are not in `src/` but in `tests/unit/`
//! (lesson11's `tests/layers.rs` keeps it so), since a test may look at the
//! whole crate (a scene test may render); a `#[cfg(test)] mod … { … }` block
//! would be skipped.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

/// The layer of each top-level module, from the fenced block that follows
/// the `# Layers` heading of the crate doc: one line per layer, its number
/// first, then its modules.
fn documented_layers(lib_rs: &str) -> BTreeMap<String, u32> {
    let mut lines = lib_rs
        .lines()
        .map(|l| l.trim_start_matches("//!").trim())
        .skip_while(|l| *l != "# Layers")
        .skip_while(|l| !l.starts_with("```"))
        .skip(1);
    let mut layers = BTreeMap::new();
    for line in lines.by_ref() {
        if line.starts_with("```") {
            return layers;
        }
        let mut words = line.split_whitespace();
        let Some(number) = words.next() else { continue };
        let layer: u32 = number
            .parse()
            .unwrap_or_else(|_| panic!("lib.rs layers: `{line}` does not start with a number"));
        for module in words {
            let old = layers.insert(module.to_string(), layer);
            assert!(old.is_none(), "lib.rs layers: `{module}` is listed twice");
        }
    }
    panic!("lib.rs has no `# Layers` heading followed by a fenced block of layers");
}

/// The modules `lib.rs` declares (`mod x;`, `pub mod x;`).
fn declared_modules(lib_rs: &str) -> Vec<String> {
    strip_comments_and_strings(lib_rs)
        .lines()
        .filter_map(|l| {
            let l = l.trim();
            let rest = l
                .strip_prefix("pub mod ")
                .or_else(|| l.strip_prefix("mod "))?;
            Some(rest.trim_end_matches(';').trim().to_string())
        })
        .collect()
}

/// Every `.rs` file below `dir` with its module path relative to the crate
/// root (`render/strategies.rs` → `[render, strategies]`, `scene/mod.rs` →
/// `[scene]`).
fn module_files(dir: &Path, prefix: &[String], out: &mut Vec<(PathBuf, Vec<String>)>) {
    let mut entries: Vec<_> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .collect();
    entries.sort();
    for path in entries {
        let name = path.file_stem().unwrap().to_string_lossy().into_owned();
        if path.is_dir() {
            let mut inner = prefix.to_vec();
            inner.push(name);
            module_files(&path, &inner, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            let mut module = prefix.to_vec();
            if name != "mod" && !(prefix.is_empty() && name == "lib") {
                module.push(name);
            }
            out.push((path, module));
        }
    }
}

/// The code of a Rust file with comments removed and string and character
/// literals emptied (newlines kept, so line numbers stay right).
fn strip_comments_and_strings(text: &str) -> String {
    let c: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len());
    let at = |j: usize| c.get(j).copied();
    let mut i = 0;
    // Copies the newlines of c[from..to] so that lines keep their numbers.
    let newlines = |out: &mut String, from: usize, to: usize| {
        out.extend(c[from..to.min(c.len())].iter().filter(|&&ch| ch == '\n'));
    };
    while i < c.len() {
        match c[i] {
            '/' if at(i + 1) == Some('/') => {
                while i < c.len() && c[i] != '\n' {
                    i += 1;
                }
            }
            '/' if at(i + 1) == Some('*') => {
                let (start, mut depth) = (i, 0);
                while i < c.len() {
                    if c[i] == '/' && at(i + 1) == Some('*') {
                        depth += 1;
                        i += 2;
                    } else if c[i] == '*' && at(i + 1) == Some('/') {
                        depth -= 1;
                        i += 2;
                        if depth == 0 {
                            break;
                        }
                    } else {
                        i += 1;
                    }
                }
                newlines(&mut out, start, i);
            }
            'r' if (at(i + 1) == Some('"') || at(i + 1) == Some('#'))
                && !c[..i]
                    .last()
                    .is_some_and(|p| p.is_alphanumeric() || *p == '_') =>
            {
                // A raw string r"…" or r#"…"#.
                let mut j = i + 1;
                let mut hashes = 0;
                while c.get(j) == Some(&'#') {
                    hashes += 1;
                    j += 1;
                }
                if c.get(j) != Some(&'"') {
                    out.push(c[i]);
                    i += 1;
                    continue;
                }
                let start = i;
                j += 1;
                loop {
                    if j >= c.len() {
                        break;
                    }
                    if c[j] == '"' && (1..=hashes).all(|k| c.get(j + k) == Some(&'#')) {
                        j += 1 + hashes;
                        break;
                    }
                    j += 1;
                }
                out.push_str("\"\"");
                newlines(&mut out, start, j);
                i = j;
            }
            '"' => {
                let start = i;
                i += 1;
                while i < c.len() && c[i] != '"' {
                    i += if c[i] == '\\' { 2 } else { 1 };
                }
                i += 1;
                out.push_str("\"\"");
                newlines(&mut out, start, i);
            }
            '\'' => {
                // A character literal ('x', '\n', '\u{…}'), else a lifetime.
                if at(i + 1) == Some('\\') {
                    i += 2;
                    while i < c.len() && c[i] != '\'' {
                        i += 1;
                    }
                    i += 1;
                    out.push_str("' '");
                } else if at(i + 2) == Some('\'') {
                    i += 3;
                    out.push_str("' '");
                } else {
                    out.push('\'');
                    i += 1;
                }
            }
            ch => {
                out.push(ch);
                i += 1;
            }
        }
    }
    out
}

/// If `#[cfg(test)]` starts at `toks[i]`, the index just after it.
fn after_cfg_test(toks: &[(Token, usize)], i: usize) -> Option<usize> {
    let want = [
        Token::Other('#'),
        Token::Other('['),
        Token::Ident("cfg".into()),
        Token::Other('('),
        Token::Ident("test".into()),
        Token::Other(')'),
        Token::Other(']'),
    ];
    let found = toks.get(i..i + want.len())?;
    found
        .iter()
        .map(|(t, _)| t)
        .eq(want.iter())
        .then_some(i + want.len())
}

/// The index of the `mod` keyword at `toks[i]`, allowing a `pub` or
/// `pub(…)` before it.
fn mod_keyword(toks: &[(Token, usize)], mut i: usize) -> Option<usize> {
    if toks.get(i).map(|t| &t.0) == Some(&Token::Ident("pub".into())) {
        i += 1;
        if toks.get(i).map(|t| &t.0) == Some(&Token::Other('(')) {
            while toks.get(i).is_some_and(|t| t.0 != Token::Other(')')) {
                i += 1;
            }
            i += 1;
        }
    }
    (toks.get(i).map(|t| &t.0) == Some(&Token::Ident("mod".into()))).then_some(i)
}

#[derive(Clone, Debug, PartialEq)]
enum Token {
    Ident(String),
    Path, // ::
    Open, // {
    Close,
    Other(char),
}

/// Tokens with their line numbers (1-based).
fn tokens(code: &str) -> Vec<(Token, usize)> {
    let c: Vec<char> = code.chars().collect();
    let mut out = Vec::new();
    let (mut i, mut line) = (0, 1);
    while i < c.len() {
        let ch = c[i];
        if ch == '\n' {
            line += 1;
            i += 1;
        } else if ch.is_whitespace() {
            i += 1;
        } else if ch.is_alphanumeric() || ch == '_' {
            let start = i;
            while i < c.len() && (c[i].is_alphanumeric() || c[i] == '_') {
                i += 1;
            }
            out.push((Token::Ident(c[start..i].iter().collect()), line));
        } else if ch == ':' && c.get(i + 1) == Some(&':') {
            out.push((Token::Path, line));
            i += 2;
        } else {
            out.push((
                match ch {
                    '{' => Token::Open,
                    '}' => Token::Close,
                    _ => Token::Other(ch),
                },
                line,
            ));
            i += 1;
        }
    }
    out
}

/// The top-level modules named after `crate::` (or after enough `super::` to
/// reach the crate root) at `toks[at]`: one name, or each item of a group.
fn names_at_root(toks: &[(Token, usize)], at: usize) -> Vec<String> {
    match toks.get(at).map(|t| &t.0) {
        Some(Token::Ident(name)) => vec![name.clone()],
        Some(Token::Open) => {
            // `{a, b::c, self, d::{e, f}}`: the first name of each item.
            let (mut depth, mut names, mut expect) = (0, Vec::new(), true);
            for (tok, _) in &toks[at..] {
                match tok {
                    Token::Open => {
                        depth += 1;
                        if depth == 1 {
                            expect = true;
                        }
                    }
                    Token::Close => {
                        depth -= 1;
                        if depth == 0 {
                            break;
                        }
                    }
                    Token::Other(',') if depth == 1 => expect = true,
                    Token::Ident(name) if depth == 1 && expect => {
                        names.push(name.clone());
                        expect = false;
                    }
                    _ => {}
                }
            }
            names
        }
        Some(Token::Other('*')) => vec!["*".to_string()],
        _ => Vec::new(),
    }
}

/// Every top-level module a file refers to outside its own, with the line:
/// `crate::x…` paths, and `super::…` chains that climb to the crate root.
/// `module` is the file's module path (`[integrator, vertex]`).
fn references(code: &str, module: &[String]) -> Vec<(String, usize)> {
    let toks = tokens(code);
    let mut found = Vec::new();
    // Inline modules (`mod tests {`) with the brace depth they opened at.
    let mut inline: Vec<(String, usize)> = Vec::new();
    let mut depth = 0usize;
    let mut i = 0;
    while i < toks.len() {
        // Test code: skip a `#[cfg(test)] mod name { … }` block whole.
        if let Some(m) = after_cfg_test(&toks, i).and_then(|j| mod_keyword(&toks, j))
            && toks.get(m + 2).map(|t| &t.0) == Some(&Token::Open)
        {
            let mut open = 0;
            i = m + 2;
            while i < toks.len() {
                match toks[i].0 {
                    Token::Open => open += 1,
                    Token::Close => {
                        open -= 1;
                        if open == 0 {
                            break;
                        }
                    }
                    _ => {}
                }
                i += 1;
            }
            i += 1;
            continue;
        }
        let (tok, line) = &toks[i];
        match tok {
            Token::Open => depth += 1,
            Token::Close => {
                depth = depth.saturating_sub(1);
                if inline.last().is_some_and(|&(_, d)| d == depth) {
                    inline.pop();
                }
            }
            Token::Ident(kw) if kw == "mod" => {
                if let (Some((Token::Ident(name), _)), Some((Token::Open, _))) =
                    (toks.get(i + 1), toks.get(i + 2))
                {
                    inline.push((name.clone(), depth));
                    depth += 1;
                    i += 3;
                    continue;
                }
            }
            Token::Ident(kw)
                if kw == "crate" && toks.get(i + 1).map(|t| &t.0) == Some(&Token::Path) =>
            {
                for name in names_at_root(&toks, i + 2) {
                    found.push((name, *line));
                }
            }
            Token::Ident(kw)
                if kw == "super"
                    // The start of a chain, not its continuation.
                    && !(i >= 1 && toks[i - 1].0 == Token::Path) =>
            {
                let mut climbs = 0;
                let mut j = i;
                while matches!(&toks.get(j).map(|t| &t.0), Some(Token::Ident(s)) if s == "super")
                    && toks.get(j + 1).map(|t| &t.0) == Some(&Token::Path)
                {
                    climbs += 1;
                    j += 2;
                }
                let here = module.len() + inline.len();
                if climbs >= here {
                    for name in names_at_root(&toks, j) {
                        found.push((name, *line));
                    }
                }
                i = j.max(i + 1);
                continue;
            }
            _ => {}
        }
        i += 1;
    }
    found
}

/// The violations of `layers` in the file `path` (module path `module`).
fn violations(
    layers: &BTreeMap<String, u32>,
    path: &Path,
    module: &[String],
    text: &str,
) -> Vec<String> {
    let Some(own) = module.first() else {
        return Vec::new(); // lib.rs declares the modules
    };
    let Some(&own_layer) = layers.get(own) else {
        return vec![format!(
            "{}: module `{own}` has no layer in lib.rs's `# Layers` block",
            path.display()
        )];
    };
    let mut out = Vec::new();
    for (name, line) in references(&strip_comments_and_strings(text), module) {
        if &name == own {
            continue;
        }
        match layers.get(&name) {
            Some(&layer) if layer < own_layer => {}
            Some(&layer) => out.push(format!(
                "{}:{line}: `{own}` (layer {own_layer}) uses `{name}` (layer {layer}): \
                 arrows must point down",
                path.display()
            )),
            None => out.push(format!(
                "{}:{line}: `{own}` uses `crate::{name}`, which is not a module with a layer \
                 (a glob or an item of the crate root?)",
                path.display()
            )),
        }
    }
    out
}

#[test]
fn every_module_uses_only_lower_layers() {
    let lib_rs = std::fs::read_to_string(src().join("lib.rs")).unwrap();
    let layers = documented_layers(&lib_rs);
    let mut declared = declared_modules(&lib_rs);
    declared.sort();
    let listed: Vec<String> = layers.keys().cloned().collect();
    assert_eq!(
        declared, listed,
        "the modules lib.rs declares and the ones its `# Layers` block lists differ"
    );
    let mut files = Vec::new();
    module_files(&src(), &[], &mut files);
    assert!(files.len() > 40, "found only {} source files", files.len());
    let mut problems = Vec::new();
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let texts: Vec<String> = files
        .iter()
        .map(|(path, _)| std::fs::read_to_string(path).unwrap())
        .collect();
    for ((path, module), text) in files.iter().zip(&texts) {
        let shown = path.strip_prefix(root).unwrap_or(path);
        problems.extend(violations(&layers, shown, module, text));
    }
    assert!(
        problems.is_empty(),
        "imports against the layers of lib.rs:\n{}",
        problems.join("\n")
    );
}

/// The checker itself: every form of an upward import is caught, and what is
/// not an import (comments, strings, lifetimes, paths inside the module, a
/// lower module) is not.
#[test]
fn the_checker_finds_upward_imports_in_every_form() {
    let layers: BTreeMap<String, u32> = [("math", 0), ("scene", 5), ("render", 7)]
        .map(|(m, l)| (m.to_string(), l))
        .into_iter()
        .collect();
    let check = |module: &[&str], text: &str| {
        let module: Vec<String> = module.iter().map(|s| s.to_string()).collect();
        violations(&layers, Path::new("x.rs"), &module, text)
    };
    let bad = [
        (&["scene"][..], "use crate::render::RenderOptions;"),
        (
            &["scene"],
            "fn f() -> crate::render::RenderOptions { todo!() }",
        ),
        (&["scene"], "use crate::{math::Vec3A, render::render};"),
        (
            &["scene", "load"],
            "use super::super::render::RenderOptions;",
        ),
        (&["scene"], "mod helpers { use super::super::render::*; }"),
        (
            &["scene"],
            "#[cfg(test)] mod tests { } use crate::render::render;",
        ),
        (&["scene"], "use super::{render};"),
        (&["scene"], "use crate::*;"),
        (&["render"], "use crate::nowhere::Thing;"),
    ];
    for (module, text) in bad {
        assert_eq!(check(module, text).len(), 1, "{module:?}: {text}");
    }
    let good = [
        (
            &["scene"][..],
            "use crate::math::Vec3A; use crate::scene::load::parse;",
        ),
        (
            &["scene"],
            "// use crate::render::RenderOptions;\n/// [`crate::render`]",
        ),
        (&["scene"], "/* crate::render:: /* nested */ */ fn f() {}"),
        (
            &["scene"],
            r##"const S: &str = "crate::render::x"; const R: &str = r#"crate::render"#;"##,
        ),
        (
            &["scene"],
            "fn f<'a>(x: &'a str) -> char { let _ = '\"'; 'x' }",
        ),
        (
            &["scene", "load"],
            "use super::builtin; mod tests { use super::super::Scene; }",
        ),
        (&["scene"], "mod tests { use super::*; }"),
        (
            &["scene"],
            "#[cfg(test)]\nmod tests { use crate::render::render; fn f() { {} } }",
        ),
        (
            &["scene"],
            "#[cfg(test)] pub(crate) mod t { use crate::{integrator, render}; }",
        ),
        (
            &["render"],
            "use crate::{math, scene::{Scene, RenderSettings}};",
        ),
    ];
    for (module, text) in good {
        assert_eq!(
            check(module, text),
            Vec::<String>::new(),
            "{module:?}: {text}"
        );
    }
}
