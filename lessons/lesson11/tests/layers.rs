//! Arrows point down inside `lesson11`: the layers listed in the crate doc of
//! `src/lib.rs` hold for every source file. The sources are read as text:
//! each `crate::…`, `super::…` and `self::…` path names the file it imports.
//! Test modules (`#[cfg(test)]` to the end of a file) are left out: a test may
//! look at the whole program.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// A source file: its path under `src/`, its module path and its code.
struct Source {
    /// `chapters/c05_path.rs`, always with forward slashes.
    rel: String,
    /// `["chapters", "c05_path"]`; empty for the crate root.
    module: Vec<String>,
    /// The code without comments and without its test module.
    code: String,
}

impl Source {
    fn new(rel: &str, text: &str) -> Source {
        let mut module: Vec<String> = rel
            .trim_end_matches(".rs")
            .split('/')
            .map(String::from)
            .collect();
        if rel == "main.rs" || rel == "lib.rs" || module.last().is_some_and(|m| m == "mod") {
            module.pop();
        }
        let code = text
            .split("#[cfg(test)]")
            .next()
            .unwrap_or_default()
            .lines()
            .map(|line| line.split("//").next().unwrap_or_default())
            .collect::<Vec<_>>()
            .join("\n");
        Source {
            rel: rel.to_string(),
            module,
            code,
        }
    }
}

/// Every `.rs` file under `dir`, as `Source`s relative to `root`.
fn read_sources(root: &Path, dir: &Path, out: &mut Vec<Source>) {
    let mut entries: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            read_sources(root, &path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            let rel = path
                .strip_prefix(root)
                .unwrap()
                .to_string_lossy()
                .replace('\\', "/");
            out.push(Source::new(&rel, &std::fs::read_to_string(&path).unwrap()));
        }
    }
}

/// The layers, top first, from the `text` block under "# Layout" in the crate
/// doc: each line starts with its patterns (`tour.rs`, `commands/`,
/// `chapters/c*.rs`), then says what they are.
fn layers(main_rs: &str) -> Vec<Vec<String>> {
    let doc: Vec<&str> = main_rs
        .lines()
        .take_while(|l| l.starts_with("//!"))
        .map(|l| l.trim_start_matches("//!").trim())
        .collect();
    let layout = doc
        .iter()
        .position(|l| *l == "# Layout")
        .expect("a # Layout section");
    let start = layout
        + doc[layout..]
            .iter()
            .position(|l| *l == "```text")
            .expect("a text block")
        + 1;
    doc[start..]
        .iter()
        .take_while(|l| **l != "```")
        .map(|l| {
            l.split_whitespace()
                .take_while(|w| w.ends_with(".rs") || w.ends_with('/'))
                .map(String::from)
                .collect::<Vec<_>>()
        })
        .inspect(|patterns| assert!(!patterns.is_empty(), "a layer line without files"))
        .collect()
}

/// Whether `pattern` (a file, a folder ending in `/`, or a file name with one
/// `*` that does not cross folders) covers the file `rel`.
fn covers(pattern: &str, rel: &str) -> bool {
    if pattern.ends_with('/') {
        rel.starts_with(pattern)
    } else if let Some((head, tail)) = pattern.split_once('*') {
        rel.len() >= head.len() + tail.len()
            && rel.starts_with(head)
            && rel.ends_with(tail)
            && !rel[head.len()..rel.len() - tail.len()].contains('/')
    } else {
        rel == pattern
    }
}

/// The submodules `code` declares (`mod x;`) and the paths after `crate::`,
/// `super::` and `self::`, as module paths from the crate root
/// (`use crate::{a::X, b}` gives `a::X` and `b`).
fn imported_paths(code: &str, module: &[String]) -> Vec<Vec<String>> {
    let mut paths = Vec::new();
    for declared in code.split("mod ").skip(1) {
        if let Some((name, _)) = declared.split_once(';') {
            if !name.is_empty() && name.chars().all(|c| c.is_alphanumeric() || c == '_') {
                paths.push(module.iter().cloned().chain([name.to_string()]).collect());
            }
        }
    }
    let bytes = code.as_bytes();
    let is_ident = |c: u8| c.is_ascii_alphanumeric() || c == b'_';
    for (start, _) in code.char_indices() {
        if start > 0 && (is_ident(bytes[start - 1]) || bytes[start - 1] == b':') {
            continue;
        }
        let rest = &code[start..];
        let mut base: Vec<String> = if rest.starts_with("crate::") {
            Vec::new()
        } else if rest.starts_with("super::") || rest.starts_with("self::") {
            module.to_vec()
        } else {
            continue;
        };
        let mut rest = rest;
        loop {
            if let Some(r) = rest.strip_prefix("crate::") {
                rest = r;
            } else if let Some(r) = rest.strip_prefix("super::") {
                base.pop();
                rest = r;
            } else if let Some(r) = rest.strip_prefix("self::") {
                rest = r;
            } else {
                break;
            }
        }
        read_tree(rest, base, &mut paths);
    }
    paths
}

