//! `lesson11 scenes`: the built-in scenes, and writing one out to edit.

use std::io::Write;
use std::path::{Path, PathBuf};

use anyhow::{Result, bail};
use clap::Args;
use raytracer::film::output::{StagedFile, commit_all};
use raytracer::scene::builtin::{BUILTIN_SCENES, builtin, builtin_names};

/// List the built-in scenes, or write one out as a TOML file (with its meshes)
/// that you can edit and render with `lesson11 render --scene FILE`.
#[derive(Args, Debug)]
pub struct ScenesArgs {
    /// Write this built-in scene out as a file.
    #[arg(long, value_name = "NAME")]
    pub write: Option<String>,
    /// Folder to write it into.
    #[arg(long, default_value = "scenes")]
    pub to: PathBuf,
    /// Replace files of the same name that differ from the built-in scene (your edits are lost).
    #[arg(long)]
    pub force: bool,
}

pub fn run(args: &ScenesArgs) -> Result<()> {
    match &args.write {
        None => {
            crate::console::say!("Built-in scenes (use with --scene NAME):");
            for s in BUILTIN_SCENES {
                crate::console::say!("  {:<14} {}", s.name, s.description);
            }
            crate::console::say!(
                "\nWrite one out to edit: lesson11 scenes --write cornell --to my-scenes"
            );
        }
        Some(name) => {
            let path = write_scene(name, &args.to, args.force)?;
            crate::console::say!("wrote {}", path.display());
            crate::console::say!(
                "render it with: cargo run --release -p lesson11 -- render --scene {}",
                path.display()
            );
        }
    }
    Ok(())
}

/// Writes the built-in scene `name` (`NAME.toml` and the files it uses) into
/// `dir`. A file that already exists with other content (the user's edits)
/// is not replaced unless `force`; nothing is replaced unless everything is
/// written.
fn write_scene(name: &str, dir: &Path, force: bool) -> Result<PathBuf> {
    let Some(scene) = builtin(name) else {
        bail!(
            "there is no built-in scene `{name}`; the built-in scenes are: {}",
            builtin_names()
        );
    };
    crate::options::create_dir_for(dir, "--to")?;
    let toml = dir.join(format!("{}.toml", scene.name));
    let files: Vec<(PathBuf, &str)> = scene
        .assets
        .iter()
        .map(|a| (dir.join(a.file), a.text))
        .chain([(toml.clone(), scene.toml)])
        .collect();
    for (path, text) in &files {
        if path.is_dir() {
            bail!(
                "cannot write {}: it is a folder; choose another folder with --to",
                path.display()
            );
        }
        let edited = std::fs::read(path).is_ok_and(|old| old != text.as_bytes());
        if edited && !force {
            bail!(
                "{} already exists and differs from the built-in scene (your edits?): \
                 choose another folder with --to, or pass --force to replace it",
                path.display()
            );
        }
    }
    let staged = files
        .iter()
        .map(|(path, text)| StagedFile::write(path, "the scene", |w| w.write_all(text.as_bytes())))
        .collect::<std::io::Result<Vec<_>>>()?;
    commit_all(staged)?;
    Ok(toml)
}
