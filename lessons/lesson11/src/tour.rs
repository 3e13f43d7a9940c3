//! The tour: every chapter of the lecture in order, with quick settings.

use std::path::PathBuf;

use anyhow::Result;
use clap::Args;
use raytracer::integrator::{AmbientOcclusion, Direct};

use crate::options::{SceneArgs, create_dir};
use crate::page::{Figure, Page, Section};
use crate::render_cmd::render_to_files;

/// Walk the lecture in order and write its pictures and out/lesson11/index.html.
#[derive(Args, Debug, Clone)]
pub struct TourArgs {
    /// Output folder.
    #[arg(long, default_value = "out/lesson11")]
    pub out: PathBuf,
    /// Worker threads (default: all cores).
    #[arg(long)]
    pub threads: Option<usize>,
}

impl Default for TourArgs {
    fn default() -> Self {
        TourArgs {
            out: PathBuf::from("out/lesson11"),
            threads: None,
        }
    }
}

pub fn run(args: &TourArgs) -> Result<()> {
    create_dir(&args.out)?;
    let mut page = Page::new("Lecture 11: global illumination, rendered");

    println!("00 · the renderer: scenes, direct light, ambient occlusion");
    let dir = args.out.join("00-foundation");
    let scene_args = |scene: &str, spp: u32| SceneArgs {
        scene: Some(scene.to_string()),
        spp: Some(spp),
        threads: args.threads,
        out: dir.clone(),
        ..SceneArgs::default()
    };
    let mut section = Section::new(
        "00 · The renderer",
        "The scenes every later chapter uses, lit by direct light only (one bounce) and shaded by \
         ambient occlusion. Compare with the global illumination chapters: the ceiling of the Cornell \
         box is black under direct light, because no light reaches it in one bounce.",
    );
    let (cornell, options) = scene_args("cornell", 64).load("cornell")?;
    let p = render_to_files(&cornell, &Direct, &options, &dir, "cornell-direct", 0.0)?;
    section.figures.push(Figure::new(
        &args.out,
        &p,
        "Cornell box, direct light (max depth 2): the ceiling gets no light.",
    ));
    let (_, ao_options) = scene_args("cornell", 64).load("cornell")?;
    let p = render_to_files(
        &cornell,
        &AmbientOcclusion { distance: 0.5 },
        &ao_options,
        &dir,
        "cornell-ao",
        0.0,
    )?;
    section.figures.push(Figure::new(
        &args.out,
        &p,
        "Ambient occlusion: darkened corners and contact shadows, no lights at all.",
    ));
    let (gallery, options) = scene_args("brdf-gallery", 32).load("brdf-gallery")?;
    let p = render_to_files(
        &gallery,
        &Direct,
        &options,
        &dir,
        "brdf-gallery-direct",
        0.0,
    )?;
    section.figures.push(Figure::new(
        &args.out,
        &p,
        "The BRDF gallery: Lambert, normalized Phong (n = 1, 10, 100, 1000), mirror, glass.",
    ));
    page.sections.push(section);

    let index = page.write(&args.out)?;
    println!("open {} to see every picture", index.display());
    Ok(())
}
