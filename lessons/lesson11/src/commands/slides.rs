//! `lesson11 slides`: the Lecture 11 deck in every language of `slides/`,
//! built into self-contained HTML with the pictures the tour renders.
//!
//! The Markdown lives in `slides/{bg,en}/NN-chapter.md`, one file per chapter
//! of the tour, the two languages slide for slide. Pictures that are missing
//! are rendered first (the whole tour, at the chosen quality); then they are
//! copied into `OUT/slides/img/` and every language gets
//! `OUT/slides/LANG/index.html`, which works offline wherever the `slides`
//! folder is copied.

pub mod deck;
pub mod html;
pub mod math;
pub mod symbols;

use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use clap::Args;
use raytracer::film::output::write_file;

pub use deck::Deck;

use crate::options::create_dir;
use crate::render_files::partial_note;
use crate::tour::{Quality, TourArgs};

/// Build the Lecture 11 slides (Bulgarian and English) into OUT/slides/LANG/index.html,
/// rendering the pictures they show first if any is missing. Arrow keys, PageUp/PageDown,
/// Home and End move between slides; printing gives one slide per page.
#[derive(Args, Debug, Clone)]
pub struct SlidesArgs {
    /// Folder of the tour's pictures; the decks go into OUT/slides/.
    #[arg(long, default_value = "out/lesson11")]
    pub out: PathBuf,
    /// Folder with one subfolder of Markdown per language (default: ./slides, else the
    /// project's slides/ folder).
    #[arg(long)]
    pub src: Option<PathBuf>,
    /// Quality of the pictures rendered when some are missing: tiny, quick or full.
    #[arg(long, value_enum, default_value = "quick")]
    pub quality: Quality,
    /// Same as --quality quick.
    #[arg(long, conflicts_with_all = ["quality", "tiny"])]
    pub quick: bool,
    /// Same as --quality tiny: 32-pixel pictures in seconds, to check the deck.
    #[arg(long, conflicts_with = "quality")]
    pub tiny: bool,
    /// Render every picture again even if all of them exist.
    #[arg(long)]
    pub render: bool,
    /// Worker threads for rendering (default: all cores).
    #[arg(long)]
    pub threads: Option<usize>,
    /// Languages to build, comma-separated (default: every subfolder of --src).
    #[arg(long, value_delimiter = ',')]
    pub lang: Vec<String>,
}

impl SlidesArgs {
    fn quality(&self) -> Quality {
        if self.tiny {
            Quality::Tiny
        } else if self.quick {
            Quality::Quick
        } else {
            self.quality
        }
    }
}

/// The project's slides folder as seen from the source tree.
pub fn project_slides_dir() -> PathBuf {
    let lesson = Path::new(env!("CARGO_MANIFEST_DIR"));
    lesson
        .parent()
        .and_then(Path::parent)
        .unwrap_or(lesson)
        .join("slides")
}

/// The folder given, or ./slides, or the project's.
fn source_dir(given: Option<&Path>) -> Result<PathBuf> {
    if let Some(dir) = given {
        if !dir.is_dir() {
            bail!("the slides folder {} does not exist", dir.display());
        }
        return Ok(dir.to_path_buf());
    }
    for dir in [PathBuf::from("slides"), project_slides_dir()] {
        if dir.join("en").is_dir() {
            return Ok(dir);
        }
    }
    bail!("cannot find the slides: run from the project folder or pass --src PATH/TO/slides")
}

/// The pictures that `src/NEEDED-PICTURES.md` lists: slides show them before
/// the chapters make them (first cell of each table row, in backticks).
pub fn needed_pictures(src: &Path) -> Result<Vec<String>> {
    let file = src.join("NEEDED-PICTURES.md");
    if !file.is_file() {
        return Ok(Vec::new());
    }
    let text = std::fs::read_to_string(&file)
        .with_context(|| format!("cannot read {}", file.display()))?;
    Ok(text
        .lines()
        .filter_map(|l| l.trim().strip_prefix("| `"))
        .filter_map(|l| l.split('`').next())
        .map(String::from)
        .collect())
}

/// Loads every language folder of `src` (or those named), checked against each other.
pub fn load_decks(src: &Path, langs: &[String]) -> Result<Vec<Deck>> {
    let mut names: Vec<String> = if langs.is_empty() {
        std::fs::read_dir(src)
            .with_context(|| format!("cannot read {}", src.display()))?
            .filter_map(|e| e.ok())
            .filter(|e| e.path().is_dir())
            .map(|e| e.file_name().to_string_lossy().into_owned())
            .collect()
    } else {
        langs.to_vec()
    };
    names.sort();
    if names.is_empty() {
        bail!("{} has no language folders (bg/, en/)", src.display());
    }
    let decks = names
        .iter()
        .map(|l| Deck::load(&src.join(l)))
        .collect::<Result<Vec<_>>>()?;
    check_parallel(&decks)?;
    Ok(decks)
}

