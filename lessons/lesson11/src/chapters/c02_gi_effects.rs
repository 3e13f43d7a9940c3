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
        lang::pick(
            "2 · Global illumination effects",
            "2 · Ефекти на глобалното осветление",
        ),
        lang::pick(
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
        "Глобално осветление = директно осветление + индиректно осветление. Една и съща Cornell \
         box по три начина. Само директната светлина (максимална дълбочина 2: светлината на \
         лампата след едно отражение) оставя тавана черен, а сенките – празни; ръбовете им вече \
         са меки, защото лампата е площна и полусенките идват от размера ѝ. Ambient occlusion \
         затъмнява ъглите и местата на допир, но не знае нищо за това къде е светлината. \
         Пълното глобално осветление (path tracing) добавя индиректната светлина: тя осветява \
         тавана и запълва сенките (без да омекотява ръбовете им), а светлината, отразена от \
         цветна стена, пренася цвета ѝ върху съседните повърхности (преливане на цветовете, \
         color bleeding). Глобалното осветление минус директното е само индиректната светлина, \
         където червеният и зеленият оттенък върху белите кутии се виждат ясно. Накрая – \
         доказателството, че рендерерът смята правилната картина: нашият path tracing с \
         настройките на Mitsuba 3 до собствената картина на Mitsuba на същата кутия, а между \
         тях z за всяко парче 16 × 16 – разликата на средните, разделена на стандартната ѝ \
         грешка.",
        ),
    )?;
    let (scene, options) = tour.scene("cornell", 64)?;
    let direct = tour.picture(
        &mut s,
        &scene,
        &Direct,
        &options,
        "cornell-direct",
        lang::pick(
            "Direct light only (max depth 2): no light on the ceiling or in the shadows, whose soft \
             edges come from the size of the lamp.",
            "Само директна светлина (максимална дълбочина 2): няма светлина по тавана и в сенките, \
             чиито меки ръбове идват от размера на лампата.",
        ),
    )?;
    let ao = AmbientOcclusion { distance: 0.5 };
    tour.picture(
        &mut s,
        &scene,
        &ao,
        &options,
        "cornell-ao",
        lang::pick(
            "Ambient occlusion (rays of 0.5 m): the open fraction of the hemisphere, not light.",
            "Ambient occlusion (лъчи с дължина 0.5 m): отворената част от полусферата, не светлина.",
        ),
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
        lang::pick(
            "Global illumination: path tracing to max depth 65 (Mitsuba's), roulette from depth 5: \
             a lit ceiling, filled shadows, colour bleeding.",
            "Глобално осветление: path tracing до максимална дълбочина 65 (тази на Mitsuba), руска \
             рулетка от дълбочина 5: осветен таван, запълнени сенки, преливане на цветовете.",
        ),
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
        lang::pick(
            "The indirect light alone: global illumination minus direct light (both pictures \
             above, their noise added). Red on the left faces of the boxes, green on the right, \
             light on the ceiling and in the shadows.",
            "Само индиректната светлина: глобалното осветление минус директното (двете картини \
             отгоре, шумът им се събира). Червено по левите стени на кутиите, зелено по десните, \
             светлина по тавана и в сенките.",
        ),
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
        lang::pick(
            "Ours: path tracing at Mitsuba's settings (max depth 65, roulette from depth 5, box \
             filter), the picture above.",
            "Нашата: path tracing с настройките на Mitsuba (максимална дълбочина 65, руска рулетка \
             от дълбочина 5, box филтър) – картината отгоре.",
        ),
    ));
    let mitsuba_picture = write_image(
        &s.dir,
        "cornell-mitsuba",
        &mitsuba.mean,
        reference.spp,
        0.0,
        None,
    )?;
    let (mw, mh) = (reference.mean.width, reference.mean.height);
    let size = if (mw, mh) == (w, h) {
        String::new()
    } else {
        lang::pick(
            format!(" at {mw}×{mh}, averaged down to {w}×{h}"),
            format!(" с размер {mw}×{mh}, усреднена до {w}×{h}"),
        )
    };
    let source = &reference.source_here();
    s.section.figures.push(Figure::new(
        &tour.out,
        &mitsuba_picture,
        &lang::pick(
            format!(
                "Mitsuba 3's path tracer on its own mitsuba.cornell_box(): {source}{size}, the \
                 same depth, roulette and filter, tone-mapped like ours."
            ),
            format!(
                "Path tracing на Mitsuba 3 върху собствената ѝ mitsuba.cornell_box(): \
                 {source}{size}, същата дълбочина, рулетка и филтър, превърната в PNG по същия \
                 начин като нашата."
            ),
        ),
    ));
    let z = z_test(ours, &ours_variance, &mitsuba.mean, &mitsuba.variance, TILE);
    let tests = z.z.len() * 3;
    let threshold = z_threshold(tests, ALPHA) as f32;
    let scale = threshold.ceil().max(z.max_abs_z.min(2.0 * threshold).ceil());
    let map = zmap_image(&z, w, h, scale, threshold);
    let (png, exr) = write_png_and_exr(&map, &s.dir, "cornell-zmap", 0.0)?;
    let verdict = if z.max_abs_z < threshold {
        lang::pick(
            "below the threshold: every difference is what noise explains",
            "под прага: всяка разлика се обяснява с шума",
        )
    } else {
        lang::pick(
            "above the threshold: a bias, or too few samples for the test's normal approximation",
            "над прага: отместване или твърде малко проби за нормалното приближение на теста",
        )
    };
    let (largest, tile) = (z.max_abs_z, z.worst_tile);
    crate::console::say!(
        "{}",
        lang::pick(
            format!(
                "  ours against Mitsuba: largest |z| {largest:.2} in tile {tile} of {tests} z-scores, threshold {threshold:.2}"
            ),
            format!(
                "  нашата срещу Mitsuba: най-голямото |z| {largest:.2} в парчето {tile} от {tests} стойности на z, праг {threshold:.2}"
            ),
        )
    );
    s.section.figures.push(Figure::image(
        &tour.out,
        &png,
        &exr,
        {
            let (x, y) = (z.worst_tile.x, z.worst_tile.y);
            lang::pick(
                format!(
                    "z = (m − m_ref)/√(v + v_ref) of every {TILE} × {TILE} tile between ours and \
                     Mitsuba's (per tile the channel with the largest |z|; m: the tile's mean, v: \
                     the variance of that mean, from both renders' variance images). Colour \
                     scale, the bar below: blue z = −{scale}, white 0, red +{scale}, a tick at \
                     every whole z and long ticks at ±{threshold:.2}, the threshold that {tests} \
                     z-scores of unbiased renders all stay within with probability 1 − 10⁻⁴. \
                     Largest |z| = {largest:.2} (tile {x}, {y}): {verdict}."
                ),
                format!(
                    "z = (m − m_ref)/√(v + v_ref) за всяко парче {TILE} × {TILE} между нашата \
                     картина и тази на Mitsuba (за всяко парче – каналът с най-голямо |z|; m: \
                     средното на парчето, v: дисперсията на това средно, от картините на \
                     дисперсията на двата рендера). Цветова скала, лентата отдолу: синьо z = \
                     −{scale}, бяло 0, червено +{scale}, чертичка при всяко цяло z и дълги \
                     чертички при ±{threshold:.2} – прагът, в който {tests} стойности на z от \
                     неотместени рендери остават всички с вероятност 1 − 10⁻⁴. Най-голямото |z| = \
                     {largest:.2} (парче {x}, {y}): {verdict}."
                ),
            )
        },
    ));
    Ok(())
}
