//! Chapter 9 · The lecture's split of the GI algorithms into unbiased and
//! biased, measured: the taxonomy as pictures at equal time, each
//! algorithm's error split into bias² and variance over independent seeds,
//! RMSE against time, and pictures that name each biased algorithm's bias.

use std::sync::atomic::AtomicBool;

use anyhow::{Result, anyhow};
use raytracer::film::Image;
use raytracer::integrator::{
    IrradianceCache, IrradianceCacheSettings, PhotonMapping, PhotonSettings,
};
use raytracer::math::{Color, Vec2};
use raytracer::metrics::mean;
use raytracer::render::RenderOptions;
use raytracer::scene::Scene;

use crate::algorithms::{Algorithm, Knobs, Prepared, Run};
use crate::page::{Figure, Section, Table, seconds_number, seconds_text};
use crate::plots::{Bars, Chart, Scale, Series};
use crate::reference::{Reference, independent};
use crate::render_files::write_image;
use crate::tour::{Chapter, ChapterOutput, Quality, Tour};

pub const CHAPTER: Chapter = Chapter::new(
    "biased",
    "9 · Unbiased and biased at equal time: photon mapping, SPPM, instant radiosity, irradiance caching",
    render,
);

/// How hard the chapter works at each quality.
struct Effort {
    /// Seconds per algorithm for the equal-time pictures.
    budget: f64,
    /// Independent seeds for the bias–variance split.
    seeds: u64,
    /// Light paths of the photon maps that show the blur (little noise).
    blur_photons: u64,
    /// Photon mapping's light paths on the caustic scene (its caustic is a
    /// small spot: the k nearest of fewer photons blur it away).
    caustic_photons: u64,
    knobs: Knobs,
}

fn effort(quality: Quality) -> Effort {
    let knobs = |photons, sppm_photons, vpl_paths| Knobs {
        photons,
        sppm_photons,
        vpl_paths,
        clamp: VPL_CLAMP,
        ic_error: 0.3,
        ic_rays: 64,
    };
    match quality {
        Quality::Tiny => Effort {
            budget: 0.02,
            seeds: 2,
            blur_photons: 5_000,
            caustic_photons: 2_000,
            knobs: knobs(2_000, 1_000, 8),
        },
        Quality::Quick => Effort {
            budget: 0.15,
            seeds: 4,
            blur_photons: 50_000,
            caustic_photons: 50_000,
            knobs: knobs(10_000, 5_000, 32),
        },
        Quality::Full => Effort {
            budget: 2.0,
            seeds: 8,
            blur_photons: 1_000_000,
            caustic_photons: 400_000,
            knobs: knobs(200_000, 20_000, 128),
        },
    }
}

/// The bound on instant radiosity's geometry term in the chapter.
const VPL_CLAMP: f32 = 0.5;
/// Exposure of the difference images, in stops.
const DIFFERENCE_EXPOSURE: f32 = 2.0;

