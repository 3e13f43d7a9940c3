//! `lesson11 slides` as the instructor meets it: the decks build from the
//! Markdown with every picture they show, every command they name is a real
//! `lesson11` command, and the HTML holds every slide with its formulas.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn lesson11(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_lesson11"))
        .args(args)
        .output()
        .expect("lesson11 runs")
}

fn slides_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../slides")
}

/// A slide as the test reads it, independently of the program's parser.
#[derive(Debug, PartialEq)]
struct Slide {
    title: String,
    images: Vec<String>,
    commands: Vec<String>,
}

fn read_deck(lang: &str) -> Vec<(String, Vec<Slide>)> {
    let dir = slides_dir().join(lang);
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    files.sort();
    files
        .iter()
        .map(|f| {
            let text = std::fs::read_to_string(f).unwrap();
            let slides = text
                .split("\n---\n")
                .map(|chunk| {
                    let title = chunk
                        .lines()
                        .find(|l| !l.trim().is_empty())
                        .and_then(|l| l.strip_prefix("# "))
                        .unwrap_or_else(|| panic!("{}: a slide without a title", f.display()))
                        .trim()
                        .to_string();
                    let mut images = Vec::new();
                    for part in chunk.split("![").skip(1) {
                        let start = part.find("](").unwrap() + 2;
                        let end = start + part[start..].find(')').unwrap();
                        images.push(part[start..end].to_string());
                    }
                    let commands = chunk
                        .lines()
                        .filter_map(|l| l.strip_prefix("> command:"))
                        .map(|c| c.trim().to_string())
                        .collect();
                    Slide {
                        title,
                        images,
                        commands,
                    }
                })
                .collect();
            (
                f.file_name().unwrap().to_string_lossy().into_owned(),
                slides,
            )
        })
        .collect()
}

#[test]
fn both_languages_have_the_same_files_slides_pictures_and_commands_in_order() {
    let bg = read_deck("bg");
    let en = read_deck("en");
    let names = |d: &[(String, Vec<Slide>)]| d.iter().map(|c| c.0.clone()).collect::<Vec<_>>();
    assert_eq!(names(&bg), names(&en));
    assert_eq!(bg.len(), 8, "one file per chapter of the tour");
    for ((file, b), (_, e)) in bg.iter().zip(&en) {
        assert_eq!(b.len(), e.len(), "{file}: slide counts differ");
        for (x, y) in b.iter().zip(e) {
            assert_eq!(x.images, y.images, "{file}: `{}` / `{}`", x.title, y.title);
            assert_eq!(
                x.commands, y.commands,
                "{file}: `{}` / `{}`",
                x.title, y.title
            );
        }
    }
}

#[test]
fn every_command_a_slide_names_is_a_real_lesson11_command() {
    let mut seen = Vec::new();
    for (file, slides) in read_deck("en") {
        for slide in slides {
            for cmd in slide.commands {
                if seen.contains(&cmd) {
                    continue;
                }
                let mut words: Vec<&str> = cmd.split_whitespace().collect();
                assert_eq!(words.remove(0), "lesson11", "{file}: {cmd}");
                // clap checks every option before it acts on --help, so a wrong
                // subcommand, option or value fails here.
                words.push("--help");
                let o = lesson11(&words);
                assert!(
                    o.status.success(),
                    "{file}, `{}`: `{cmd}` is not a valid command: {}",
                    slide.title,
                    String::from_utf8_lossy(&o.stderr)
                );
                seen.push(cmd);
            }
        }
    }
    assert!(seen.len() >= 20, "only {} distinct commands", seen.len());
    // The check itself can fail.
    assert!(
        !lesson11(&["render", "--integrator", "nope", "--help"])
            .status
            .success()
    );
    assert!(!lesson11(&["slideshow", "--help"]).status.success());
}

#[test]
fn slides_tiny_renders_the_missing_pictures_and_writes_every_slide() {
    let out = std::env::temp_dir().join(format!("lesson11-slides-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&out);
    let o = lesson11(&["slides", "--tiny", "--out", out.to_str().unwrap()]);
    assert!(
        o.status.success(),
        "slides failed: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    for lang in ["bg", "en"] {
        let deck = read_deck(lang);
        let page = out.join("slides").join(lang).join("index.html");
        let html = std::fs::read_to_string(&page).unwrap();
        let slides: Vec<&Slide> = deck.iter().flat_map(|c| &c.1).collect();
        assert_eq!(
            html.matches("<section class=\"slide").count(),
            slides.len() + 1,
            "{lang}: every slide and the cover"
        );
        let mut at = 0;
        for s in &slides {
            let title = format!("<h1>{}</h1>", s.title.replace('&', "&amp;"));
            let found = html[at..]
                .find(&title)
                .unwrap_or_else(|| panic!("{lang}: `{}` missing or out of order", s.title));
            at += found + title.len();
            for img in &s.images {
                assert!(out.join(img).is_file(), "{lang}: {img} was not rendered");
                assert!(
                    html.contains(&format!("src=\"../img/{img}\"")),
                    "{lang}: {img} not linked"
                );
            }
        }
        // Every link of the deck resolves offline, next to the page.
        for part in html.split("src=\"").skip(1) {
            let link = &part[..part.find('"').unwrap()];
            assert!(
                page.parent().unwrap().join(link).is_file(),
                "{lang}: {link} is missing"
            );
        }
        assert!(html.matches("<math").count() >= 30, "{lang}: formulas");
        assert!(!html.contains("$$"), "{lang}: unconverted LaTeX");
        assert!(
            !html.contains("http"),
            "{lang}: the deck must not need the network"
        );
        assert!(html.contains("@media print") && html.contains("PageDown"));
    }
    std::fs::remove_dir_all(&out).ok();
}
