//! Independent references: the images the lesson measures its renders
//! against, each with the variance of its own mean (a reference is an
//! estimate too; its noise is the floor under every error measured with it).
//!
//! - the Cornell box of Mitsuba 3 (`raytracer/tests/data/cornell-mitsuba.exr`,
//!   2048 spp, max depth 65), an independent renderer;
//! - the door and caustic scenes rendered once by our bidirectional path
//!   tracer with a seed of its own and thousands of samples per pixel, stored
//!   in `lessons/lesson11/references/` (`lesson11 references` renders them
//!   again).
//!
//! Both are stored at one size and box-filtered (each sample counts for the
//! pixel it falls in), so averaging k × k blocks gives exactly the reference
//! of an image k times smaller: the tour uses them at every size that divides
//! theirs.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use raytracer::film::Image;
use raytracer::integrator::Bdpt;
use raytracer::render::{RenderOptions, render};
use raytracer::scene::Scene;
use raytracer::scene::builtin::builtin;

/// A reference image: the mean, the variance of each pixel's mean, and where
/// it comes from.
pub struct Reference {
    pub mean: Image,
    pub variance: Image,
    /// Samples per pixel at its own size.
    pub spp: u32,
    /// Who made it, for tables: "Mitsuba 3.9.1, 2048 spp" (in English, as
    /// the CSV keeps it; [`Reference::source_here`] in the run's language).
    pub source: String,
    /// What captions call it: "Mitsuba 3's image".
    pub name: &'static str,
}

impl Reference {
    /// [`Reference::source`] in the run's language (for the console and the
    /// page; the CSV keeps the English).
    pub fn source_here(&self) -> String {
        match lang::current() {
            lang::Lang::En => self.source.clone(),
            lang::Lang::Bg => self
                .source
                .replace(
                    "our bidirectional path tracer, another seed,",
                    "нашият bidirectional path tracer, други случайни числа,",
                )
                .replace("(stored)", "(запазен)")
                .replace("(rendered now)", "(рендериран сега)"),
        }
    }

    /// The reference's own RMSE against the truth it estimates,
    /// `√(mean over pixels and channels of the variance of its mean)`: the
    /// floor an error measured against it cannot go below.
    pub fn noise_floor(&self) -> f64 {
        let sum: f64 = self
            .variance
            .pixels
            .iter()
            .map(|v| (v.x + v.y + v.z) as f64)
            .sum();
        (sum / (3 * self.variance.pixels.len()).max(1) as f64).sqrt()
    }

    /// The reference at `width`×`height`, if that divides its size by one
    /// integer factor: each pixel the mean of a k × k block, its variance the
    /// block's sum over k⁴ (independent pixels).
    pub fn at_size(&self, width: u32, height: u32) -> Option<Reference> {
        let (w, h) = (self.mean.width, self.mean.height);
        if width == 0 || w % width != 0 || height * (w / width) != h {
            return None;
        }
        let k = w / width;
        Some(Reference {
            mean: downsample(&self.mean, k, 1),
            variance: downsample(&self.variance, k, 2),
            spp: self.spp,
            source: self.source.clone(),
            name: self.name,
        })
    }
}

/// Sums `k × k` blocks and divides by `k^(2·power)`: the block mean for
/// `power = 1`, the variance of the block mean for `power = 2`.
fn downsample(image: &Image, k: u32, power: i32) -> Image {
    let scale = 1.0 / ((k * k) as f32).powi(power);
    Image::from_fn(image.width / k, image.height / k, |x, y| {
        let mut sum = raytracer::math::Color::ZERO;
        for dy in 0..k {
            for dx in 0..k {
                sum += image.get(x * k + dx, y * k + dy);
            }
        }
        sum * scale
    })
}

/// The project's folder (two above `lessons/lesson11`), where the stored
/// references live.
fn project_dir() -> PathBuf {
    let lesson = Path::new(env!("CARGO_MANIFEST_DIR"));
    lesson
        .parent()
        .and_then(Path::parent)
        .unwrap_or(lesson)
        .to_path_buf()
}

fn read(path: &Path) -> Result<Image> {
    Image::read_exr(path).with_context(|| format!("cannot read the reference {}", path.display()))
}

/// Mitsuba 3's Cornell box at 256 × 256 (max depth 65, roulette from depth 5,
/// box filter, 2048 spp), as stored for `raytracer/tests/mitsuba_cornell.rs`.
pub fn mitsuba_cornell() -> Result<Reference> {
    let dir = project_dir().join("raytracer/tests/data");
    Ok(Reference {
        mean: read(&dir.join("cornell-mitsuba.exr"))?,
        variance: read(&dir.join("cornell-mitsuba-variance.exr"))?,
        spp: 2048,
        source: "Mitsuba 3.9.1, 2048 spp".into(),
        name: lang::pick("Mitsuba 3's image", "картината на Mitsuba 3"),
    })
}

