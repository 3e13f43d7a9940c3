//! Every algorithm at the same time budget, measured against one independent
//! reference: the comparison of chapter 8 (unbiased algorithms differ only
//! in their noise) and of `lesson11 bench`; Metropolis light transport joins
//! it on request. Every error here is the one of chapters 8 and 9: the RMSE
//! over the pixels off the lights ([`off_the_light`], [`masked_rmse`]).

use raytracer::film::Image;
use raytracer::integrator::{
    Bdpt, DirectStrategy, Integrator, LightTracer, NaiveRecursive, PathTracer,
};
use raytracer::render::{Metropolis, RenderOptions, render, render_metropolis};
use raytracer::scene::Scene;

use crate::reference::Reference;

/// How one algorithm renders: `spp` samples (mutations, for Metropolis) per
/// pixel in; the image, its seconds, and the part of them that does not grow
/// with `spp` (Metropolis's bootstrap) out, or `None` if Ctrl-C cut the
/// render short (its time measures nothing).
type Run<'a> = Box<dyn Fn(u32) -> Option<(Image, f64, f64)> + 'a>;

/// An integrator rendered by the pixel loop.
fn pixels<'a>(
    scene: &'a Scene,
    integrator: &'a dyn Integrator,
    base: &'a RenderOptions,
) -> Run<'a> {
    Box::new(move |spp| {
        let options = RenderOptions {
            spp,
            progress: false,
            ..base.clone()
        };
        let result = render(scene, integrator, &options);
        (!result.stats.interrupted).then(|| {
            (
                result.film.image(),
                result.stats.elapsed.as_secs_f64().max(1e-6),
                0.0,
            )
        })
    })
}

/// Metropolis light transport over `bdpt` with the default parameters;
/// the bootstrap's time counts, as a fixed cost.
fn metropolis<'a>(scene: &'a Scene, bdpt: &'a Bdpt, base: &'a RenderOptions) -> Run<'a> {
    Box::new(move |spp| {
        let options = RenderOptions {
            spp,
            progress: false,
            ..base.clone()
        };
        let result = render_metropolis(scene, bdpt, &options, &Metropolis::default());
        (!result.stats.interrupted).then(|| {
            (
                result.film.image(),
                result.stats.elapsed.as_secs_f64().max(1e-6),
                result.bootstrap_seconds,
            )
        })
    })
}

/// What [`render_for`] measures: the image, its samples per pixel, its
/// seconds and the convergence curve (seconds, RMSE).
type Measured = (Image, u32, f64, Vec<(f64, f64)>);

/// Renders with `run` for about `seconds`: renders of 1, 2, 4, … samples
/// per pixel measure the time per sample and trace the error against
/// `reference` as it falls (the convergence curve), then one render takes the
/// samples that fit the budget (after the fixed part of the time). `None`
/// if Ctrl-C cut a render short.
fn render_for(run: &Run, seconds: f64, reference: &Image, counted: &[bool]) -> Option<Measured> {
    let rmse = |image: &Image| masked_rmse(image, reference, counted);
    let mut curve = Vec::new();
    let mut spp = 1;
    let (fixed, per_spp, last) = loop {
        let (image, secs, fixed) = run(spp)?;
        curve.push((secs, rmse(&image)));
        if secs * 2.0 > seconds / 2.0 || spp >= 1 << 15 {
            let fixed = fixed.clamp(0.0, secs / 2.0);
            break (fixed, (secs - fixed) / spp as f64, (image, spp, secs));
        }
        spp *= 2;
    };
    let fitted = (((seconds - fixed) / per_spp) as u32).clamp(1, 1 << 16);
    // A budget that fits no more than the last run: that run is the
    // picture (rendering it again would only draw a second point on the first).
    let (image, spp, secs) = if fitted > last.1 {
        let (image, secs, _) = run(fitted)?;
        curve.push((secs, rmse(&image)));
        (image, fitted, secs)
    } else {
        last
    };
    // A curve of one point gets a second with twice the work, past the
    // budget, unless that would take more than twice the budget.
    if curve.len() < 2 && secs <= seconds {
        let (more, more_secs, _) = run(2 * spp)?;
        curve.push((more_secs, rmse(&more)));
    }
    curve.sort_by(|a, b| a.0.total_cmp(&b.0));
    Some((image, spp, secs, curve))
}