/// Chapter 9: unbiased and biased, at equal time.
fn render(tour: &Tour) -> Result<Section> {
    let e = effort(tour.quality);
    let k = e.knobs;
    let mut c = tour.chapter(
        "09-biased",
        "9 · Unbiased and biased algorithms",
        &format!(
            "The lecture splits the GI algorithms in two. Unbiased ones (path tracing, light tracing, \
             bidirectional, Metropolis): their error is only noise, and it falls as 1/√t. Biased ones \
             (photon mapping, irradiance caching, instant radiosity): they can give a picture without \
             noise whose error does not go away — smooth but wrong, and sooner. Here each algorithm gets \
             the same time (about {} each; every time below includes building the photon maps, virtual \
             point lights or cache records) on the Cornell box, measured against Mitsuba 3's image, and on \
             the caustic scene, measured against a stored bidirectional render with thousands of samples. \
             Photon mapping: {} light paths ({} on the caustic scene, whose caustic is a small \
             spot), the 50 nearest photons under an Epanechnikov kernel. SPPM: \
             {} photon paths per pass, radii shrinking with α = 2/3 (consistent: its bias falls with \
             the passes). Instant radiosity: the VPLs of {} light paths, the geometry term clamped at \
             {VPL_CLAMP}. Irradiance caching: a = {}, {} rays per record. The error of each algorithm is \
             split into bias² (of the mean of {} runs with independent seeds) and variance (their \
             spread).",
            seconds_text(e.budget),
            k.photons,
            e.caustic_photons,
            k.sppm_photons,
            k.vpl_paths,
            k.ic_error,
            k.ic_rays,
            e.seeds
        ),
    )?;
    let mut table = Table::new(
        "Equal time on the Cornell box: error against Mitsuba 3's image, split into bias² and variance",
        &[
            "algorithm",
            "unbiased",
            "spp",
            "seconds",
            "RMSE",
            "bias²",
            "variance",
            "first time RMSE ≤ target",
        ],
    );

    // The Cornell box: the curves, the grid, bias and variance.
    let (mut scene, mut base) = tour.scene("cornell", 1)?;
    if tour.quality != Quality::Tiny {
        scene.set_resolution(64, 64);
    }
    base.progress = false;
    let builtin = tour.overrides.scene.is_none().then_some("cornell");
    let (reference, max_depth) = independent(builtin, &scene, &base, 5, 256);
    let floor = reference.noise_floor();
    crate::console::say!(
        "  {} {}×{}: max depth {max_depth}, reference {} (noise floor {floor:.5})",
        scene.name,
        scene.camera.width, scene.camera.height, reference.source
    );
    // The lamp and the pixels that see part of it are left out of every
    // error: theirs is the anti-aliasing noise of an edge 18.6 times brighter
    // than white, the same for every algorithm.
    let counted = off_the_light(&reference.mean);
    let mut measured = Vec::new();
    for algorithm in Algorithm::ALL {
        let m = measure(&scene, &base, algorithm, &k, max_depth, &reference, &counted, &e)?;
        crate::console::say!(
            "  {} {:20} {:5} spp {:>8} (build {:>8})  RMSE {:.4}  bias² {:.2e}  variance {:.2e}",
            scene.name,
            algorithm.label(),
            m.run.spp,
            seconds_text(m.run.seconds),
            seconds_text(m.build_seconds),
            m.rmse,
            m.bias2,
            m.variance
        );
        measured.push(m);
    }
    // The target: halfway (log) between the best and the worst error at
    // equal time, so that some reach it early, some late and some never.
    let (best, worst) = measured
        .iter()
        .fold((f64::MAX, 0.0f64), |(b, w), m| (b.min(m.rmse), w.max(m.rmse)));
    let target = (best * worst).sqrt();
    let mut series = Vec::new();
    for m in &measured {
        let reached = first_time_below(&m.curve, target);
        let unbiased = m.algorithm.unbiased();
        let picture = write_image(
            &c.dir,
            &format!("{}-{}", scene.name, m.algorithm.stem()),
            &m.run.image,
            m.run.spp,
            0.0,
            Some(m.run.seconds),
        )?;
        c.section.figures.push(Figure::new(
            &tour.out,
            &picture,
            &format!(
                "Cornell box, {} ({}), equal time: RMSE {:.4} against {}, off the lamp.",
                m.algorithm.label(),
                if unbiased { "unbiased" } else { "biased" },
                m.rmse,
                reference.name
            ),
        ));
        table.rows.push(vec![
            m.algorithm.label().into(),
            if unbiased { "yes" } else { "no" }.into(),
            m.run.spp.to_string(),
            seconds_number(m.run.seconds),
            format!("{:.5}", m.rmse),
            format!("{:.3e}", m.bias2),
            format!("{:.3e}", m.variance),
            reached.map_or_else(
                || format!("not within {}", seconds_text(m.run.seconds)),
                seconds_number,
            ),
        ]);
        series.push(Series {
            label: m.algorithm.label().into(),
            points: m.curve.clone(),
        });
    }
    let times = measured.iter().flat_map(|m| m.curve.iter().map(|p| p.0));
    let (t0, t1) = times.fold((f64::MAX, 0.0f64), |(a, b), t| (a.min(t), b.max(t)));
    series.push(Series {
        label: "target".into(),
        points: vec![(t0, target), (t1, target)],
    });
    let chart = Chart {
        title: "Cornell box: error against time".into(),
        x_label: "seconds (build included)".into(),
        y_label: "RMSE".into(),
        x_scale: Scale::Log,
        y_scale: Scale::Log,
        series,
    };
    let svg = c.dir.join(format!("{}-rmse-time.svg", scene.name));
    chart.write(&svg)?;
    c.section.figures.push(Figure::plot(
        &tour.out,
        &svg,
        &format!(
            "RMSE against time, log–log, against {} (off the lamp), each point a run of its own: \
             path tracing and bidirectional fall as t^−1/2, all the way to zero; photon mapping, \
             clamped instant radiosity and irradiance caching build once and then start lower and \
             fall more slowly, towards the floor their bias sets (the table's bias²); SPPM, \
             consistent, keeps falling. The flat line is a target RMSE, {target:.4} (halfway, \
             log, between the best and the worst at equal time); the table gives the time each \
             algorithm first reaches it.",
            reference.name
        ),
    ));
    let bars = Bars {
        title: format!("Cornell box: bias² and variance at equal time ({} seeds)", e.seeds),
        y_label: "mean squared error".into(),
        parts: vec!["bias²".into(), "variance".into()],
        bars: measured
            .iter()
            .map(|m| (m.algorithm.label().to_string(), vec![m.bias2, m.variance]))
            .collect(),
    };
    let svg = c.dir.join(format!("{}-bias-variance.svg", scene.name));
    bars.write(&svg)?;
    c.section.figures.push(Figure::plot(
        &tour.out,
        &svg,
        &format!(
            "Bias² and variance per algorithm at equal time ({} each at half the budget), from {} \
             runs with independent seeds: variance is their spread per pixel, bias² the squared error \
             of their mean image against {}, less the part the spread and the reference's own noise \
             (floor {floor:.5}) explain.",
            seconds_text(e.budget / 2.0),
            e.seeds,
            reference.name
        ),
    ));

    // The bias, named.
    photon_blur(
        tour,
        &mut c,
        (&scene, &base, max_depth),
        &reference,
        e.blur_photons,
        0.15,
        "the blur is brightest along the edges and in the corners, where the disk reaches onto the \
         neighbouring wall and averages its light in",
    )?;
    let vpl = &measured[4];
    let unclamped = Knobs { clamp: 0.0, ..k };
    let prepared = Algorithm::Vpl
        .prepare(&scene, &unclamped, max_depth, base.seed)
        .map_err(|e| anyhow!(e))?;
    let full = prepared.run(&scene, &base, vpl.run.spp);
    let (lost, total) = (mean(&full.image) - mean(&vpl.run.image), mean(&full.image));
    difference(
        tour,
        &mut c,
        &format!("{}-vpl-clamping", scene.name),
        &full.image,
        &vpl.run.image,
        vpl.run.spp,
        &format!(
            "What clamping G at {VPL_CLAMP} removes: unclamped minus clamped instant radiosity, the \
             same VPLs. The light lost sits in the corners and along the edges, where a VPL is close \
             to the point it lights; the clamped image is {:.1}% darker overall.",
            100.0 * luminance(lost) / luminance(total).max(1e-9)
        ),
    )?;
    irradiance_records(tour, &mut c, (&scene, &base, max_depth), &k, &reference, &counted)?;

    // The caustic scene: the grid at equal time.
    let (mut scene, mut base) = tour.scene("caustic", 1)?;
    if tour.quality != Quality::Tiny {
        scene.set_resolution(64, 48);
    }
    base.progress = false;
    let (reference, max_depth) = independent(Some("caustic"), &scene, &base, 8, 256);
    crate::console::say!(
        "  caustic {}×{}: max depth {max_depth}, reference {}",
        scene.camera.width, scene.camera.height, reference.source
    );
    let everywhere = vec![true; reference.mean.pixels.len()];
    let caustic_knobs = Knobs {
        photons: e.caustic_photons,
        ..k
    };
    for algorithm in Algorithm::ALL {
        let prepared = algorithm
            .prepare(&scene, &caustic_knobs, max_depth, base.seed)
            .map_err(|e| anyhow!(e))?;
        let (run, _) = equal_time(&prepared, &scene, &base, e.budget, |image| {
            masked_rmse(image, &reference.mean, &everywhere)
        });
        let error = masked_rmse(&run.image, &reference.mean, &everywhere);
        crate::console::say!(
            "  caustic {:20} {:5} spp {:>8}  RMSE {error:.4}",
            algorithm.label(),
            run.spp,
            seconds_text(run.seconds)
        );
        let picture = write_image(
            &c.dir,
            &format!("caustic-{}", algorithm.stem()),
            &run.image,
            run.spp,
            0.0,
            Some(run.seconds),
        )?;
        c.section.figures.push(Figure::new(
            &tour.out,
            &picture,
            &format!(
                "Caustic scene, {}, equal time: RMSE {error:.4} against {}.",
                algorithm.label(),
                reference.name
            ),
        ));
    }
    photon_blur(
        tour,
        &mut c,
        (&scene, &base, max_depth),
        &reference,
        e.blur_photons,
        0.15,
        "the caustic is spread over the disk: too dim in its centre, too bright around its edge",
    )?;
    table.caption = format!(
        "{}; errors over the pixels off the lamp (its edge is anti-aliasing noise 18.6 times \
         brighter than white, the same for all); target RMSE {target:.4}.",
        table.caption
    );
    table.write_csv(&c.dir.join("biased.csv"))?;
    c.section.tables.push(table);
    Ok(c.section)
}