/// The settings of the stored door reference: the scene at `width`×`height`,
/// bidirectional path tracing to max depth `max_depth` with roulette from
/// the scene's depth, `spp` samples per pixel with its own `seed`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct StoredSettings {
    pub scene: String,
    /// FNV-1a hash of the built-in scene's file: a changed scene makes the
    /// stored reference stale.
    pub scene_hash: u64,
    pub width: u32,
    pub height: u32,
    pub max_depth: u32,
    pub spp: u32,
    pub seed: u64,
}

/// The door scene's reference: 128 × 96, max depth 5 (the equal-time
/// comparison's), 4096 spp, a seed no tour uses.
pub fn door_settings() -> StoredSettings {
    StoredSettings {
        scene: "door".into(),
        scene_hash: fnv1a(builtin("door").map_or("", |s| s.toml).as_bytes()),
        width: 128,
        height: 96,
        max_depth: 5,
        spp: 4096,
        seed: 0x5eed_d00e,
    }
}

/// The caustic scene's reference (chapter 9 measures the biased algorithms
/// against it): 128 × 96, max depth 8 (chapter 6's), 2048 spp, a seed no
/// tour uses. Bidirectional path tracing finds the caustic through its
/// light-tracing strategies.
pub fn caustic_settings() -> StoredSettings {
    StoredSettings {
        scene: "caustic".into(),
        scene_hash: fnv1a(builtin("caustic").map_or("", |s| s.toml).as_bytes()),
        width: 128,
        height: 96,
        max_depth: 8,
        spp: 2048,
        seed: 0x5eed_ca05,
    }
}

/// 64-bit FNV-1a.
pub fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ b as u64).wrapping_mul(0x0100_0000_01b3)
    })
}

impl StoredSettings {
    /// The files: `NAME.exr`, `NAME-variance.exr` and `NAME.txt` (these settings).
    fn paths(&self) -> [PathBuf; 3] {
        let dir = project_dir().join("lessons/lesson11/references");
        ["exr", "variance.exr", "txt"].map(|ext| {
            dir.join(match ext {
                "variance.exr" => format!("{}-variance.exr", self.scene),
                ext => format!("{}.{ext}", self.scene),
            })
        })
    }

    pub fn to_text(&self) -> String {
        format!(
            "# The {scene} scene's reference for the equal-time comparisons (lesson11 compare, biased).\n\
             # Rendered by `lesson11 references`; the tour uses it only while these settings hold.\n\
             scene = {scene}\nscene_hash = {:016x}\nwidth = {}\nheight = {}\nmax_depth = {}\n\
             spp = {}\nseed = {}\n",
            self.scene_hash,
            self.width,
            self.height,
            self.max_depth,
            self.spp,
            self.seed,
            scene = self.scene,
        )
    }

    pub fn from_text(text: &str) -> Option<StoredSettings> {
        let field = |key: &str| {
            text.lines()
                .filter(|l| !l.starts_with('#'))
                .filter_map(|l| l.split_once(" = "))
                .find(|(k, _)| k.trim() == key)
                .map(|(_, v)| v.trim().to_string())
        };
        Some(StoredSettings {
            scene: field("scene")?,
            scene_hash: u64::from_str_radix(&field("scene_hash")?, 16).ok()?,
            width: field("width")?.parse().ok()?,
            height: field("height")?.parse().ok()?,
            max_depth: field("max_depth")?.parse().ok()?,
            spp: field("spp")?.parse().ok()?,
            seed: field("seed")?.parse().ok()?,
        })
    }

    /// The stored reference, if it exists and was made with these settings;
    /// otherwise why not.
    pub fn load(&self) -> Result<Reference> {
        let [mean, variance, text] = self.paths();
        let stored = std::fs::read_to_string(&text)
            .ok()
            .and_then(|t| StoredSettings::from_text(&t));
        if stored.as_ref() != Some(self) {
            bail!(
                "the stored reference {} was not made with the current scene and settings \
                 (run `cargo run --release -p lesson11 -- references`)",
                mean.display()
            );
        }
        Ok(Reference {
            mean: read(&mean)?,
            variance: read(&variance)?,
            spp: self.spp,
            source: format!(
                "our bidirectional path tracer, another seed, {} spp (stored)",
                self.spp
            ),
            name: lang::pick("the stored reference", "запазения еталон"),
        })
    }

