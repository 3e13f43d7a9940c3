//! Chapter 2 · Global illumination effects: what direct light alone misses.
//! The same Cornell box with direct light only, ambient occlusion and full
//! global illumination (path tracing) side by side; the indirect light alone
//! (their difference), where colour bleeding shows; and our path tracer
//! against Mitsuba 3's reference, tile by tile.

use anyhow::{Context, Result};
use raytracer::film::Image;
use raytracer::integrator::{AmbientOcclusion, Direct, DirectStrategy, PathTracer};
use raytracer::metrics::{z_test, z_threshold};

use crate::page::{Figure, Picture, Section};
use crate::plots::zmap_image;
use crate::reference::{MITSUBA_MAX_DEPTH, mitsuba_cornell};
use crate::render_files::{write_image, write_png_and_exr};
use crate::tour::{Chapter, ChapterOutput, Tour};

pub const CHAPTER: Chapter = Chapter::new(
    "gi-effects",
    "2 · Global illumination effects: direct light, ambient occlusion, full GI, the indirect light alone, \
     and our Cornell box against Mitsuba's",
    render,
);

/// Exposure of the indirect light alone, in stops: it is a fraction of the
/// whole, and brighter shows its tints.
const INDIRECT_EXPOSURE: f32 = 1.0;

/// Edge of the tiles of the z-map, in pixels.
const TILE: u32 = 16;

/// False-alarm probability of the whole z-map: the chance that an unbiased
/// renderer shows a tile beyond the threshold.
const ALPHA: f64 = 1e-4;

/// Chapter 2: what direct light alone misses, and the evidence that the
/// renderer's global illumination is right.
fn render(tour: &Tour) -> Result<Section> {
    let mut s = tour.chapter(
        "02-gi-effects",
        "2 · Global illumination effects",
        "Global illumination = direct illumination + indirect illumination. The same Cornell box \
         three ways. Direct light alone (max depth 2: light from the lamp after one reflection) \
         leaves the ceiling black and the shadows empty; their edges are already soft, because the \
         lamp is an area light and the penumbrae come from its size. Ambient occlusion darkens \
         corners and contact regions but knows nothing of where the light is. Full global \
         illumination (path tracing) brings the indirect light: it lights the ceiling and fills \
         the shadows (it does not soften their edges), and light reflected by a coloured wall \
         carries its colour to its neighbours (colour bleeding). Global illumination minus direct \
         light is the indirect light alone, where the red and green tints on the white boxes are \
         plain to see. Last, the evidence that the renderer computes the right picture: our path \
         tracer at Mitsuba 3's settings beside Mitsuba's own image of the same box, and between \
         them the z of every 16 × 16 tile, the difference of the means divided by its standard \
         error.",
    )?;
    let (scene, options) = tour.scene("cornell", 64)?;
    let direct = tour.picture(
        &mut s,
        &scene,
        &Direct,
        &options,
        "cornell-direct",
        "Direct light only (max depth 2): no light on the ceiling or in the shadows, whose soft \
         edges come from the size of the lamp.",
    )?;
    let ao = AmbientOcclusion { distance: 0.5 };
    tour.picture(
        &mut s,
        &scene,
        &ao,
        &options,
        "cornell-ao",
        "Ambient occlusion (rays of 0.5 m): the open fraction of the hemisphere, not light.",
    )?;
    let pt = PathTracer {
        max_depth: Some(MITSUBA_MAX_DEPTH),
        rr_depth: 5,
        strategy: DirectStrategy::Mis,
    };
    let path = tour.path_picture(
        &mut s,
        &scene,
        &pt,
        &options,
        "cornell-path",
        "Global illumination: path tracing to max depth 65 (Mitsuba's), roulette from depth 5: a \
         lit ceiling, filled shadows, colour bleeding.",
    )?;
    let (gi, direct_image) = (read(&path.exr)?, read(&direct.exr)?);
    let indirect = Image {
        pixels: gi
            .pixels
            .iter()
            .zip(&direct_image.pixels)
            .map(|(a, b)| *a - *b)
            .collect(),
        ..gi.clone()
    };
    let picture = write_image(
        &s.dir,
        "cornell-indirect",
        &indirect,
        options.spp,
        INDIRECT_EXPOSURE,
        None,
    )?;
    s.section.figures.push(Figure::new(
        &tour.out,
        &picture,
        "The indirect light alone: global illumination minus direct light (both pictures above, \
         their noise added). Red on the left faces of the boxes, green on the right, light on the \
         ceiling and in the shadows.",
    ));
    if tour.overrides.scene.is_none() {
        against_mitsuba(tour, &mut s, &gi, &path)?;
    }
    Ok(s.section)
}