/// One algorithm measured on one scene.
struct Measured {
    algorithm: Algorithm,
    /// The equal-time run.
    run: Run,
    rmse: f64,
    /// (seconds, RMSE) of runs with doubling work.
    curve: Vec<(f64, f64)>,
    bias2: f64,
    variance: f64,
    build_seconds: f64,
}

/// Runs `algorithm` with doubling work until the next run would pass the
/// budget (the curve), then once at the work that fits the budget (the
/// picture), then `effort.seeds` times with independent seeds at half the
/// budget (bias² and variance).
#[allow(clippy::too_many_arguments)]
fn measure(
    scene: &Scene,
    base: &RenderOptions,
    algorithm: Algorithm,
    knobs: &Knobs,
    max_depth: u32,
    reference: &Reference,
    counted: &[bool],
    effort: &Effort,
) -> Result<Measured> {
    let error = |image: &Image| masked_rmse(image, &reference.mean, counted);
    let prepared = algorithm
        .prepare(scene, knobs, max_depth, base.seed)
        .map_err(|e| anyhow!(e))?;
    let (run, curve) = equal_time(&prepared, scene, base, effort.budget, error);
    let half = prepared.fit(run.spp, run.seconds, effort.budget / 2.0);
    let images: Vec<Image> = (0..effort.seeds)
        .map(|s| {
            let seed = base.seed.wrapping_add(1 + s).wrapping_mul(0x9e37_79b9);
            let p: Prepared = algorithm
                .prepare(scene, knobs, max_depth, seed)
                .map_err(|e| anyhow!(e))?;
            Ok(p.run(scene, base, half).image)
        })
        .collect::<Result<_>>()?;
    let (bias2, variance) = bias_and_variance(&images, reference, counted);
    Ok(Measured {
        algorithm,
        rmse: error(&run.image),
        run,
        curve,
        bias2,
        variance,
        build_seconds: prepared.build_seconds,
    })
}

