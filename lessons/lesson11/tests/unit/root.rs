//! Unit tests of `lib.rs`.

use clap::{CommandFactory, Parser};
use lesson11::*;

#[test]
fn the_command_line_passes_claps_own_checks() {
    Cli::command().debug_assert();
    for l in lang::Lang::ALL {
        language::localize(Cli::command(), l).debug_assert();
    }
}

#[test]
fn help_speaks_bulgarian_with_lang_bg() {
    let mut cli = language::localize(Cli::command(), lang::Lang::Bg);
    let help = cli.render_long_help().to_string();
    for word in [
        "Употреба:",
        "Команди:",
        "Опции:",
        "Лекция 11",
        "Стереоскопия",
        "Показва помощта",
        "Езикът",
    ] {
        assert!(help.contains(word), "no {word:?} in:\n{help}");
    }
    // Every command has its Bulgarian line.
    for sub in cli.get_subcommands() {
        let about = sub.get_about().map(|a| a.to_string()).unwrap_or_default();
        assert!(
            about.chars().any(|c| ('а'..='я').contains(&c)),
            "`{}` has no Bulgarian help: {about}",
            sub.get_name()
        );
    }
    let mut en = language::localize(Cli::command(), lang::Lang::En);
    assert!(en.render_long_help().to_string().contains("Usage:"));
}

#[test]
fn help_lists_the_tour_then_every_chapter_in_lecture_order_then_the_commands() {
    let cli = Cli::command();
    let names: Vec<&str> = cli.get_subcommands().map(|c| c.get_name()).collect();
    let chapters: Vec<&str> = chapters::CHAPTERS.iter().map(|c| c.name).collect();
    assert_eq!(names[0], "tour");
    assert_eq!(names[1..=chapters.len()], chapters[..]);
    assert_eq!(
        chapters,
        [
            "stereo",
            "gi-effects",
            "brdf",
            "rendering-equation",
            "path",
            "light",
            "bdpt",
            "compare",
            "biased"
        ]
    );
    assert!(names[chapters.len() + 1..].contains(&"render"));
    assert!(names[chapters.len() + 1..].contains(&"lab"));
}

#[test]
fn a_chapter_subcommand_keeps_its_own_options() {
    let parse = |words: &[&str]| Cli::try_parse_from(words).map(|c| c.command);
    match parse(&["lesson11", "stereo", "--lf-views", "3", "--toe-in"]) {
        Ok(Some(Command::Chapter(chapter, matches))) => {
            assert_eq!(chapter.name, "stereo");
            assert_eq!(matches.get_one::<u32>("lf_views"), Some(&3));
        }
        _ => panic!("`lesson11 stereo --lf-views 3` is not the stereo chapter"),
    }
    match parse(&["lesson11", "path", "--quick", "--out", "x"]) {
        Ok(Some(Command::Chapter(chapter, _))) => assert_eq!(chapter.name, "path"),
        _ => panic!("`lesson11 path --quick --out x` is not the path chapter"),
    }
    assert!(parse(&["lesson11", "path", "--lf-views", "3"]).is_err());
    assert!(matches!(
        parse(&["lesson11", "tour", "--quality", "tiny"]),
        Ok(Some(Command::Tour(_)))
    ));
    assert!(matches!(
        parse(&["lesson11", "scenes"]),
        Ok(Some(Command::Other(_)))
    ));
    assert!(matches!(parse(&["lesson11"]), Ok(None)));
}
