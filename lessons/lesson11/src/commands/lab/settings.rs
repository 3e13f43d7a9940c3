//! A render's settings as the lab receives them, read exactly as
//! `lesson11 render` reads its command line: the query's parameters become
//! that command's options (`spp=64` is `--spp 64`) and go through the same
//! parser and the same checks ([`RenderArgs`], `SceneArgs::load`,
//! `IntegratorKind::plan`). So the lab refuses what the command refuses,
//! with the same reason, and renders what it renders, from the same plan:
//! the lab's picture at N spp is `lesson11 render`'s picture with the same
//! options, bit for bit. What takes long (photon maps and the like) is
//! built later, on the render's own thread (`job.rs`).
//!
//! The lab adds caps of its own (it serves a page, not a batch job): at most
//! [`MAX_PIXELS`] pixels and [`MAX_SPP`] samples per pixel, so that a few
//! pages' films always fit in memory.

use std::path::{Path, PathBuf};

use clap::{Args, FromArgMatches};
use raytracer::render::RenderOptions;
use raytracer::scene::{BUILTIN_SCENES, Scene};
use raytracer::wavefront::WavefrontPathTracer;
use serde::Serialize;

use super::query::Query;
use crate::commands::render::RenderArgs;
use crate::integrators::{IntegratorArgs, IntegratorKind, IntegratorPlan};

/// The most pixels of one picture (one eye of a stereo pair): 0.48
/// megapixels, 800×600 (a film takes about 100 bytes a pixel).
pub const MAX_PIXELS: u64 = 800 * 600;

/// The most samples per pixel the lab renders towards.
pub const MAX_SPP: u32 = 65_536;

/// The query parameters that are options of `lesson11 render`.
pub const RENDER_PARAMS: &[&str] = &[
    "scene",
    "integrator",
    "width",
    "height",
    "spp",
    "seed",
    "max-depth",
    "rr-depth",
    "branching",
    "roulette",
    "cutoff",
    "ao-distance",
    "engine",
];

/// What the page calls each option (its label, in English and Bulgarian),
/// so that an error of `lesson11 render` reads in the page's words: "“Seed”:
/// …" where the command line says "'--seed <SEED>'".
pub const PAGE_LABELS: &[(&str, &str, &str)] = &[
    ("scene", "Scene", "Сцена"),
    ("integrator", "Integrator", "Интегратор"),
    ("width", "Size (width)", "Размер (ширина)"),
    ("height", "Size (height)", "Размер (височина)"),
    ("spp", "Target spp", "Проби на пиксел (цел)"),
    ("seed", "Seed", "Начално число (seed)"),
    ("max-depth", "Max depth D", "Максимална дълбочина D"),
    ("rr-depth", "Roulette from bounce", "Рулетка от отражение"),
    ("branching", "Branching N", "Разклоняване N"),
    ("roulette", "Russian roulette", "Руска рулетка"),
    ("cutoff", "cutoff", "cutoff"),
    ("ao-distance", "AO distance", "разстояние за AO"),
    ("engine", "Engine", "Машина"),
    ("separation", "Separation", "Разстояние между очите"),
    ("convergence", "Convergence", "Конвергенция"),
    ("toe-in", "toe-in", "toe-in"),
];

/// A checked render: what to render, how (checked, not built yet), and the
/// command line that renders the same picture.
pub struct RenderSetup {
    pub scene: Scene,
    /// The integrator chosen and its options, as `lesson11 render` read them.
    pub kind: IntegratorKind,
    pub integrator_args: IntegratorArgs,
    pub plan: IntegratorPlan,
    pub options: RenderOptions,
    /// The options of `lesson11 render` (and of `lesson11 stereo`) that give
    /// the same picture, e.g. `--scene cornell --integrator path --spp 64`.
    pub options_line: String,
    /// `engine=wavefront`: the path tracer on the wavefront engine.
    pub wavefront: Option<WavefrontPathTracer>,
}

/// The scenes a page may choose: the built-in ones, and the `.toml` files of
/// the folder given with `--scenes` (read again at every request).
#[derive(Clone, Debug, Default)]
pub struct SceneFolder(pub Option<PathBuf>);

