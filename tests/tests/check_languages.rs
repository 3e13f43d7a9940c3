//! Both languages of the toolkit, checked: every message of the grader
//! exists in English and in Bulgarian with the same placeholders (a missing
//! one is named), every key the grader uses exists, no grader makes a
//! message of English prose outside the tables, and the Bulgarian texts use
//! the glossary's words (`lang/glossary.toml`). With `--features solutions`
//! (the stubs are the student's to edit) every stub carries its task in
//! Bulgarian too. That a Bulgarian failure names the same mistake as the
//! English one is checked on the wrong fixtures, in `check_grader.rs`
//! (`fails_in_both`).

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use grading::messages::{Lang, catalog, keys_in_source, mismatches};
use grading::texts::repo_root;

/// The grader's sources (`tests/src/*.rs`), name and text.
fn grader_sources() -> Vec<(String, String)> {
    sources_in("src")
}

/// The Rust files of `tests/{folder}`, name and text.
fn sources_in(folder: &str) -> Vec<(String, String)> {
    let dir = repo_root().join("tests").join(folder);
    let mut out: Vec<(String, String)> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "rs"))
        .map(|p| {
            let name = p
                .file_name()
                .unwrap_or_default()
                .to_string_lossy()
                .into_owned();
            (name, std::fs::read_to_string(&p).unwrap_or_default())
        })
        .collect();
    out.sort();
    out
}

#[test]
fn messages_exist_in_both_languages() {
    let (en, bg) = (catalog(Lang::En), catalog(Lang::Bg));
    let problems = mismatches(en, bg);
    assert!(
        problems.is_empty(),
        "the messages of the two languages differ:\n{}",
        problems.join("\n")
    );
    let mut used = BTreeSet::new();
    for (file, source) in grader_sources().into_iter().chain(sources_in("tests")) {
        for key in keys_in_source(&source) {
            assert!(
                en.contains_key(&key),
                "tests/src/{file}: message `{key}` is in neither tests/messages/en.toml nor bg.toml"
            );
            used.insert(key);
        }
    }
    let unused: Vec<&String> = en.keys().filter(|k| !used.contains(*k)).collect();
    assert!(unused.is_empty(), "messages no grader uses: {unused:?}");
}

/// Sources whose messages are for the instructor (the checks of the texts
/// and of the messages themselves), not the student.
const INSTRUCTOR_ONLY: &[&str] = &["messages.rs", "texts.rs"];

/// Whether a string literal's text reads as English prose (three words;
/// not a scene file written in the grader, `[camera]\nposition = …`).
fn english_prose(text: &str) -> bool {
    !text.starts_with('[')
        && text.contains(' ')
        && text
            .split(|c: char| !c.is_ascii_alphabetic())
            .filter(|w| w.len() >= 2 && w.chars().all(|c| c.is_ascii_lowercase()))
            .count()
            >= 3
}

/// The English prose a source makes into messages (outside its tests).
fn english_messages(source: &str) -> Vec<String> {
    let code = source.split("#[cfg(test)]").next().unwrap_or_default();
    let mut out = Vec::new();
    let mut rest = code;
    while let Some(i) = rest.find('"') {
        let before = rest[..i].trim_end();
        let after = &rest[i + 1..];
        let mut end = 0;
        let bytes = after.as_bytes();
        while end < bytes.len() && (bytes[end] != b'"' || (end > 0 && bytes[end - 1] == b'\\')) {
            end += 1;
        }
        let text = &after[..end.min(after.len())];
        let next = after.get(end + 1..).unwrap_or_default().trim_start();
        let made = before.ends_with("format!(")
            || next.starts_with(".to_string()")
            || next.starts_with(".into()")
            || before.ends_with("Failed(")
            || before.ends_with("Err(");
        if made && english_prose(text) {
            out.push(text.chars().take(60).collect());
        }
        rest = after.get(end + 1..).unwrap_or_default();
    }
    out
}

