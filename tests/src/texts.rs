//! What the exercise texts say, checked against what exists: the slides they
//! cite (the decks `slides/{en,bg}/*.md`, read when the test runs, so the
//! check tells the truth about whatever decks are checked out) and the API
//! names they mention (the sources of `raytracer` and of `exercises::plug`,
//! also read when the test runs).
//!
//! The stubs in `exercises/src/` are the student's to edit, so the checks of
//! their text run only in the instructor's run (`--features solutions`,
//! `tests/tests/check_texts.rs`); the registry (`info.toml`) and the decks
//! are checked in every run.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

use exercises::Exercise;

/// The repository's root (the parent of the `exercises` crate).
pub fn repo_root() -> PathBuf {
    exercises::crate_dir()
        .parent()
        .map_or_else(|| PathBuf::from(".."), Path::to_path_buf)
}

/// The slide titles of one deck: every `# ` line of its `*.md` files,
/// outside code fences, in file order.
pub fn deck_titles(dir: &Path) -> std::io::Result<Vec<String>> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "md"))
        .collect();
    files.sort();
    let mut titles = Vec::new();
    for f in files {
        let mut fenced = false;
        for line in std::fs::read_to_string(&f)?.lines() {
            if line.trim_start().starts_with("```") {
                fenced = !fenced;
            } else if !fenced && let Some(t) = line.strip_prefix("# ") {
                titles.push(t.trim().to_string());
            }
        }
    }
    Ok(titles)
}

/// Every slide an exercise of the registry cites that the decks lack, one
/// line each (empty: all found).
pub fn missing_slides(reg: &[Exercise], en: &[String], bg: &[String]) -> Vec<String> {
    let mut out = Vec::new();
    for e in reg {
        for t in &e.slides {
            if !en.contains(t) {
                out.push(format!("{}: no slide \"{t}\" in slides/en", e.name));
            }
        }
        for t in &e.slides_bg {
            if !bg.contains(t) {
                out.push(format!("{}: no slide \"{t}\" in slides/bg", e.name));
            }
        }
    }
    out
}

/// The text of the comments of a Rust file (`//!`, `///`, `//` lines),
/// without the comment markers, code fences (formulas) left out.
pub fn comment_text(source: &str) -> String {
    let mut out = String::new();
    let mut fenced = false;
    for line in source.lines() {
        let t = line.trim_start();
        let Some(rest) = t
            .strip_prefix("//!")
            .or_else(|| t.strip_prefix("///"))
            .or_else(|| t.strip_prefix("//"))
        else {
            continue;
        };
        if rest.trim_start().starts_with("```") {
            fenced = !fenced;
            continue;
        }
        if !fenced {
            out.push_str(rest);
            out.push('\n');
        }
    }
    out
}

/// The slides a stub cites: the quoted titles of its `Slides:` paragraph,
/// English and Bulgarian alternating (`"Title" ("Заглавие"), …`).
pub fn cited_slides(source: &str) -> (Vec<String>, Vec<String>) {
    let text = comment_text(source);
    let Some(start) = text.find("Slides:") else {
        return (Vec::new(), Vec::new());
    };
    let paragraph = text[start..].split("\n\n").next().unwrap_or_default();
    let quoted: Vec<String> = paragraph
        .split('"')
        .skip(1)
        .step_by(2)
        .map(|s| s.split_whitespace().collect::<Vec<_>>().join(" "))
        .collect();
    let en = quoted.iter().step_by(2).cloned().collect();
    let bg = quoted.iter().skip(1).step_by(2).cloned().collect();
    (en, bg)
}

/// glam's vector types (re-exported by `raytracer::math`) and the members
/// the texts may use; glam is not ours to scan.
const GLAM_TYPES: &[&str] = &["Vec2", "Vec3", "Vec3A", "UVec2", "Color"];
const GLAM_MEMBERS: &[&str] = &[
    "x",
    "y",
    "z",
    "ZERO",
    "ONE",
    "X",
    "Y",
    "Z",
    "new",
    "splat",
    "dot",
    "cross",
    "length",
    "length_squared",
    "normalize",
    "abs",
    "lerp",
    "max_element",
    "min_element",
    "signum",
];
/// Rust's own names that texts may use.
const STD_NAMES: &[&str] = &["Some", "None", "Option", "Ok", "Err", "Result", "Vec"];

