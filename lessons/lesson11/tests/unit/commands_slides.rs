//! Unit tests of `commands/slides.rs`.

use clap::Parser as _;
use deck::Deck;
use lesson11::commands::slides::*;

fn decks() -> Vec<Deck> {
    load_decks(&project_slides_dir(), &[]).expect("the project's slides load")
}

#[test]
fn both_languages_have_the_same_slides_pictures_and_commands_in_the_same_order() {
    let decks = decks();
    let langs: Vec<&str> = decks.iter().map(|d| d.lang.as_str()).collect();
    assert_eq!(langs, ["bg", "en"]);
    let (bg, en) = (&decks[0], &decks[1]);
    assert_eq!(bg.slides().count(), en.slides().count());
    assert_eq!(bg.images(), en.images());
    for (a, b) in bg.slides().zip(en.slides()) {
        assert_eq!(a.commands, b.commands, "{} / {}", a.origin, b.origin);
        assert_eq!(a.exercises, b.exercises, "{} / {}", a.origin, b.origin);
    }
    assert!(en.slides().count() >= 40, "a whole lecture");
}

#[test]
fn one_file_per_tour_chapter_in_the_tour_order() {
    for deck in decks() {
        let names: Vec<&str> = deck.chapters.iter().map(|c| c.name.as_str()).collect();
        assert_eq!(
            names,
            [
                "01-stereo",
                "02-gi-effects",
                "03-brdf",
                "04-rendering-equation",
                "05-path",
                "06-light",
                "07-bdpt",
                "08-compare",
                "09-biased"
            ],
            "{}",
            deck.lang
        );
        // Pictures come from their own chapter or an earlier one.
        for c in &deck.chapters {
            for s in &c.slides {
                for i in &s.images {
                    assert!(
                        i.path.as_str() <= c.name.as_str() || i.path.starts_with(&c.name[..2]),
                        "{}: {} belongs to a later chapter",
                        s.origin,
                        i.path
                    );
                }
            }
        }
    }
}

#[test]
fn every_slide_with_a_picture_names_its_command_and_every_command_parses() {
    for deck in decks() {
        for s in deck.slides() {
            if !s.images.is_empty() {
                assert!(
                    !s.commands.is_empty(),
                    "{}: a picture without its command",
                    s.origin
                );
            }
            for cmd in &s.commands {
                let words: Vec<&str> = cmd.split_whitespace().collect();
                if let Err(e) = lesson11::Cli::try_parse_from(&words) {
                    panic!("{}: `{cmd}` is not a valid lesson11 command: {e}", s.origin);
                }
            }
        }
    }
}

#[test]
fn every_formula_of_both_decks_converts() {
    for deck in decks() {
        let mut formulas = 0;
        for s in deck.slides() {
            let html =
                html::markdown_to_html(&s.body).unwrap_or_else(|e| panic!("{}: {e:#}", s.origin));
            formulas += html.matches("<math").count();
            assert!(!html.contains('$'), "{}: a stray $ in {html}", s.origin);
        }
        assert!(formulas >= 30, "{}: only {formulas} formulas", deck.lang);
    }
}

#[test]
fn languages_that_differ_are_reported_with_both_places() {
    let mut decks = decks();
    decks[0].chapters[1].slides[0].images.clear();
    let err = check_parallel(&decks).unwrap_err().to_string();
    assert!(err.contains("02-gi-effects.md"), "{err}");
    let mut decks = crate::commands_slides::decks();
    decks[0].chapters[2].slides.pop();
    let err = check_parallel(&decks).unwrap_err().to_string();
    assert!(err.contains("03-brdf"), "{err}");
}