/// No grader writes a message in English in its code (a `format!("…")` of
/// English prose, or an English literal made a `String`): every message is
/// keyed in `tests/messages/`, so it exists in both languages.
#[test]
fn no_grader_message_is_english_only() {
    let english: Vec<String> = grader_sources()
        .into_iter()
        .filter(|(name, _)| !INSTRUCTOR_ONLY.contains(&name.as_str()))
        .filter(|(name, source)| {
            let found = english_messages(source);
            if !found.is_empty() {
                println!(
                    "{name}: {} English message(s), e.g. {:?}",
                    found.len(),
                    found[0]
                );
            }
            !found.is_empty()
        })
        .map(|(name, _)| name)
        .collect();
    assert!(
        english.is_empty(),
        "graders with messages in English only, not in tests/messages/{{en,bg}}.toml: {english:?}"
    );
    assert!(english_messages("Err(format!(\"your code is wrong\"))").len() == 1);
    assert!(english_messages("tr!(\"ex03.albedo\", x = format!(\"{x:.3}\"))").is_empty());
}

/// The glossary's terms: (English, Bulgarian, words to avoid).
fn glossary() -> Vec<(String, String, Vec<String>)> {
    let table: toml::Table = toml::from_str(lang::GLOSSARY).expect("lang/glossary.toml parses");
    let terms = table["term"].as_array().expect("[[term]] entries");
    terms
        .iter()
        .map(|t| {
            let s = |k: &str| {
                t.get(k)
                    .and_then(|v| v.as_str())
                    .unwrap_or_default()
                    .to_string()
            };
            let avoid = t
                .get("avoid")
                .and_then(|v| v.as_array())
                .map(|a| {
                    a.iter()
                        .filter_map(|w| w.as_str().map(str::to_string))
                        .collect()
                })
                .unwrap_or_default();
            (s("en"), s("bg"), avoid)
        })
        .collect()
}

#[test]
fn bulgarian_texts_use_the_glossary_words() {
    let terms = glossary();
    assert!(
        terms.len() > 20
            && terms
                .iter()
                .all(|(en, bg, _)| !en.is_empty() && !bg.is_empty())
    );
    let mut texts: Vec<(String, String)> = catalog(Lang::Bg)
        .iter()
        .map(|(k, v)| (format!("tests/messages/bg.toml {k}"), v.clone()))
        .collect();
    for e in exercises::registry() {
        texts.push((
            format!("exercises/info.toml {} title_bg", e.name),
            e.title_bg.clone(),
        ));
        for (i, h) in e.hints_bg.iter().enumerate() {
            texts.push((
                format!("exercises/info.toml {} hint {}", e.name, i + 1),
                h.clone(),
            ));
        }
    }
    let found = avoided_words(&texts);
    assert!(
        found.is_empty(),
        "words the glossary avoids:\n{}",
        found.join("\n")
    );
}

/// Every word the glossary avoids in `(place, text)`, one line each.
fn avoided_words(texts: &[(String, String)]) -> Vec<String> {
    let terms = glossary();
    let mut found = Vec::new();
    for (place, text) in texts {
        let words = words_of(text);
        for (en, bg, avoid) in &terms {
            for w in avoid.iter().filter(|w| says(&words, w)) {
                found.push(format!(
                    "{place}: \"{w}\" for {en} (the glossary says \"{bg}\")"
                ));
            }
        }
    }
    found
}

/// A text's words, lower case (letters and digits; everything else parts them).
fn words_of(text: &str) -> Vec<String> {
    text.to_lowercase()
        .split(|c: char| !c.is_alphanumeric())
        .filter(|w| !w.is_empty())
        .map(str::to_string)
        .collect()
}

/// Whether `words` hold the avoided `phrase` as whole words in a row; a word
/// of the phrase ending in `*` matches every word that starts with it (see
/// the glossary's head).
fn says(words: &[String], phrase: &str) -> bool {
    let lower = phrase.to_lowercase();
    let wanted: Vec<&str> = lower.split_whitespace().collect();
    let matches = |word: &str, w: &str| match w.strip_suffix('*') {
        Some(stem) => word.starts_with(stem),
        None => word == w,
    };
    !wanted.is_empty()
        && words
            .windows(wanted.len())
            .any(|window| window.iter().zip(&wanted).all(|(word, w)| matches(word, w)))
}