/// One row of an equal-time comparison.
pub struct EqualTimeRow {
    pub algorithm: &'static str,
    pub stem: String,
    pub spp: u32,
    pub seconds: f64,
    /// RMSE off the lights ([`masked_rmse`]).
    pub rmse: f64,
    pub image: Image,
    /// RMSE against time on the way (seconds, RMSE).
    pub curve: Vec<(f64, f64)>,
}

/// Seconds per algorithm at the default quality, in chapter 8 and chapter
/// 9 alike, so that their errors on the Cornell box can be read side by
/// side. Not more: the tour took 60.3 s with 0.5 s in chapter 9 (13.0 s),
/// and 59.6 s with 0.7 s in chapter 8.
pub const QUICK_SECONDS: f64 = 0.4;

/// The branching factor of naive recursion in the comparison.
pub const NAIVE_N: u32 = 4;

/// The algorithms that join path, light and bidirectional tracing in a
/// comparison.
#[derive(Clone, Copy, Debug, Default)]
pub struct Also {
    /// Naive recursion, N = 4 down to the roulette's depth, then 1.
    pub naive: bool,
    /// Metropolis light transport over bidirectional path tracing.
    pub metropolis: bool,
}

/// Renders `scene` with every algorithm for about `budget` seconds each, all
/// stopping at `max_depth` (the reference's) with Russian roulette from the
/// scene's depth, and measures each one's RMSE off the lights (the pixels
/// [`off_the_light`] counts) against `reference`, an
/// independent estimate (another renderer, or another seed): an algorithm's
/// own samples are never part of it. Naive recursion (N = 4 down to the
/// roulette's depth, then one ray per hit, ended by roulette) and
/// Metropolis light transport (over the same bidirectional tracer) join the
/// comparison as `also` says. Ctrl-C ends the comparison: the rows are
/// those measured before it, and no row is printed for what it cut short.
pub fn equal_time(
    scene: &Scene,
    base: &RenderOptions,
    budget: f64,
    reference: &Reference,
    max_depth: u32,
    also: Also,
) -> Vec<EqualTimeRow> {
    let rr_depth = scene.settings.rr_depth;
    let max_depth = Some(max_depth);
    let bdpt = Bdpt {
        max_depth,
        rr_depth,
        ..Bdpt::default()
    };
    // The full tree down to the roulette's depth, then one ray per hit: with
    // N ≥ 2 at every hit, roulette (which keeps a ray with a chance near the
    // albedo) would leave each ray more than one child on average.
    let mut branching = vec![NAIVE_N; rr_depth.saturating_sub(1).max(1) as usize];
    branching.push(1);
    let naive = NaiveRecursive::try_new(branching, max_depth, Some(rr_depth), None)
        .expect("a bounded recursion with valid branching factors");
    let path = PathTracer {
        max_depth,
        rr_depth,
        strategy: DirectStrategy::Mis,
    };
    let path_brdf = PathTracer {
        max_depth,
        rr_depth,
        strategy: DirectStrategy::BrdfOnly,
    };
    let light = LightTracer {
        max_depth,
        rr_depth,
    };
    let mut algorithms: Vec<(&'static str, &str, Run)> = vec![
        ("path (MIS)", path.name(), pixels(scene, &path, base)),
        (
            "path (BRDF only)",
            path_brdf.name(),
            pixels(scene, &path_brdf, base),
        ),
        ("light", light.name(), pixels(scene, &light, base)),
        ("bidirectional", bdpt.name(), pixels(scene, &bdpt, base)),
    ];
    if also.naive {
        let run = pixels(scene, &naive, base);
        algorithms.insert(0, ("naive recursion, N = 4 then 1", naive.name(), run));
    }
    if also.metropolis {
        let run = metropolis(scene, &bdpt, base);
        algorithms.push(("Metropolis (over bidirectional)", "mlt", run));
    }
    let counted = off_the_light(&reference.mean);
    let mut rows = Vec::new();
    for (algorithm, name, run) in algorithms {
        let Some((image, spp, seconds, curve)) =
            render_for(&run, budget, &reference.mean, &counted)
        else {
            break;
        };
        let rmse = masked_rmse(&image, &reference.mean, &counted);
        crate::console::say!(
            "  {:14} {:34} {spp:6} spp {seconds:7.2} s  RMSE {rmse:.4}",
            scene.name,
            lang::pick(algorithm, label_in_bulgarian(algorithm))
        );
        let stem = format!("{}-{name}", scene.name);
        rows.push(EqualTimeRow {
            algorithm,
            stem,
            spp,
            seconds,
            rmse,
            image,
            curve,
        });
    }
    rows
}