    /// Renders the reference and stores it with its settings (the
    /// instructor's `lesson11 references`).
    pub fn render_and_store(&self) -> Result<PathBuf> {
        let mut scene = Scene::builtin(&self.scene)?;
        scene.set_resolution(self.width, self.height);
        let bdpt = Bdpt {
            max_depth: Some(self.max_depth),
            rr_depth: scene.settings.rr_depth,
            ..Bdpt::default()
        };
        let options = RenderOptions {
            spp: self.spp,
            seed: self.seed,
            label: format!("{} reference", self.scene),
            ..RenderOptions::default()
        };
        let result = render(&scene, &bdpt, &options);
        if result.stats.interrupted {
            bail!("interrupted: the stored reference was left as it was");
        }
        let [mean, variance, text] = self.paths();
        crate::options::create_dir(mean.parent().unwrap_or(Path::new(".")))?;
        result
            .film
            .write_exr(&mean)
            .with_context(|| format!("cannot write {}", mean.display()))?;
        result
            .film
            .variance_image()
            .write_exr(&variance)
            .with_context(|| format!("cannot write {}", variance.display()))?;
        std::fs::write(&text, self.to_text())
            .with_context(|| format!("cannot write {}", text.display()))?;
        Ok(mean)
    }
}

/// A reference rendered now, when no stored one fits (another scene or
/// size): bidirectional path tracing with a different seed and `spp`
/// samples, so that its noise is independent of the renders it judges.
pub fn render_now(scene: &Scene, base: &RenderOptions, max_depth: u32, spp: u32) -> Reference {
    let bdpt = Bdpt {
        max_depth: Some(max_depth),
        rr_depth: scene.settings.rr_depth,
        ..Bdpt::default()
    };
    let options = RenderOptions {
        spp,
        seed: base.seed ^ 0x9e37_79b9_7f4a_7c15,
        progress: false,
        label: format!("{} reference", scene.name),
        ..base.clone()
    };
    let film = render(scene, &bdpt, &options).film;
    Reference {
        mean: film.image(),
        variance: film.variance_image(),
        spp,
        source: format!("our bidirectional path tracer, another seed, {spp} spp (rendered now)"),
        name: lang::pick(
            "a reference rendered now with another seed",
            "еталон, рендериран сега с други случайни числа",
        ),
    }
}

/// Mitsuba's max depth for its Cornell box reference: in practice unlimited.
pub const MITSUBA_MAX_DEPTH: u32 = 65;

/// The independent reference for the built-in scene `builtin` (`None` for a
/// scene from a file) at `scene`'s size, and the max depth every render
/// compared with it must use: Mitsuba's Cornell box (max depth 65), the
/// stored door (max depth 5) and caustic (max depth 8); for any other scene or size, or a stored
/// reference that is stale, one rendered now with another seed, at
/// `fallback_depth` and `fallback_spp` (and a note printed why).
pub fn independent(
    builtin: Option<&str>,
    scene: &Scene,
    base: &RenderOptions,
    fallback_depth: u32,
    fallback_spp: u32,
) -> (Reference, u32) {
    let (w, h) = (scene.camera.width, scene.camera.height);
    let stored = match builtin {
        Some("cornell") if scene.settings.rr_depth == 5 => {
            mitsuba_cornell().map(|r| (r, MITSUBA_MAX_DEPTH))
        }
        Some(name @ ("door" | "caustic")) => {
            let settings = if name == "door" {
                door_settings()
            } else {
                caustic_settings()
            };
            settings.load().map(|r| (r, settings.max_depth))
        }
        _ => Err(anyhow::anyhow!("no stored reference")),
    };
    match stored {
        Ok((reference, depth)) => match reference.at_size(w, h) {
            Some(r) => return (r, depth),
            None => crate::console::say!(
                "  {}",
                lang::fill(
                    lang::pick(
                        "note: the stored reference of {scene} is {rw}×{rh}, which {w}×{h} does \
                         not divide; rendering one now",
                        "бележка: запазеният еталон на {scene} е {rw}×{rh}, което {w}×{h} не \
                         дели; рендерирам нов сега",
                    ),
                    &[
                        ("scene", &scene.name),
                        ("rw", &reference.mean.width),
                        ("rh", &reference.mean.height),
                        ("w", &w),
                        ("h", &h),
                    ]
                )
            ),
        },
        Err(e) if builtin.is_some_and(|b| ["cornell", "door", "caustic"].contains(&b)) => {
            crate::console::say!(
                "  {} {e:#}; {}",
                lang::pick("note:", "бележка:"),
                lang::pick("rendering a reference now", "рендерирам еталон сега")
            )
        }
        Err(_) => {}
    }
    (
        render_now(scene, base, fallback_depth, fallback_spp),
        fallback_depth,
    )
}
