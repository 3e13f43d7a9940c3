//! What the exercises say is checked against what exists.
//!
//! In every run (files students do not edit): the registry's slides exist in
//! both decks (read now, from `slides/{en,bg}/*.md`), the hints name only
//! existing API, the instructor guide lists every exercise.
//!
//! Only with `--features solutions` (the instructor's run and CI): the stubs
//! in `exercises/src/` are pristine (a `todo!()` body per function, their
//! `// TODO` lines), open with their number, cite exactly the registry's
//! slides and name only existing API. A student who replaces a stub's text
//! must not fail `cargo test`, so these never run for students.

use grading::texts::{
    Api, cited_slides, code_spans, comment_text, deck_titles, missing_slides, repo_root,
};

fn decks() -> (Vec<String>, Vec<String>) {
    let root = repo_root();
    let read = |lang: &str| {
        deck_titles(&root.join("slides").join(lang))
            .unwrap_or_else(|e| panic!("cannot read the {lang} deck: {e}"))
    };
    (read("en"), read("bg"))
}

#[test]
fn every_slide_an_exercise_cites_is_in_both_decks() {
    let (en, bg) = decks();
    assert!(
        en.len() > 20 && bg.len() == en.len(),
        "{} / {}",
        en.len(),
        bg.len()
    );
    let missing = missing_slides(&exercises::registry(), &en, &bg);
    assert!(
        missing.is_empty(),
        "exercises/info.toml cites slides the decks lack:\n{}",
        missing.join("\n")
    );
}

#[test]
fn a_slide_missing_from_the_deck_is_reported() {
    let (en, bg) = decks();
    let mut reg = exercises::registry();
    reg[10].slides.push("Path tracing (II)".into());
    reg[10].slides_bg.push("Path tracing (II)".into());
    let missing = missing_slides(&reg, &en, &bg);
    assert_eq!(missing.len(), 2, "{missing:?}");
    assert!(missing[0].contains("ex11_path_tracing") && missing[0].contains("Path tracing (II)"));
}

#[test]
fn hints_name_only_existing_api() {
    let api = Api::of_repository().expect("sources");
    for e in exercises::registry() {
        for h in &e.hints {
            let unknown = api.unknown_names(h, false);
            assert!(
                unknown.is_empty(),
                "{}: hint {h:?} names {unknown:?}",
                e.name
            );
        }
    }
}

#[test]
fn the_instructor_guide_lists_every_exercise() {
    let guide = std::fs::read_to_string(exercises::crate_dir().join("README.md")).expect("README");
    for e in exercises::registry() {
        assert!(
            guide.contains(&format!("`{}.rs`", e.name)),
            "exercises/README.md lists {}",
            e.name
        );
    }
}

/// The checks of a stub's text, one problem per line.
fn stub_problems(e: &exercises::Exercise, text: &str, api: &Api) -> Vec<String> {
    let mut out = Vec::new();
    let number = e.number().unwrap_or(0);
    if !text.starts_with(&format!("//! Exercise {number} — ")) {
        out.push(format!(
            "{}: opens with \"//! Exercise {number} — \"",
            e.file
        ));
    }
    let (en, bg) = cited_slides(text);
    if en != e.slides || bg != e.slides_bg {
        out.push(format!(
            "{}: cites the slides {en:?} / {bg:?}, the registry {:?} / {:?}",
            e.file, e.slides, e.slides_bg
        ));
    }
    for span in code_spans(&comment_text(text)) {
        let unknown = api.unknown_names(&span, true);
        if !unknown.is_empty() {
            out.push(format!(
                "{}: `{span}` names {unknown:?}, which the sources lack",
                e.file
            ));
        }
    }
    let fns = text.matches("\npub fn ").count();
    let todos = text.matches("    todo!()\n").count();
    if fns == 0 || todos != fns {
        out.push(format!(
            "{}: {fns} functions but {todos} todo!() bodies",
            e.file
        ));
    }
    if !text.contains("// TODO") {
        out.push(format!("{}: no `// TODO` line", e.file));
    }
    out
}

/// The stub checks are the instructor's, and each one bites: a pristine
/// stub (built here from the registry, so that this test needs no stub
/// file) has no problem, and each single change a student or an old text
/// makes to it is reported by the check that names it — a solved body (no
/// `todo!()` left), one of two functions solved, the `// TODO` line gone,
/// another opening, another slide, an API name that does not exist.
#[test]
fn each_stub_check_catches_its_own_change() {
    let api = Api::of_repository().expect("sources");
    let reg = exercises::registry();
    let e = &reg[2];
    assert_eq!(e.number(), Some(3), "{}", e.name);
    let cites: Vec<String> = e
        .slides
        .iter()
        .zip(&e.slides_bg)
        .map(|(en, bg)| format!("\"{en}\" (\"{bg}\")"))
        .collect();
    let pristine = format!(
        "//! Exercise 3 — the Lambertian BRDF.\n//!\n//! Slides: {}.\n//!\n\
         //! Receives the albedo (its colour is `Texture::eval`).\n\n\
         pub fn f_r() -> f32 {{\n    // TODO: the constant.\n    todo!()\n}}\n",
        cites.join(", ")
    );
    assert_eq!(
        stub_problems(e, &pristine, &api),
        Vec::<String>::new(),
        "a pristine stub has problems:\n{pristine}"
    );
    let only = |text: String, expected: &str| {
        let problems = stub_problems(e, &text, &api);
        assert!(
            problems.len() == 1 && problems[0].contains(expected),
            "expected only {expected:?}, got {problems:?} for:\n{text}"
        );
    };
    only(
        pristine.replace("    todo!()\n", "    1.0 / std::f32::consts::PI\n"),
        "1 functions but 0 todo!() bodies",
    );
    only(
        pristine.clone() + "\npub fn g() -> f32 {\n    // TODO: another.\n    0.0\n}\n",
        "2 functions but 1 todo!() bodies",
    );
    only(
        pristine.replace("    // TODO: the constant.\n", ""),
        "no `// TODO` line",
    );
    only(
        pristine.replace("//! Exercise 3 — ", "//! The exercise — "),
        "opens with \"//! Exercise 3 — \"",
    );
    only(
        pristine.replace(&format!("\"{}\"", e.slides[0]), "\"Path tracing (II)\""),
        "cites the slides",
    );
    only(
        pristine.replace("`Texture::eval`", "`Texture::sample`"),
        "`Texture::sample` names [\"Texture::sample\"]",
    );
}

#[cfg(feature = "solutions")]
#[test]
fn stubs_are_pristine_and_their_texts_true() {
    let api = Api::of_repository().expect("sources");
    let mut problems = Vec::new();
    for e in exercises::registry() {
        let text =
            std::fs::read_to_string(exercises::crate_dir().join(&e.file)).expect("exercise file");
        problems.extend(stub_problems(&e, &text, &api));
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}