/// One scene of the list the page shows.
#[derive(Serialize)]
pub struct SceneEntry {
    /// What `scene=` takes: a built-in name or a file name (`room.toml`).
    pub name: String,
    pub description: String,
    pub builtin: bool,
}

impl SceneFolder {
    /// Every scene, built-in ones first, then the folder's files by name.
    pub fn list(&self) -> Vec<SceneEntry> {
        let mut list: Vec<SceneEntry> = BUILTIN_SCENES
            .iter()
            .map(|s| SceneEntry {
                name: s.name.to_string(),
                description: s.description.to_string(),
                builtin: true,
            })
            .collect();
        if let Some(dir) = &self.0 {
            let mut files: Vec<String> = std::fs::read_dir(dir)
                .into_iter()
                .flatten()
                .flatten()
                // A regular file itself, not a link: a link could lead out of
                // the folder to any file the lab's user can read.
                .filter(|e| e.file_type().is_ok_and(|t| t.is_file()))
                .filter_map(|e| e.file_name().into_string().ok())
                .filter(|name| is_scene_file_name(name))
                .collect();
            files.sort();
            list.extend(files.into_iter().map(|name| SceneEntry {
                description: format!("{}", dir.join(&name).display()),
                name,
                builtin: false,
            }));
        }
        list
    }

    /// The `--scene` value for `name`: a built-in name as it is, a regular
    /// file of the folder as its path. Nothing else: no other file can be
    /// named, and a symbolic link in the folder is not followed.
    pub fn resolve(&self, name: &str) -> Result<String, String> {
        if BUILTIN_SCENES.iter().any(|s| s.name == name) {
            return Ok(name.to_string());
        }
        if let Some(dir) = &self.0
            && is_scene_file_name(name)
        {
            let path = dir.join(name);
            // Not `is_file`, which follows a link out of the folder.
            if std::fs::symlink_metadata(&path).is_ok_and(|m| m.file_type().is_file()) {
                return Ok(path.to_string_lossy().into_owned());
            }
        }
        let names: Vec<String> = self.list().into_iter().map(|s| s.name).collect();
        Err(lang::pick(
            format!("unknown scene {name:?}: choose one of {}", names.join(", ")),
            format!(
                "непозната сцена {name:?}: изберете една от {}",
                names.join(", ")
            ),
        ))
    }
}

/// A plain file name ending in `.toml` (no folder, not hidden).
fn is_scene_file_name(name: &str) -> bool {
    name.ends_with(".toml")
        && !name.starts_with('.')
        && !name.contains(['/', '\\'])
        && Path::new(name).file_name().is_some_and(|f| f == name)
}

/// The render that the query's [`RENDER_PARAMS`] describe (`default_scene`
/// if it names none); other parameters are the caller's.
pub fn render_setup(
    q: &Query,
    folder: &SceneFolder,
    default_scene: &str,
    default_integrator: &str,
) -> Result<RenderSetup, String> {
    let mut words: Vec<String> = Vec::new();
    let scene = folder.resolve(q.get("scene").unwrap_or(default_scene))?;
    words.push(format!("--scene={scene}"));
    words.push(format!(
        "--integrator={}",
        q.get("integrator").unwrap_or(default_integrator)
    ));
    if q.flag("roulette")? {
        words.push("--roulette".into());
    }
    for (name, value) in q.iter() {
        match name {
            "scene" | "integrator" | "roulette" => {}
            _ if RENDER_PARAMS.contains(&name) => words.push(format!("--{name}={value}")),
            _ => {}
        }
    }
    let command = RenderArgs::augment_args(clap::Command::new("render").no_binary_name(true));
    let matches = command
        .try_get_matches_from(&words)
        .map_err(|e| on_the_page(&clap_reason(&e)))?;
    let args = RenderArgs::from_arg_matches(&matches).map_err(|e| on_the_page(&clap_reason(&e)))?;
    let (scene, mut options) = args
        .scene
        .load("cornell")
        .map_err(|e| on_the_page(&one_line(&e)))?;
    let (w, h) = (scene.camera.width, scene.camera.height);
    if w as u64 * h as u64 > MAX_PIXELS {
        return Err(lang::pick(
            format!(
                "the picture would be {w}×{h} pixels, more than the lab's {MAX_PIXELS} (800×600): \
                 lower width and height (lesson11 render takes any size)"
            ),
            format!(
                "картината би била {w}×{h} пиксела, повече от {MAX_PIXELS} (800×600) на \
                 лабораторията: намалете ширината и височината (lesson11 render приема всеки размер)"
            ),
        ));
    }
    if options.spp > MAX_SPP {
        return Err(lang::pick(
            format!(
                "“Target spp” must be at most {MAX_SPP} in the lab, got {}",
                options.spp
            ),
            format!(
                "„Проби на пиксел (цел)“ са най-много {MAX_SPP} в лабораторията, а са {}",
                options.spp
            ),
        ));
    }
    options.progress = false;
    // The checks of `lesson11 render`, naive recursion's ray budget among
    // them: the lab refuses what the command line refuses, with its message
    // (it ran a naive render of 6.4e14 rays whose command the page showed
    // and `lesson11 render` refused).
    let plan = args
        .integrator
        .plan(&args.integrator_args, &scene, &options, false)
        .map_err(|e| on_the_page(&one_line(&e)))?;
    let wavefront = crate::commands::render::wavefront_engine(&args, &scene)
        .map_err(|e| on_the_page(&one_line(&e)))?;
    let options_line = words
        .iter()
        .map(|w| match w.split_once('=') {
            Some((flag, value)) => format!("{flag} {}", shell_word(value)),
            None => w.clone(),
        })
        .collect::<Vec<_>>()
        .join(" ");
    Ok(RenderSetup {
        scene,
        kind: args.integrator,
        integrator_args: args.integrator_args,
        plan,
        options,
        options_line,
        wavefront,
    })
}