/// An index of the names the sources define.
#[derive(Debug, Default)]
pub struct Api {
    /// Types (struct, enum, type alias, trait) and their members (methods,
    /// associated constants, fields, variants).
    pub types: BTreeMap<String, BTreeSet<String>>,
    /// Every `fn` name, wherever defined.
    pub fns: BTreeSet<String>,
    /// Every `pub` field name, of any struct.
    pub fields: BTreeSet<String>,
    /// Modules (file and folder names, `mod` items).
    pub modules: BTreeSet<String>,
}

impl Api {
    /// Scans `raytracer/src` and `exercises/src/plug/` of the repository.
    pub fn of_repository() -> std::io::Result<Api> {
        let root = repo_root();
        let mut api = Api::default();
        let mut files = Vec::new();
        collect_rs(&root.join("raytracer/src"), &mut files)?;
        collect_rs(&root.join("exercises/src/plug"), &mut files)?;
        files.push(root.join("exercises/src/registry.rs"));
        for f in files {
            if let Some(stem) = f.file_stem() {
                api.modules.insert(stem.to_string_lossy().into_owned());
            }
            if let Some(dir) = f.parent().and_then(Path::file_name) {
                api.modules.insert(dir.to_string_lossy().into_owned());
            }
            api.scan(&std::fs::read_to_string(&f)?);
        }
        api.modules
            .extend(["raytracer", "exercises", "plug"].map(String::from));
        Ok(api)
    }

    /// Adds the items of one source file.
    pub fn scan(&mut self, source: &str) {
        let code = strip_comments_and_strings(source);
        let bytes = code.as_bytes();
        for (i, _) in code.match_indices("fn ") {
            if i > 0 && is_ident(bytes[i - 1] as char) {
                continue;
            }
            self.fns.insert(ident_at(&code[i + 3..]));
        }
        for (i, _) in code.match_indices("mod ") {
            if i == 0 || !is_ident(bytes[i - 1] as char) {
                self.modules.insert(ident_at(&code[i + 4..]));
            }
        }
        for kw in ["struct ", "enum ", "type ", "trait "] {
            for (i, _) in code.match_indices(kw) {
                if i > 0 && is_ident(bytes[i - 1] as char) {
                    continue;
                }
                let name = ident_at(&code[i + kw.len()..]);
                if name.is_empty() {
                    continue;
                }
                let members = self.types.entry(name).or_default();
                if kw == "struct " || kw == "enum " {
                    if let Some(body) = block_after(&code, i) {
                        for m in item_members(body, kw == "enum ") {
                            if kw == "struct " {
                                self.fields.insert(m.clone());
                            }
                            members.insert(m);
                        }
                    }
                }
            }
        }
        for (i, _) in code.match_indices("impl") {
            if (i > 0 && is_ident(bytes[i - 1] as char))
                || code[i + 4..].starts_with(|c: char| is_ident(c))
            {
                continue;
            }
            let Some(open) = code[i..].find('{').map(|o| i + o) else {
                continue;
            };
            let header = &code[i + 4..open];
            let target = header.rsplit(" for ").next().unwrap_or(header);
            let target = strip_generics(target);
            let name = target
                .trim()
                .rsplit("::")
                .next()
                .unwrap_or_default()
                .trim()
                .to_string();
            if name.is_empty() || !name.starts_with(|c: char| c.is_ascii_uppercase()) {
                continue;
            }
            if let Some(body) = block_after(&code, i) {
                let members = self.types.entry(name).or_default();
                for (j, _) in body.match_indices("fn ") {
                    if j == 0 || !is_ident(body.as_bytes()[j - 1] as char) {
                        members.insert(ident_at(&body[j + 3..]));
                    }
                }
                for (j, _) in body.match_indices("const ") {
                    if j == 0 || !is_ident(body.as_bytes()[j - 1] as char) {
                        members.insert(ident_at(&body[j + 6..]));
                    }
                }
            }
        }
    }

    fn has_type(&self, t: &str) -> bool {
        self.types.contains_key(t) || GLAM_TYPES.contains(&t) || STD_NAMES.contains(&t)
    }