/// The glossary check matches whole words (issue 30: "семпли" was found in
/// "семплиране"), stems where the glossary asks with `*`, and phrases.
#[test]
fn avoided_words_are_whole_words() {
    let found = |text: &str| avoided_words(&[("t".to_string(), text.to_string())]);
    assert!(found("семплиране по значимост").is_empty());
    assert_eq!(found("две семпли на пиксел").len(), 1);
    assert_eq!(found("пристрастна оценка").len(), 1);
    assert_eq!(found("по телесния ъгъл").len(), 1);
    assert_eq!(found("телесен ъгъл").len(), 1);
    assert_eq!(found("червено-синьозелен анаглиф").len(), 1);
    assert!(found("червено-циан анаглиф").is_empty());
}

/// Avoided words the deck still has, in slides another change owns (issue
/// 30 left them): "file: word". This list may only shrink.
const DECK_LEFT: &[&str] = &[];

/// The Bulgarian deck, the chapters' texts and the lab's page use the
/// glossary's words too (issue 30: the deck said "циан" where the exercise's
/// title said "синьозелен", and "извадки" where the glossary says "проби").
#[test]
fn the_deck_the_tour_and_the_lab_use_the_glossary_words() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut files: Vec<PathBuf> = Vec::new();
    let mut stack = vec![root.join("slides/bg"), root.join("lessons/lesson11/src")];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
            } else if path
                .extension()
                .is_some_and(|e| e == "md" || e == "rs" || e == "js")
            {
                files.push(path);
            }
        }
    }
    files.sort();
    assert!(files.len() > 30, "{files:?}");
    let mut found = Vec::new();
    let mut left = Vec::new();
    for f in &files {
        let place = f
            .strip_prefix(&root)
            .unwrap()
            .to_string_lossy()
            .replace('\\', "/");
        let text = std::fs::read_to_string(f).unwrap();
        for line in avoided_words(&[(place.clone(), text)]) {
            let word = line.split('"').nth(1).unwrap_or_default();
            let key = format!("{place}: {word}");
            if DECK_LEFT.contains(&key.as_str()) {
                left.push(key);
            } else {
                found.push(line);
            }
        }
    }
    assert!(
        found.is_empty(),
        "words the glossary avoids:\n{}",
        found.join("\n")
    );
    for known in DECK_LEFT {
        assert!(
            left.iter().any(|l| l == known),
            "{known} is gone: take it off DECK_LEFT"
        );
    }
}

/// The heading of a stub's task in Bulgarian, under the English one.
const BULGARIAN_HEADING: &str = "//! # На български";

/// Whether a text has Bulgarian letters in it.
fn has_cyrillic(text: &str) -> bool {
    text.chars()
        .any(|c| ('а'..='я').contains(&c.to_lowercase().next().unwrap_or(c)))
}

