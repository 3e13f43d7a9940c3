//! Options shared by every chapter: which scene, how big, how many samples.
//!
//! Two steps, as in ripgrep: clap keeps what the user typed ([`SceneArgs`]),
//! and [`SceneArgs::load`] turns it once into a checked scene and render
//! options, with errors that say what to do.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use clap::Args;
use raytracer::render::RenderOptions;
use raytracer::scene::Scene;

/// Scene and sampling options common to the chapters.
#[derive(Args, Clone, Debug, Default)]
pub struct SceneArgs {
    /// A built-in scene name (see `lesson11 scenes`) or a path to a scene file (.toml).
    #[arg(long, short)]
    pub scene: Option<String>,
    /// Image width in pixels (default: the scene's).
    #[arg(long)]
    pub width: Option<u32>,
    /// Image height in pixels (default: the scene's).
    #[arg(long)]
    pub height: Option<u32>,
    /// Samples per pixel (default: the scene's).
    #[arg(long)]
    pub spp: Option<u32>,
    /// Seed of the random numbers: the same seed gives the same image, bit for bit.
    #[arg(long)]
    pub seed: Option<u64>,
    /// Worker threads (default: all cores). The image does not depend on it.
    #[arg(long)]
    pub threads: Option<usize>,
    /// Output folder.
    #[arg(long, default_value = "out/lesson11")]
    pub out: PathBuf,
}

impl SceneArgs {
    /// Loads the scene (`default` if none was named) and applies the overrides.
    pub fn load(&self, default: &str) -> Result<(Scene, RenderOptions)> {
        let name = self.scene.as_deref().unwrap_or(default);
        let mut scene = load_scene(name)?;
        let width = self.width.unwrap_or(scene.settings.width);
        let height = self.height.unwrap_or(scene.settings.height);
        if width == 0 || height == 0 {
            bail!(
                "the image size must be positive, got {width}×{height}: pass e.g. --width 256 --height 256"
            );
        }
        if width != scene.settings.width || height != scene.settings.height {
            scene.set_resolution(width, height);
        }
        if let Some(seed) = self.seed {
            scene.settings.seed = seed;
        }
        let spp = self.spp.unwrap_or(scene.settings.spp);
        if spp == 0 {
            bail!("--spp must be at least 1");
        }
        if self.threads == Some(0) {
            bail!("--threads must be at least 1 (or left out to use every core)");
        }
        scene.settings.spp = spp;
        let options = RenderOptions {
            spp,
            seed: scene.settings.seed,
            threads: self.threads,
            label: scene.name.clone(),
            ..RenderOptions::default()
        };
        Ok((scene, options))
    }
}

/// A built-in scene by name, or a scene file by path.
pub fn load_scene(name: &str) -> Result<Scene> {
    let path = Path::new(name);
    let looks_like_file = name.ends_with(".toml") || name.contains('/') || name.contains('\\');
    if looks_like_file || (path.exists() && path.is_file()) {
        Ok(Scene::load(path)?)
    } else {
        Ok(Scene::builtin(name)?)
    }
}

/// Creates `dir` (and its parents), with an error that names it.
pub fn create_dir(dir: &Path) -> Result<()> {
    std::fs::create_dir_all(dir).with_context(|| {
        format!(
            "cannot create the output folder {}: choose another with --out",
            dir.display()
        )
    })
}