/// An equal-time row's label in Bulgarian: the algorithms keep the
/// lecture's English names, as on the slides; the words around them do not.
/// The rows keep their English labels (the CSV and the charts' colours
/// read them).
pub fn label_in_bulgarian(en: &str) -> &str {
    match en {
        "path (BRDF only)" => "path tracing (само BRDF)",
        "naive recursion, N = 4 then 1" => "наивна рекурсия, N = 4, после 1",
        "naive recursion" => "наивна рекурсия",
        "Metropolis (over bidirectional)" => "Metropolis (върху bidirectional)",
        other => other,
    }
}

/// The pixels an error counts: those off the lights, and not next to them —
/// a pixel is left out if its reference luminance or that of one of its
/// eight neighbours is 1 or more. A pixel at the lamp's edge sees the lamp
/// (in the Cornell box 18.6 times brighter than white) through part of its
/// area, and a few samples per pixel either hit it or miss it: its error is
/// that edge's anti-aliasing noise, the same for every algorithm and larger
/// than all else (over all pixels, path tracing's RMSE on the Cornell box
/// is three times its RMSE off the lamp).
pub fn off_the_light(reference: &Image) -> Vec<bool> {
    let (w, h) = (reference.width as i64, reference.height as i64);
    let bright = |x: i64, y: i64| {
        (0..w).contains(&x)
            && (0..h).contains(&y)
            && raytracer::math::luminance(reference.get(x as u32, y as u32)) >= 1.0
    };
    (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .map(|(x, y)| !(-1..=1).any(|dy| (-1..=1).any(|dx| bright(x + dx, y + dy))))
        .collect()
}

/// The RMSE of `a` against `b` over the `counted` pixels and all channels.
pub fn masked_rmse(a: &Image, b: &Image, counted: &[bool]) -> f64 {
    let (mut sum, mut n) = (0.0f64, 0usize);
    for ((x, y), _) in a
        .pixels
        .iter()
        .zip(&b.pixels)
        .zip(counted)
        .filter(|(_, c)| **c)
    {
        for ch in 0..3 {
            let d = (x[ch] - y[ch]) as f64;
            sum += d * d;
        }
        n += 3;
    }
    (sum / n.max(1) as f64).sqrt()
}

/// The reference's own noise floor over the `counted` pixels: √(mean
/// variance of its mean), below which no error measured against it falls.
pub fn masked_noise_floor(reference: &crate::reference::Reference, counted: &[bool]) -> f64 {
    let (mut sum, mut n) = (0.0f64, 0usize);
    for (v, _) in reference
        .variance
        .pixels
        .iter()
        .zip(counted)
        .filter(|(_, c)| **c)
    {
        sum += (v.x + v.y + v.z) as f64;
        n += 3;
    }
    (sum / n.max(1) as f64).sqrt()
}