/// Runs `prepared` with doubling work until the next run would pass
/// `budget` (the curve of (seconds, `error`)), then once at the work that
/// fits the budget: the equal-time run and the curve, in time order.
fn equal_time(
    prepared: &Prepared,
    scene: &Scene,
    base: &RenderOptions,
    budget: f64,
    error: impl Fn(&Image) -> f64,
) -> (Run, Vec<(f64, f64)>) {
    let mut curve = Vec::new();
    let mut n = 1;
    let last = loop {
        let run = prepared.run(scene, base, n);
        curve.push((run.seconds, error(&run.image)));
        if run.seconds * 2.0 > budget || n >= 1 << 14 {
            break run;
        }
        n *= 2;
    };
    let fitted = prepared.fit(last.spp, last.seconds, budget);
    let run = if fitted > last.spp {
        let run = prepared.run(scene, base, fitted);
        curve.push((run.seconds, error(&run.image)));
        run
    } else {
        last
    };
    curve.sort_by(|a, b| a.0.total_cmp(&b.0));
    (run, curve)
}

/// Bias² and variance of `images` (independent runs) against `reference`,
/// averaged over pixels and channels. The variance is the unbiased sample
/// variance per pixel; the squared error of the mean image holds, besides
/// the bias², the variance of that mean (variance / K) and the reference's
/// own, so both are subtracted (and the result kept ≥ 0).
fn bias_and_variance(images: &[Image], reference: &Reference, counted: &[bool]) -> (f64, f64) {
    let k = images.len() as f64;
    let (mut bias2, mut variance) = (0.0f64, 0.0f64);
    let pixels = reference.mean.pixels.len();
    for p in (0..pixels).filter(|&p| counted[p]) {
        for ch in 0..3 {
            let values: Vec<f64> = images.iter().map(|i| i.pixels[p][ch] as f64).collect();
            let m = values.iter().sum::<f64>() / k;
            let v = values.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / (k - 1.0).max(1.0);
            let d = m - reference.mean.pixels[p][ch] as f64;
            bias2 += d * d - v / k - reference.variance.pixels[p][ch] as f64;
            variance += v;
        }
    }
    let n = (3 * counted.iter().filter(|&&c| c).count()).max(1) as f64;
    ((bias2 / n).max(0.0), variance / n)
}