/// What is missing from a stub's Bulgarian, one line each (empty: nothing):
/// the section `# На български` with the exercise's number and the
/// Bulgarian deck's slides (`„Заглавие“`, as the registry's `slides_bg`),
/// a Bulgarian line in each function's doc, a `// TODO (бг):` line in each
/// function.
fn bulgarian_problems(e: &exercises::Exercise, text: &str) -> Vec<String> {
    let file = &e.file;
    let Some((english, bulgarian)) = text.split_once(BULGARIAN_HEADING) else {
        return vec![format!("{file}: no section \"{BULGARIAN_HEADING}\"")];
    };
    let mut out = Vec::new();
    let task: String = bulgarian
        .lines()
        .skip(1)
        .map_while(|l| l.strip_prefix("//!"))
        .collect::<Vec<_>>()
        .join("\n");
    let number = e.number().unwrap_or(0);
    if !task
        .trim_start()
        .starts_with(&format!("Задача {number} — "))
    {
        out.push(format!(
            "{file}: the Bulgarian section opens with \"Задача {number} — \""
        ));
    }
    if task.len() < english.len() / 3 || !has_cyrillic(&task) {
        out.push(format!(
            "{file}: the Bulgarian section is not the task in Bulgarian"
        ));
    }
    let slides: Vec<String> = task
        .split_once("Слайдове:")
        .or_else(|| task.split_once("Слайд:"))
        .map(|(_, rest)| {
            let paragraph = rest.split("\n\n").next().unwrap_or_default();
            paragraph
                .split('„')
                .skip(1)
                .filter_map(|q| q.split_once('“').map(|(t, _)| t))
                .map(|t| t.split_whitespace().collect::<Vec<_>>().join(" "))
                .collect()
        })
        .unwrap_or_default();
    if slides != e.slides_bg {
        out.push(format!(
            "{file}: the Bulgarian section cites the slides {slides:?}, the registry's slides_bg {:?}",
            e.slides_bg
        ));
    }
    let lines: Vec<&str> = text.lines().collect();
    for (i, line) in lines.iter().enumerate() {
        let Some(name) = line.strip_prefix("pub fn ") else {
            continue;
        };
        let name = name.split('(').next().unwrap_or_default();
        let doc: String = lines[..i]
            .iter()
            .rev()
            .skip_while(|l| !l.starts_with("///"))
            .take_while(|l| l.starts_with("///"))
            .copied()
            .collect();
        if !has_cyrillic(&doc) {
            out.push(format!("{file}: `{name}` has no Bulgarian line in its doc"));
        }
        let body: String = lines[i..]
            .iter()
            .take_while(|l| **l != "}")
            .copied()
            .collect();
        if !body.contains("// TODO (бг): ") {
            out.push(format!("{file}: `{name}` has no `// TODO (бг):` line"));
        }
    }
    out
}

/// Each check of a stub's Bulgarian bites: a stub built here with its task
/// in both languages has no problem, and each change is named.
#[test]
fn each_bulgarian_stub_check_catches_its_own_change() {
    let reg = exercises::registry();
    let e = &reg[2];
    let slides: Vec<String> = e.slides_bg.iter().map(|t| format!("„{t}“")).collect();
    let good = format!(
        "//! Exercise 3 — the Lambertian BRDF.\n//!\n//! ---\n//!\n{BULGARIAN_HEADING}\n//!\n\
         //! Задача 3 — ламбертовата BRDF.\n//!\n//! Слайдове: {}.\n//!\n\
         //! Пресметнете f_r.\n\n\
         /// f_r.\n///\n/// f_r на ламбертова повърхност.\n\
         pub fn f_r() -> f32 {{\n    // TODO: the constant.\n    // TODO (бг): константата.\n    todo!()\n}}\n",
        slides.join(", ")
    );
    assert_eq!(bulgarian_problems(e, &good), Vec::<String>::new(), "{good}");
    let only = |text: String, expected: &str| {
        let problems = bulgarian_problems(e, &text);
        assert!(
            problems.len() == 1 && problems[0].contains(expected),
            "expected only {expected:?}, got {problems:?} for:\n{text}"
        );
    };
    only(
        good.replace(BULGARIAN_HEADING, "//! # In Bulgarian"),
        "no section",
    );
    only(good.replace("Задача 3 — ", "Задача 4 — "), "opens with");
    only(
        good.replace(&slides[0], "„Path tracing (II)“"),
        "cites the slides",
    );
    only(
        good.replace("/// f_r на ламбертова повърхност.\n", ""),
        "no Bulgarian line in its doc",
    );
    only(
        good.replace("    // TODO (бг): константата.\n", ""),
        "no `// TODO (бг):` line",
    );
}

/// Every stub carries its task in Bulgarian, under the English one, in the
/// glossary's words. The stubs are the student's to edit: only in the
/// instructor's run.
#[cfg(feature = "solutions")]
#[test]
fn every_stub_has_its_task_in_bulgarian() {
    let mut problems = Vec::new();
    let mut sections = Vec::new();
    for e in exercises::registry() {
        let text =
            std::fs::read_to_string(exercises::crate_dir().join(&e.file)).expect("exercise file");
        problems.extend(bulgarian_problems(&e, &text));
        if let Some((_, bulgarian)) = text.split_once(BULGARIAN_HEADING) {
            sections.push((format!("exercises/{}", e.file), bulgarian.to_string()));
        }
    }
    problems.extend(avoided_words(&sections));
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}
