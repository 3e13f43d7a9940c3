//! Unit tests of `commands/slides/deck.rs`.

use lesson11::commands::slides::deck::*;

const CHAPTER: &str = "# One\n\n- a $x$\n\n---\n\n# Two\n\n![A](05-path/a.png) ![B](05-path/b.png)\n\n> command: lesson11 render --scene cornell\n> exercise: 3, 4\n";

#[test]
fn slides_split_on_rules_with_titles_figures_commands_and_exercises() {
    let slides = parse_chapter(CHAPTER, "t.md").unwrap();
    assert_eq!(slides.len(), 2);
    assert_eq!(slides[0].title, "One");
    assert_eq!(slides[0].body, "- a $x$");
    assert!(slides[0].images.is_empty());
    assert_eq!(slides[1].title, "Two");
    assert_eq!(
        slides[1].images,
        vec![
            Image {
                caption: "A".into(),
                path: "05-path/a.png".into()
            },
            Image {
                caption: "B".into(),
                path: "05-path/b.png".into()
            },
        ]
    );
    assert_eq!(slides[1].commands, vec!["lesson11 render --scene cornell"]);
    assert_eq!(slides[1].exercises, vec![3, 4]);
    assert_eq!(slides[1].origin, "t.md:7");
}

#[test]
fn malformed_slides_are_errors_with_file_and_line() {
    for (text, needle) in [
        ("no title\n", "t.md:1: a slide must start"),
        ("# A\n---\n", "empty slide"),
        ("# A\n> exercise: nine\n", "t.md:2"),
        (
            "# A\n> exercise: 99\n",
            "there is no exercise 99 (the exercises are 1, 2,",
        ),
        ("# A\n> command: cargo run\n", "lesson11"),
        ("# A\n![x](/abs.png)\n", "relative"),
        ("# A\ntext ![x](a.png)\n", "own"),
        ("# A\n![x](a.png\n", "expected"),
    ] {
        let err = parse_chapter(text, "t.md").unwrap_err().to_string();
        assert!(err.contains(needle), "{text:?}: {err}");
    }
}