    fn has_member(&self, t: &str, m: &str) -> bool {
        if GLAM_TYPES.contains(&t) && GLAM_MEMBERS.contains(&m) {
            return true;
        }
        self.types.get(t).is_some_and(|ms| ms.contains(m))
    }

    /// Every API mention of `code` that names nothing in the sources:
    /// `Type::member`, `module::item` and `.method(` always; with `spans`
    /// (the text of code spans, not prose) also a bare `Type` and `.field`.
    pub fn unknown_names(&self, code: &str, spans: bool) -> Vec<String> {
        let mut out = Vec::new();
        let chars: Vec<char> = code.chars().collect();
        let mut i = 0;
        while i < chars.len() {
            let c = chars[i];
            let after_dot = i > 0 && chars[i - 1] == '.';
            let starts = is_ident(c)
                && !c.is_ascii_digit()
                && (i == 0 || !(is_ident(chars[i - 1]) || chars[i - 1] == ':'));
            if !starts {
                i += 1;
                continue;
            }
            // A path a::b::c.
            let mut segments = Vec::new();
            let mut j = i;
            loop {
                let s = j;
                while j < chars.len() && is_ident(chars[j]) {
                    j += 1;
                }
                segments.push(chars[s..j].iter().collect::<String>());
                if j + 2 < chars.len()
                    && chars[j] == ':'
                    && chars[j + 1] == ':'
                    && is_ident(chars[j + 2])
                {
                    j += 2;
                } else {
                    break;
                }
            }
            let call = j < chars.len() && chars[j] == '(';
            if after_dot {
                let name = &segments[0];
                // `x.0`, numbers, and text like "e.g." are not names.
                let known = self.fns.contains(name) || GLAM_MEMBERS.contains(&name.as_str());
                if call && !known {
                    out.push(format!(".{name}("));
                } else if spans && !call && !known && !self.fields.contains(name) {
                    out.push(format!(".{name}"));
                }
            } else if segments.len() >= 2 {
                let (owner, last) = (&segments[segments.len() - 2], &segments[segments.len() - 1]);
                let ok = if owner.starts_with(|c: char| c.is_ascii_uppercase()) {
                    self.has_type(owner) && self.has_member(owner, last)
                } else {
                    segments[..segments.len() - 1]
                        .iter()
                        .all(|m| self.modules.contains(m))
                        && (self.fns.contains(last)
                            || self.types.contains_key(last)
                            || self.modules.contains(last)
                            || GLAM_TYPES.contains(&last.as_str()))
                };
                if !ok {
                    out.push(segments.join("::"));
                }
            } else if spans {
                let name = &segments[0];
                // CamelCase: a type's name (not `L_e`, `W_e`, `D`).
                let camel = name.starts_with(|c: char| c.is_ascii_uppercase())
                    && name.chars().any(|c| c.is_ascii_lowercase())
                    && !name.contains('_');
                if camel && !self.has_type(name) && !self.is_variant(name) {
                    out.push(name.clone());
                }
            }
            i = j.max(i + 1);
        }
        out
    }

    fn is_variant(&self, name: &str) -> bool {
        self.types.values().any(|ms| ms.contains(name))
    }
}

/// The code spans (between backticks) of a comment text.
pub fn code_spans(text: &str) -> Vec<String> {
    text.split('`')
        .skip(1)
        .step_by(2)
        .map(String::from)
        .collect()
}

/// The text of every `.rs` file under `raytracer/src`, one after another.
///
/// # Panics
/// If the folder cannot be read (a test's helper).
pub fn raytracer_sources() -> String {
    let mut files = Vec::new();
    collect_rs(&repo_root().join("raytracer/src"), &mut files).expect("raytracer/src");
    files
        .iter()
        .map(|f| std::fs::read_to_string(f).unwrap_or_default())
        .collect::<Vec<_>>()
        .join("\n")
}