/// A word as a shell reads it: quoted if it holds anything but plain characters.
fn shell_word(s: &str) -> String {
    let plain = !s.is_empty()
        && s.chars()
            .all(|c| c.is_ascii_alphanumeric() || "-_./,:+".contains(c));
    if plain {
        s.to_string()
    } else {
        format!("'{}'", s.replace('\'', r"'\''"))
    }
}

/// A clap error in one line, without its `error:` and its advice to try
/// `--help`; "invalid value 'V' for '--seed <SEED>': why" becomes
/// "--seed: 'V' is not valid (why)", which [`on_the_page`] then names.
fn clap_reason(e: &clap::Error) -> String {
    let text = e.render().to_string();
    let first = text.lines().next().unwrap_or("invalid parameters");
    let first = first.trim_start_matches("error: ");
    let parsed = first.strip_prefix("invalid value '").and_then(|rest| {
        let (value, rest) = rest.split_once("' for '")?;
        let (arg, why) = rest.split_once('\'').unwrap_or((rest, ""));
        let flag = arg.split_whitespace().next()?.trim_start_matches("--");
        let why = why.trim_start_matches(':').trim();
        let why = lang::pick(why, crate::cli_errors::why_bg(why));
        let invalid = lang::pick("is not valid", "не е допустима стойност");
        Some(if why.is_empty() {
            format!("--{flag}: {value:?} {invalid}")
        } else {
            format!("--{flag}: {value:?} {invalid} ({why})")
        })
    });
    parsed.unwrap_or_else(|| first.to_string())
}

/// A message of `lesson11 render` in the page's words: every `--option`
/// it names becomes the label of its field (`--max-depth` → “Max depth D”),
/// so its advice can be followed on the page.
pub fn on_the_page(message: &str) -> String {
    let mut out = String::with_capacity(message.len());
    let mut rest = message;
    while let Some(at) = rest.find("--") {
        out.push_str(&rest[..at]);
        let after = &rest[at + 2..];
        let end = after
            .find(|c: char| !(c.is_ascii_alphanumeric() || c == '-'))
            .unwrap_or(after.len());
        match PAGE_LABELS
            .iter()
            .find(|(flag, _, _)| *flag == &after[..end])
        {
            Some((_, en, bg)) => out.push_str(&lang::pick(format!("“{en}”"), format!("„{bg}“"))),
            None => out.push_str(&rest[at..at + 2 + end]),
        }
        rest = &after[end..];
    }
    out.push_str(rest);
    out
}

/// An error and its causes in one line.
pub fn one_line(e: &anyhow::Error) -> String {
    format!("{e:#}")
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .collect::<Vec<_>>()
        .join(" — ")
}