/// The pixels an error counts: those whose reference luminance is below 1
/// (not the lamp, nor a pixel that sees part of it).
fn off_the_light(reference: &Image) -> Vec<bool> {
    reference.pixels.iter().map(|&c| luminance(c) < 1.0).collect()
}

/// The RMSE over the `counted` pixels and all channels.
fn masked_rmse(a: &Image, b: &Image, counted: &[bool]) -> f64 {
    let (mut sum, mut n) = (0.0f64, 0usize);
    for ((x, y), _) in a.pixels.iter().zip(&b.pixels).zip(counted).filter(|(_, c)| **c) {
        for ch in 0..3 {
            let d = (x[ch] - y[ch]) as f64;
            sum += d * d;
        }
        n += 3;
    }
    (sum / n.max(1) as f64).sqrt()
}

/// The first time a curve reaches `target`, interpolated log–log between
/// its points (`None` if it never does).
fn first_time_below(curve: &[(f64, f64)], target: f64) -> Option<f64> {
    let i = curve.iter().position(|&(_, e)| e <= target)?;
    if i == 0 {
        return Some(curve[0].0);
    }
    let ((t0, e0), (t1, e1)) = (curve[i - 1], curve[i]);
    let f = (target.ln() - e0.ln()) / (e1.ln() - e0.ln());
    Some((t0.ln() + f * (t1.ln() - t0.ln())).exp())
}

fn luminance(c: Color) -> f32 {
    raytracer::math::luminance(c)
}

/// Writes |a − b| at [`DIFFERENCE_EXPOSURE`] and adds it to the chapter.
fn difference(
    tour: &Tour,
    c: &mut ChapterOutput,
    stem: &str,
    a: &Image,
    b: &Image,
    spp: u32,
    caption: &str,
) -> Result<()> {
    let diff = Image::from_fn(a.width, a.height, |x, y| (a.get(x, y) - b.get(x, y)).abs());
    let picture = write_image(&c.dir, stem, &diff, spp, DIFFERENCE_EXPOSURE, None)?;
    c.section
        .figures
        .push(Figure::new(&tour.out, &picture, caption));
    Ok(())
}