/// Reads `a::b::{c, d::e}` at the start of `s`, appending each full path.
fn read_tree(s: &str, prefix: Vec<String>, out: &mut Vec<Vec<String>>) {
    let s = s.trim_start();
    if let Some(group) = s.strip_prefix('{') {
        let mut depth = 0;
        let mut item = 0;
        for (i, c) in group.char_indices() {
            match c {
                '{' => depth += 1,
                '}' if depth == 0 => {
                    read_tree(&group[item..i], prefix.clone(), out);
                    return;
                }
                '}' => depth -= 1,
                ',' if depth == 0 => {
                    read_tree(&group[item..i], prefix.clone(), out);
                    item = i + 1;
                }
                _ => {}
            }
        }
        return;
    }
    let end = s
        .find(|c: char| !(c.is_alphanumeric() || c == '_'))
        .unwrap_or(s.len());
    let mut path = prefix;
    if end > 0 {
        path.push(s[..end].to_string());
    }
    match s[end..].strip_prefix("::") {
        Some(rest) => read_tree(rest, path, out),
        None => out.push(path),
    }
}

/// What is wrong with the imports of `sources` under `layers`: files on no
/// line or on two, arrows that run up or across a line, and circles.
fn violations(layers: &[Vec<String>], sources: &[Source]) -> Vec<String> {
    let mut wrong = Vec::new();
    // The line and the pattern of every file.
    let mut place: BTreeMap<&str, (usize, &str)> = BTreeMap::new();
    for s in sources {
        let found: Vec<(usize, &str)> = layers
            .iter()
            .enumerate()
            .flat_map(|(i, line)| line.iter().map(move |p| (i, p.as_str())))
            .filter(|(_, p)| covers(p, &s.rel))
            .collect();
        match found[..] {
            [one] => {
                place.insert(&s.rel, one);
            }
            [] => wrong.push(format!(
                "{} is on no line of the layers in src/lib.rs",
                s.rel
            )),
            _ => wrong.push(format!("{} is on more than one line of the layers", s.rel)),
        }
    }
    let by_module: BTreeMap<&[String], &str> = sources
        .iter()
        .map(|s| (s.module.as_slice(), s.rel.as_str()))
        .collect();
    // The imports, file to file.
    let mut edges: BTreeMap<&str, BTreeSet<&str>> = BTreeMap::new();
    for s in sources {
        for path in imported_paths(&s.code, &s.module) {
            // The longest prefix of the path that is a module names the file.
            let Some(target) = (0..=path.len())
                .rev()
                .find_map(|n| by_module.get(&path[..n]).copied())
            else {
                continue;
            };
            if target == s.rel {
                continue;
            }
            edges.entry(&s.rel).or_default().insert(target);
        }
    }
    for (&from, targets) in &edges {
        let module = &sources.iter().find(|s| s.rel == from).unwrap().module;
        for &to in targets {
            let to_module = &sources.iter().find(|s| s.rel == to).unwrap().module;
            if to_module.starts_with(module) {
                continue; // a module uses its own submodule
            }
            let (Some(&(a, pa)), Some(&(b, pb))) = (place.get(from), place.get(to)) else {
                continue;
            };
            if b < a {
                wrong.push(format!(
                    "{from} imports {to}, which is above it (line {} of the layers, {from} is on line {})",
                    b + 1,
                    a + 1
                ));
            } else if b == a && !(pa == pb && pa.ends_with('/')) {
                wrong.push(format!(
                    "{from} imports {to} on the same line of the layers (only files of one folder may)"
                ));
            }
        }
    }
    // Circles: a depth-first search that meets a file still on its path.
    fn visit<'a>(
        file: &'a str,
        edges: &BTreeMap<&'a str, BTreeSet<&'a str>>,
        path: &mut Vec<&'a str>,
        done: &mut BTreeSet<&'a str>,
        wrong: &mut Vec<String>,
    ) {
        if let Some(i) = path.iter().position(|f| *f == file) {
            let mut circle = path[i..].to_vec();
            circle.push(file);
            wrong.push(format!("a circle of imports: {}", circle.join(" -> ")));
            return;
        }
        if !done.insert(file) {
            return;
        }
        path.push(file);
        for &next in edges.get(file).into_iter().flatten() {
            visit(next, edges, path, done, wrong);
        }
        path.pop();
    }
    let mut done = BTreeSet::new();
    for s in sources {
        visit(&s.rel, &edges, &mut Vec::new(), &mut done, &mut wrong);
    }
    wrong
}

#[test]
fn every_file_imports_only_files_below_it_in_the_documented_order() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let lib_rs = std::fs::read_to_string(src.join("lib.rs")).unwrap();
    let layers = layers(&lib_rs);
    assert!(layers.len() >= 5, "the layers in lib.rs: {layers:?}");
    let mut sources = Vec::new();
    read_sources(&src, &src, &mut sources);
    assert!(sources.len() >= 20, "read only {} files", sources.len());
    let wrong = violations(&layers, &sources);
    assert!(
        wrong.is_empty(),
        "the layers of src/lib.rs do not hold:\n{}",
        wrong.join("\n")
    );
}