fn collect_rs(dir: &Path, out: &mut Vec<PathBuf>) -> std::io::Result<()> {
    for entry in std::fs::read_dir(dir)? {
        let p = entry?.path();
        if p.is_dir() {
            collect_rs(&p, out)?;
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
    Ok(())
}

fn is_ident(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

fn ident_at(s: &str) -> String {
    s.trim_start()
        .chars()
        .take_while(|&c| is_ident(c))
        .collect()
}

fn strip_generics(s: &str) -> String {
    let mut depth = 0;
    let mut out = String::new();
    for c in s.chars() {
        match c {
            '<' => depth += 1,
            '>' => depth -= 1,
            _ if depth == 0 => out.push(c),
            _ => {}
        }
    }
    out
}

/// The text between the first `{` after `at` and its matching `}` (`None`
/// for an item that ends with `;` first, like a tuple struct).
fn block_after(code: &str, at: usize) -> Option<&str> {
    let rest = &code[at..];
    let open = rest.find('{')?;
    if rest.find(';').is_some_and(|s| s < open) {
        return None;
    }
    let mut depth = 0;
    for (k, c) in rest[open..].char_indices() {
        match c {
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth == 0 {
                    return Some(&rest[open + 1..open + k]);
                }
            }
            _ => {}
        }
    }
    None
}

/// Field names of a struct body (`name: Type`, any visibility) or variant
/// names of an enum body, at the body's top level.
fn item_members(body: &str, is_enum: bool) -> Vec<String> {
    let mut out = Vec::new();
    let mut depth = 0;
    let mut start = 0;
    let mut pieces = Vec::new();
    for (k, c) in body.char_indices() {
        match c {
            '{' | '(' | '<' | '[' => depth += 1,
            '}' | ')' | '>' | ']' => depth -= 1,
            ',' if depth == 0 => {
                pieces.push(&body[start..k]);
                start = k + 1;
            }
            _ => {}
        }
    }
    pieces.push(&body[start..]);
    for p in pieces {
        // Drop attributes (`#[…]`) and visibility.
        let mut p = p.trim();
        while let Some(rest) = p.strip_prefix("#[") {
            p = rest.split_once(']').map_or("", |(_, r)| r).trim();
        }
        let p = p
            .trim_start_matches("pub(crate)")
            .trim_start_matches("pub")
            .trim();
        let name = ident_at(p);
        if name.is_empty() {
            continue;
        }
        if is_enum || p[name.len()..].trim_start().starts_with(':') {
            out.push(name);
        }
    }
    out
}

/// The source with comments, string and char literals blanked out (their
/// braces would confuse the block matching).
fn strip_comments_and_strings(source: &str) -> String {
    let b: Vec<char> = source.chars().collect();
    let mut out = String::with_capacity(source.len());
    let mut i = 0;
    while i < b.len() {
        let c = b[i];
        let next = b.get(i + 1).copied().unwrap_or('\0');
        if c == '/' && next == '/' {
            while i < b.len() && b[i] != '\n' {
                i += 1;
            }
        } else if c == '/' && next == '*' {
            i += 2;
            while i + 1 < b.len() && !(b[i] == '*' && b[i + 1] == '/') {
                i += 1;
            }
            i += 2;
        } else if c == 'r' && (next == '"' || next == '#') && (i == 0 || !is_ident(b[i - 1])) {
            // A raw string r"…" or r#"…"#.
            let mut j = i + 1;
            let mut hashes = 0;
            while j < b.len() && b[j] == '#' {
                hashes += 1;
                j += 1;
            }
            if j < b.len() && b[j] == '"' {
                j += 1;
                loop {
                    if j >= b.len() {
                        break;
                    }
                    if b[j] == '"' && (0..hashes).all(|h| b.get(j + 1 + h) == Some(&'#')) {
                        j += 1 + hashes;
                        break;
                    }
                    j += 1;
                }
                out.push_str("\"\"");
                i = j;
            } else {
                out.push(c);
                i += 1;
            }
        } else if c == '"' {
            i += 1;
            while i < b.len() && b[i] != '"' {
                if b[i] == '\\' {
                    i += 1;
                }
                i += 1;
            }
            i += 1;
            out.push_str("\"\"");
        } else if c == '\'' && b.get(i + 2) == Some(&'\'') {
            out.push_str("' '");
            i += 3;
        } else if c == '\'' && next == '\\' {
            // An escaped char literal like '\n' or '\''.
            let mut j = i + 2;
            while j < b.len() && b[j] != '\'' {
                j += 1;
            }
            if j + 1 < b.len() && b[j + 1] == '\'' {
                j += 1;
            }
            out.push_str("' '");
            i = j + 1;
        } else {
            out.push(c);
            i += 1;
        }
    }
    out
}
