//! The slide deck as the Markdown in `slides/{bg,en}/` writes it.
//!
//! One file per chapter of the tour (`01-stereo.md` … `09-biased.md`);
//! slides are separated by a line `---`; each slide starts with `# Title`.
//! A line of images (`![caption](02-gi-effects/cornell-path.png) …`, paths
//! relative to `out/lesson11`; `{lang}` in a path stands for the deck's
//! language, for a figure drawn with words in each language, e.g.
//! `03-brdf/hemisphere-{lang}.svg`) becomes the slide's figures; the lines
//! `> command: lesson11 …` and `> exercise: 9` say which command renders the
//! picture and which exercise goes with it. Everything else is Markdown with
//! `$…$` and `$$…$$` formulas.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};

/// A picture on a slide.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Image {
    pub caption: String,
    /// Relative to the tour's output folder, e.g. `05-path/cornell-mis.png`,
    /// as written: the same in every language (see [`Image::file`]).
    pub path: String,
}

impl Image {
    /// The file a deck in `lang` shows: the path with `{lang}` replaced.
    pub fn file(&self, lang: &str) -> String {
        self.path.replace("{lang}", lang)
    }
}

/// One slide.
#[derive(Clone, Debug)]
pub struct Slide {
    pub title: String,
    /// The Markdown between the title and the figures (may contain formulas).
    pub body: String,
    pub images: Vec<Image>,
    /// Commands that render the picture, as typed (starting with `lesson11`).
    pub commands: Vec<String>,
    /// Exercise numbers that go with the slide.
    pub exercises: Vec<u32>,
    /// `file:line` of the title, for error messages.
    pub origin: String,
}

/// One chapter file.
#[derive(Clone, Debug)]
pub struct Chapter {
    /// The file name without `.md`, e.g. `02-gi-effects`.
    pub name: String,
    pub slides: Vec<Slide>,
}

/// A whole deck in one language.
#[derive(Clone, Debug)]
pub struct Deck {
    pub lang: String,
    pub chapters: Vec<Chapter>,
}

impl Deck {
    /// Reads every `*.md` of `dir` in file-name order.
    pub fn load(dir: &Path) -> Result<Deck> {
        let lang = dir
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
            .with_context(|| format!("cannot read the slides folder {}", dir.display()))?
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|e| e == "md"))
            .collect();
        files.sort();
        if files.is_empty() {
            bail!("no .md files in {}", dir.display());
        }
        let mut chapters = Vec::new();
        for file in files {
            let text = std::fs::read_to_string(&file)
                .with_context(|| format!("cannot read {}", file.display()))?;
            let name = file
                .file_stem()
                .map(|s| s.to_string_lossy().into_owned())
                .unwrap_or_default();
            let slides = parse_chapter(&text, &file.display().to_string())?;
            chapters.push(Chapter { name, slides });
        }
        Ok(Deck { lang, chapters })
    }

    pub fn slides(&self) -> impl Iterator<Item = &Slide> {
        self.chapters.iter().flat_map(|c| &c.slides)
    }

    /// Every image path as written, in slide order (repeats kept): the same
    /// in every language.
    pub fn images(&self) -> Vec<&str> {
        self.slides()
            .flat_map(|s| s.images.iter().map(|i| i.path.as_str()))
            .collect()
    }

    /// Every file this deck's language shows, in slide order (repeats kept).
    pub fn files(&self) -> Vec<String> {
        self.slides()
            .flat_map(|s| s.images.iter().map(|i| i.file(&self.lang)))
            .collect()
    }
}

/// Splits a chapter file into slides.
pub fn parse_chapter(text: &str, file: &str) -> Result<Vec<Slide>> {
    let mut slides = Vec::new();
    let mut chunk: Vec<(usize, &str)> = Vec::new();
    for (i, line) in text.lines().enumerate() {
        if line.trim_end() == "---" {
            slides.push(parse_slide(&chunk, file)?);
            chunk.clear();
        } else {
            chunk.push((i + 1, line));
        }
    }
    slides.push(parse_slide(&chunk, file)?);
    Ok(slides)
}

fn parse_slide(lines: &[(usize, &str)], file: &str) -> Result<Slide> {
    let mut lines = lines.iter().skip_while(|(_, l)| l.trim().is_empty());
    let Some(&(first, title_line)) = lines.next() else {
        bail!(
            "{file}: an empty slide (two `---` lines with nothing between them, or one at the end)"
        );
    };
    let origin = format!("{file}:{first}");
    let Some(title) = title_line.strip_prefix("# ") else {
        bail!("{origin}: a slide must start with `# Title`, found `{title_line}`");
    };
    let mut slide = Slide {
        title: title.trim().to_string(),
        body: String::new(),
        images: Vec::new(),
        commands: Vec::new(),
        exercises: Vec::new(),
        origin: origin.clone(),
    };
    for &(n, line) in lines {
        let at = format!("{file}:{n}");
        let t = line.trim();
        if let Some(cmd) = t.strip_prefix("> command:") {
            let cmd = cmd.trim();
            if !cmd.starts_with("lesson11 ") && cmd != "lesson11" {
                bail!("{at}: a command must start with `lesson11`, found `{cmd}`");
            }
            slide.commands.push(cmd.to_string());
        } else if let Some(ex) = t.strip_prefix("> exercise:") {
            for part in ex.split(',') {
                let num: u32 = part.trim().parse().map_err(|_| {
                    anyhow::anyhow!(
                        "{at}: `> exercise:` takes numbers like `9` or `3, 4`, found `{ex}`"
                    )
                })?;
                let numbers: Vec<u32> = exercises::registry::registry()
                    .iter()
                    .filter_map(|e| e.number())
                    .map(|n| n as u32)
                    .collect();
                if !numbers.contains(&num) {
                    let list: Vec<String> = numbers.iter().map(u32::to_string).collect();
                    bail!(
                        "{at}: there is no exercise {num} (the exercises are {})",
                        list.join(", ")
                    );
                }
                slide.exercises.push(num);
            }
        } else if t.starts_with("![") {
            slide.images.extend(parse_images(t, &at)?);
        } else if t.contains("![") {
            bail!("{at}: put images on a line of their own");
        } else {
            slide.body.push_str(line);
            slide.body.push('\n');
        }
    }
    slide.body = slide.body.trim().to_string();
    Ok(slide)
}

/// Parses a line of `![caption](path)` items separated by spaces.
fn parse_images(line: &str, at: &str) -> Result<Vec<Image>> {
    let mut images = Vec::new();
    let mut rest = line.trim();
    while !rest.is_empty() {
        let bad = || anyhow::anyhow!("{at}: expected `![caption](path)`, found `{rest}`");
        let after = rest.strip_prefix("![").ok_or_else(bad)?;
        let close = after.find("](").ok_or_else(bad)?;
        let caption = &after[..close];
        let tail = &after[close + 2..];
        let end = tail.find(')').ok_or_else(bad)?;
        let path = tail[..end].trim();
        if path.is_empty() || path.starts_with('/') || path.contains("..") || path.contains(':') {
            bail!(
                "{at}: image paths are relative to out/lesson11, like `05-path/cornell-mis.png`; found `{path}`"
            );
        }
        images.push(Image {
            caption: caption.trim().to_string(),
            path: path.to_string(),
        });
        rest = tail[end + 1..].trim_start();
    }
    Ok(images)
}