#[test]
fn every_chapter_file_is_listed_once_in_lecture_order() {
    let chapters = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/chapters");
    let mut files: Vec<String> = std::fs::read_dir(&chapters)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|f| f != "mod.rs")
        .map(|f| f.trim_end_matches(".rs").to_string())
        .collect();
    files.sort();
    let list = std::fs::read_to_string(chapters.join("mod.rs")).unwrap();
    let listed: Vec<String> = list
        .split("chapters![")
        .nth(1)
        .expect("the chapters![…] list")
        .split(']')
        .next()
        .unwrap()
        .split(',')
        .map(|c| c.trim().to_string())
        .filter(|c| !c.is_empty())
        .collect();
    assert_eq!(
        listed, files,
        "chapters/mod.rs lists every chapter file, in file-name order"
    );
}

/// The check itself can fail: a page that imports the tour, a chapter that
/// imports another, two commands that import each other, a file on no line.
#[test]
fn upward_sideways_and_circular_imports_are_reported() {
    let layers = layers(
        "//! # Layout\n//!\n//! ```text\n//! main.rs  top\n//! commands/  commands\n\
         //! chapters/c*.rs  chapters\n//! tour.rs  context\n//! page/ plots/  page\n//! ```\n",
    );
    assert_eq!(layers.len(), 5);
    let files = [
        ("main.rs", "mod tour; use crate::commands::Command;"),
        ("commands/mod.rs", "mod a; mod b; use self::a::A;"),
        ("commands/a.rs", "use super::b::B; use crate::tour::Tour;"),
        ("commands/b.rs", "use crate::commands::a::A;"),
        (
            "chapters/c01_one.rs",
            "use crate::{page::Section, tour::Tour};",
        ),
        (
            "chapters/c02_two.rs",
            "use crate::chapters::c01_one::CHAPTER;",
        ),
        (
            "tour.rs",
            "use crate::page::Section; // crate::main::Cli in a comment",
        ),
        ("page/mod.rs", "pub fn f() { crate::tour::Tour::new(); }"),
        ("plots/mod.rs", "use crate::page::Section;"),
        ("stray.rs", ""),
        (
            "page/figure.rs",
            "#[cfg(test)]\nmod tests { use crate::tour::Tour; }",
        ),
    ];
    let sources: Vec<Source> = files
        .iter()
        .map(|(rel, code)| Source::new(rel, code))
        .collect();
    let wrong = violations(&layers, &sources);
    let expect = [
        "stray.rs is on no line",
        "chapters/c02_two.rs imports chapters/c01_one.rs on the same line",
        "page/mod.rs imports tour.rs, which is above it",
        "plots/mod.rs imports page/mod.rs on the same line",
        "a circle of imports: commands/a.rs -> commands/b.rs -> commands/a.rs",
        "a circle of imports: tour.rs -> page/mod.rs -> tour.rs",
    ];
    for e in expect {
        assert!(
            wrong.iter().any(|w| w.starts_with(e)),
            "missing `{e}` in {wrong:#?}"
        );
    }
    assert_eq!(wrong.len(), expect.len(), "{wrong:#?}");
}

/// The libraries of the renderer, the program and the grader are built with
/// `test = false` (their unit tests are in `tests/unit/`, so that a cold `cargo
/// test` compiles each once): a `#[test]` left in their sources would never run.
#[test]
fn no_test_is_left_in_a_library_that_cargo_does_not_test() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let mut found = Vec::new();
    for (crate_dir, manifest) in [
        ("raytracer/src", "raytracer/Cargo.toml"),
        ("lessons/lesson11/src", "lessons/lesson11/Cargo.toml"),
        ("tests/src", "tests/Cargo.toml"),
    ] {
        let toml = std::fs::read_to_string(root.join(manifest)).unwrap();
        assert!(
            toml.contains("[lib]") && toml.contains("test = false"),
            "{manifest} no longer says `test = false`: then this check is not needed there"
        );
        let src = root.join(crate_dir);
        let mut sources = Vec::new();
        read_sources(&src, &src, &mut sources);
        assert!(!sources.is_empty(), "no sources under {crate_dir}");
        for s in &sources {
            let text = std::fs::read_to_string(src.join(&s.rel)).unwrap();
            for (n, line) in text.lines().enumerate() {
                let code = line.split("//").next().unwrap_or_default();
                if code.contains("#[cfg(test)]") || code.contains("#[test]") {
                    found.push(format!("{crate_dir}/{}:{}: {}", s.rel, n + 1, line.trim()));
                }
            }
        }
    }
    assert!(
        found.is_empty(),
        "tests in a library that `cargo test` does not build for tests (move them to its tests/unit/):\n{}",
        found.join("\n")
    );
}