/// The languages must have the same chapters and the same slides in the same
/// order: the same pictures, commands and exercises on each slide.
pub fn check_parallel(decks: &[Deck]) -> Result<()> {
    let Some((first, rest)) = decks.split_first() else {
        return Ok(());
    };
    for other in rest {
        let names = |d: &Deck| {
            d.chapters
                .iter()
                .map(|c| c.name.clone())
                .collect::<Vec<_>>()
        };
        if names(first) != names(other) {
            bail!(
                "the {} and {} slides have different chapter files: {:?} and {:?}",
                first.lang,
                other.lang,
                names(first),
                names(other)
            );
        }
        for (a, b) in first.chapters.iter().zip(&other.chapters) {
            if a.slides.len() != b.slides.len() {
                bail!(
                    "{}.md has {} slides in {} but {} in {}",
                    a.name,
                    a.slides.len(),
                    first.lang,
                    b.slides.len(),
                    other.lang
                );
            }
            for (x, y) in a.slides.iter().zip(&b.slides) {
                let paths =
                    |s: &deck::Slide| s.images.iter().map(|i| i.path.clone()).collect::<Vec<_>>();
                if paths(x) != paths(y) || x.commands != y.commands || x.exercises != y.exercises {
                    bail!(
                        "{} and {} differ in their pictures, commands or exercises: \
                         {:?} {:?} {:?} against {:?} {:?} {:?}",
                        x.origin,
                        y.origin,
                        paths(x),
                        x.commands,
                        x.exercises,
                        paths(y),
                        y.commands,
                        y.exercises
                    );
                }
            }
        }
    }
    Ok(())
}

/// Builds every deck; returns the paths of the HTML files written.
pub fn build(args: &SlidesArgs) -> Result<Vec<PathBuf>> {
    let src = source_dir(args.src.as_deref())?;
    let decks = load_decks(&src, &args.lang)?;
    let mut pictures: Vec<String> = decks.iter().flat_map(|d| d.files()).collect();
    pictures.sort();
    pictures.dedup();

    // Pictures the chapters do not make yet are shown as placeholders.
    // A picture of an interrupted render counts as missing: it is rendered
    // again rather than shown as finished.
    let needed = needed_pictures(&src)?;
    let missing = |out: &Path| -> Vec<String> {
        pictures
            .iter()
            .filter(|p| {
                let file = out.join(p);
                (!file.is_file() || partial_note(&file).exists()) && !needed.contains(p)
            })
            .cloned()
            .collect()
    };
    let absent = missing(&args.out);
    if args.render || !absent.is_empty() {
        if !absent.is_empty() {
            crate::console::say!(
                "{} of the {} pictures are missing or from an interrupted render (e.g. {}): \
                 rendering the tour first",
                absent.len(),
                pictures.len(),
                absent[0]
            );
        }
        let mut tour = TourArgs {
            quality: args.quality(),
            ..TourArgs::default()
        };
        tour.common.out = args.out.clone();
        tour.common.threads = args.threads;
        crate::chapters::run(&tour)?;
        let still = missing(&args.out);
        if !still.is_empty() {
            bail!(
                "the slides show pictures that the tour does not render: {}",
                still.join(", ")
            );
        }
    }

    // Copy the pictures next to the decks, so that the slides folder stands alone.
    let slides_out = args.out.join("slides");
    let not_yet: Vec<&str> = pictures
        .iter()
        .filter(|p| !args.out.join(p).is_file())
        .map(String::as_str)
        .collect();
    if !not_yet.is_empty() {
        crate::console::say!(
            "{} pictures are not made by the chapters yet (slides/NEEDED-PICTURES.md): \
             shown as placeholders: {}",
            not_yet.len(),
            not_yet.join(", ")
        );
    }
    for p in &pictures {
        let to = slides_out.join("img").join(p);
        if not_yet.contains(&p.as_str()) {
            // No stale copy from an earlier build may stand in for it.
            let _ = std::fs::remove_file(&to);
            continue;
        }
        if let Some(parent) = to.parent() {
            create_dir(parent)?;
        }
        std::fs::read(args.out.join(p))
            .and_then(|bytes| write_file(&to, bytes))
            .with_context(|| format!("cannot copy {} to {}", p, to.display()))?;
    }

    let mut written = Vec::new();
    let mut links = String::new();
    for deck in &decks {
        let dir = slides_out.join(&deck.lang);
        create_dir(&dir)?;
        let page = html::deck_html(deck, "../img/")?;
        let path = dir.join("index.html");
        write_file(&path, page).with_context(|| format!("cannot write {}", path.display()))?;
        crate::console::say!(
            "wrote {} ({} slides)",
            path.display(),
            deck.slides().count() + 1
        );
        links.push_str(&format!(
            "<li><a href=\"{l}/index.html\">{t}</a></li>",
            l = html::escape(&deck.lang),
            t = html::escape(html::Words::for_lang(&deck.lang).title)
        ));
        written.push(path);
    }
    let index = slides_out.join("index.html");
    write_file(
        &index,
        format!(
            "<!doctype html>\n<html><head><meta charset=\"utf-8\"><title>Lecture 11 slides</title></head>\
             <body style=\"font-family:system-ui,sans-serif;margin:3rem\"><h1>Lecture 11</h1><ul>{links}</ul></body></html>\n"
        ),
    )
    .with_context(|| format!("cannot write {}", index.display()))?;
    Ok(written)
}

pub fn run(args: &SlidesArgs) -> Result<()> {
    let written = build(args)?;
    if let Some(first) = written.first() {
        crate::console::say!("Open {} (arrow keys move between slides).", first.display());
    }
    Ok(())
}