/// Photon mapping with many photons and a fixed search `radius` (little
/// noise, so that the blur shows), and its error against `reference`.
fn photon_blur(
    tour: &Tour,
    c: &mut ChapterOutput,
    (scene, base, max_depth): (&Scene, &RenderOptions, u32),
    reference: &Reference,
    photons: u64,
    radius: f32,
    what: &str,
) -> Result<()> {
    let start = std::time::Instant::now();
    let pm = PhotonMapping::build(
        scene,
        PhotonSettings {
            photons,
            radius: Some(radius),
            max_depth: Some(max_depth),
            rr_depth: scene.settings.rr_depth,
            seed: base.seed,
            ..PhotonSettings::default()
        },
        &AtomicBool::new(false),
    )
    .map_err(|e| anyhow!(e))?;
    let options = RenderOptions {
        spp: 16,
        progress: false,
        ..base.clone()
    };
    let image = raytracer::render::render(scene, &pm, &options).film.image();
    let seconds = start.elapsed().as_secs_f64();
    let name = &scene.name;
    let picture = write_image(
        &c.dir,
        &format!("{name}-photon-blur"),
        &image,
        options.spp,
        0.0,
        Some(seconds),
    )?;
    c.section.figures.push(Figure::new(
        &tour.out,
        &picture,
        &format!(
            "{name}, photon mapping with {photons} light paths and a fixed search radius of \
             {radius}: little noise, so the blur shows."
        ),
    ));
    difference(
        tour,
        c,
        &format!("{name}-photon-error"),
        &image,
        &reference.mean,
        options.spp,
        &format!(
            "{name}, |photon mapping − {}| of the picture before: {what}.",
            reference.name
        ),
    )
}

/// Irradiance caching at three thresholds `a`: the records as red dots over
/// each picture, and the error growing with `a`.
fn irradiance_records(
    tour: &Tour,
    c: &mut ChapterOutput,
    (scene, base, max_depth): (&Scene, &RenderOptions, u32),
    knobs: &Knobs,
    reference: &Reference,
    counted: &[bool],
) -> Result<()> {
    let spp = 4;
    for a in [0.15f32, 0.3, 0.6] {
        let start = std::time::Instant::now();
        let cache = IrradianceCache::build(
            scene,
            IrradianceCacheSettings {
                error: a,
                rays: knobs.ic_rays,
                max_depth: Some(max_depth),
                rr_depth: scene.settings.rr_depth,
                seed: base.seed,
                gradients: false,
            },
            &AtomicBool::new(false),
        )
        .map_err(|e| anyhow!(e))?;
        let options = RenderOptions {
            spp,
            progress: false,
            ..base.clone()
        };
        let r = raytracer::render::render(scene, &cache, &options);
        let seconds = start.elapsed().as_secs_f64();
        let image = r.film.image();
        let error = masked_rmse(&image, &reference.mean, counted);
        let mut dots = image.clone();
        let first = cache.records().iter().map(|r| r.depth).min().unwrap_or(1);
        let lens = scene.camera.position();
        let mut shown = 0;
        for record in cache.records().iter().filter(|r| r.depth == first) {
            if let Some(Vec2 { x, y }) = scene.camera.raster_of(record.p, lens) {
                dots.set(x as u32, y as u32, Color::new(1.0, 0.05, 0.05));
                shown += 1;
            }
        }
        let stem = format!("{}-ic-a{a:.2}", scene.name);
        let picture = write_image(&c.dir, &stem, &image, spp, 0.0, Some(seconds))?;
        c.section.figures.push(Figure::new(
            &tour.out,
            &picture,
            &format!(
                "Irradiance caching, a = {a}: {} records, RMSE {error:.4} against {} off the lamp; a larger a \
                 lets each record cover more, and its interpolation shows as blotches.",
                cache.records().len(),
                reference.name
            ),
        ));
        let picture = write_image(&c.dir, &format!("{stem}-records"), &dots, spp, 0.0, None)?;
        c.section.figures.push(Figure::new(
            &tour.out,
            &picture,
            &format!(
                "Irradiance caching, a = {a}: the {shown} records seen from the camera as red dots, \
                 dense where the irradiance changes fast (corners, edges), sparse on open walls."
            ),
        ));
    }
    Ok(())
}
