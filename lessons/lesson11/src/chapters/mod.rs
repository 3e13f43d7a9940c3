//! The lecture's chapters in order, one file each, and the tour that walks
//! them.
//!
//! A chapter file (`cNN_topic.rs`) renders its pictures, writes its tables and
//! plots, returns its section of the page, and declares itself as
//! `pub const CHAPTER: Chapter` (its subcommand, its line in `--help`, its
//! options if the tour's are not enough). Adding a chapter is adding its file
//! and one line to the list below; its subcommand follows from the list.

use std::time::Instant;

use anyhow::Result;
use clap::{ArgMatches, FromArgMatches};

use crate::page::Page;
use crate::tour::{Chapter, Tour, TourArgs};

/// Declares the chapter modules and lists their `CHAPTER`s in the same order.
macro_rules! chapters {
    ($($chapter:ident),* $(,)?) => {
        $(pub mod $chapter;)*

        /// The chapters in lecture order.
        pub const CHAPTERS: &[Chapter] = &[$($chapter::CHAPTER),*];
    };
}

chapters![
    c01_stereo,
    c02_gi_effects,
    c03_brdf,
    c04_rendering_equation,
    c05_path,
    c06_light,
    c07_bdpt,
    c08_compare,
    c09_biased,
];

/// The chapter whose subcommand is `name`.
pub fn find(name: &str) -> Option<&'static Chapter> {
    CHAPTERS.iter().find(|c| c.name == name)
}

/// The whole tour: every chapter, and `index.html` with all of them.
pub fn run(args: &TourArgs) -> Result<()> {
    run_chapters(args, None)
}

/// A chapter's subcommand: with options of its own, the chapter runs them;
/// with the tour's, it runs as a tour of one chapter.
pub fn run_alone(chapter: &Chapter, matches: &ArgMatches) -> Result<()> {
    match &chapter.options {
        Some(options) => (options.run)(matches),
        None => run_chapters(&TourArgs::from_arg_matches(matches)?, Some(chapter.name)),
    }
}

/// Runs every chapter (`only = None`) or one, and writes the page: the
/// tour's `index.html`, or `<chapter>.html` beside it for a single chapter.
pub fn run_chapters(args: &TourArgs, only: Option<&str>) -> Result<()> {
    let tour = Tour::new(args)?;
    let start = Instant::now();
    let mut page = Page::new(lang::pick(
        "Lecture 11: stereoscopy and global illumination, rendered",
        "Лекция 11: стереоскопия и глобално осветление, рендерирани",
    ));
    page.intro = lang::pick(
        "To watch these pictures converge and turn the lecture's knobs yourself \
         (integrator, max depth, samples, stereo separation, BRDF parameters), run \
         `cargo run --release -p lesson11 -- lab` and open the address it prints.",
        "За да гледате как тези картини се изчистват от шума и сами да въртите параметрите \
         на лекцията (интегратор, максимална дълбочина, проби, stereoSeparation, параметри на \
         BRDF-ите), изпълнете `cargo run --release -p lesson11 -- lab` и отворете адреса, \
         който програмата отпечатва.",
    )
    .into();
    for chapter in CHAPTERS {
        let name = chapter.name;
        if only.is_some_and(|o| o != name) {
            continue;
        }
        crate::console::say!("\n== {name}");
        let t = Instant::now();
        page.sections.push((chapter.render)(&tour)?);
        crate::console::say!("== {name}: {:.1} s", t.elapsed().as_secs_f64());
    }
    let file = only.map_or_else(|| "index.html".to_string(), |name| format!("{name}.html"));
    let index = page.write(&tour.out, &file)?;
    let (seconds, index) = (start.elapsed().as_secs_f64(), index.display());
    crate::console::say!(
        "{}",
        lang::pick(
            format!("\nThat took {seconds:.1} s. Open {index} to see the pictures."),
            format!("\nОтне {seconds:.1} s. Отворете {index}, за да видите картините."),
        )
    );
    Ok(())
}