fn read(path: &std::path::Path) -> Result<Image> {
    Image::read_exr(path).with_context(|| format!("cannot read back {}", path.display()))
}

/// Ours beside Mitsuba's reference and the tile z-map between them.
fn against_mitsuba(tour: &Tour, s: &mut ChapterOutput, ours: &Image, path: &Picture) -> Result<()> {
    let variance_path = path.exr.with_file_name("cornell-path-variance.exr");
    let ours_variance = read(&variance_path)?;
    let reference = match mitsuba_cornell() {
        Ok(r) => r,
        Err(e) => {
            crate::console::say!(
                "{}",
                lang::pick(
                    format!("  note: {e:#}; no comparison with Mitsuba"),
                    format!("  бележка: {e:#}; няма сравнение с Mitsuba"),
                )
            );
            return Ok(());
        }
    };
    let (w, h) = (ours.width, ours.height);
    let Some(mitsuba) = reference.at_size(w, h) else {
        let (mw, mh) = (reference.mean.width, reference.mean.height);
        crate::console::say!(
            "{}",
            lang::pick(
                format!("  note: Mitsuba's image is {mw}×{mh}, which {w}×{h} does not divide: no comparison"),
                format!("  бележка: картината на Mitsuba е {mw}×{mh}, а {w}×{h} не я дели: няма сравнение"),
            )
        );
        return Ok(());
    };
    let ours_picture = write_image(&s.dir, "cornell-ours", ours, path.spp, 0.0, path.seconds)?;
    s.section.figures.push(Figure::new(
        &tour.out,
        &ours_picture,
        "Ours: path tracing at Mitsuba's settings (max depth 65, roulette from depth 5, box \
         filter), the picture above.",
    ));
    let mitsuba_picture = write_image(
        &s.dir,
        "cornell-mitsuba",
        &mitsuba.mean,
        reference.spp,
        0.0,
        None,
    )?;
    let size = if (reference.mean.width, reference.mean.height) == (w, h) {
        String::new()
    } else {
        format!(
            " at {}×{}, averaged down to {w}×{h}",
            reference.mean.width, reference.mean.height
        )
    };
    s.section.figures.push(Figure::new(
        &tour.out,
        &mitsuba_picture,
        &format!(
            "Mitsuba 3's path tracer on its own mitsuba.cornell_box(): {}{size}, the same depth, \
             roulette and filter, tone-mapped like ours.",
            reference.source
        ),
    ));
    let z = z_test(ours, &ours_variance, &mitsuba.mean, &mitsuba.variance, TILE);
    let tests = z.z.len() * 3;
    let threshold = z_threshold(tests, ALPHA) as f32;
    let scale = threshold.ceil().max(z.max_abs_z.min(2.0 * threshold).ceil());
    let map = zmap_image(&z, w, h, scale, threshold);
    let (png, exr) = write_png_and_exr(&map, &s.dir, "cornell-zmap", 0.0)?;
    let verdict = if z.max_abs_z < threshold {
        "below the threshold: every difference is what noise explains"
    } else {
        "above the threshold: a bias, or too few samples for the test's normal approximation"
    };
    crate::console::say!(
        "  ours against Mitsuba: largest |z| {:.2} in tile {} of {} z-scores, threshold {threshold:.2}",
        z.max_abs_z, z.worst_tile, tests
    );
    s.section.figures.push(Figure::image(
        &tour.out,
        &png,
        &exr,
        format!(
            "z = (m − m_ref)/√(v + v_ref) of every {TILE} × {TILE} tile between ours and Mitsuba's \
             (per tile the channel with the largest |z|; m: the tile's mean, v: the variance of that \
             mean, from both renders' variance images). Colour scale, the bar below: blue z = −{scale}, \
             white 0, red +{scale}, a tick at every whole z and long ticks at ±{threshold:.2}, the \
             threshold that {tests} z-scores of unbiased renders all stay within with probability \
             1 − 10⁻⁴. Largest |z| = {:.2} (tile {}, {}): {verdict}.",
            z.max_abs_z, z.worst_tile.x, z.worst_tile.y
        ),
    ));
    Ok(())
}
