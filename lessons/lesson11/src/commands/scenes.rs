//! `lesson11 scenes`: the built-in scenes, and writing one out to edit.

use std::path::PathBuf;

use anyhow::{Context, Result};
use clap::Args;
use raytracer::scene::builtin::{BUILTIN_SCENES, write_builtin};

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
}

pub fn run(args: &ScenesArgs) -> Result<()> {
    match &args.write {
        None => {
            println!("Built-in scenes (use with --scene NAME):");
            for s in BUILTIN_SCENES {
                println!("  {:<14} {}", s.name, s.description);
            }
            println!("\nWrite one out to edit: lesson11 scenes --write cornell --to my-scenes");
        }
        Some(name) => {
            crate::options::create_dir(&args.to)?;
            let path = write_builtin(name, &args.to)
                .with_context(|| format!("cannot write scene `{name}`"))?;
            println!("wrote {}", path.display());
            println!(
                "render it with: cargo run --release -p lesson11 -- render --scene {}",
                path.display()
            );
        }
    }
    Ok(())
}
