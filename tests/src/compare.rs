//! Whole integrators against a stored reference, tile by tile: the student's
//! integrator is rendered at a small size with a fixed seed, and each tile's
//! mean is compared with the reference's (the renderer's own integrator at
//! many samples, stored as mean and variance EXR in `tests/references/`) by a
//! z-test that uses both variances ([`raytracer::metrics::z_test`]). On
//! failure the two pictures and a map of the tiles' |z| are written under
//! `target/grading/`, enlarged (nearest neighbour) to at least
//! [`crate::pictures::MIN_WIDTH`] pixels across so that they can be read.

use raytracer::film::Image;
use std::path::{Path, PathBuf};

use raytracer::integrator::{Bdpt, DirectStrategy, Integrator, LightTracer, PathTracer};
use raytracer::metrics::{z_test, z_threshold};
use raytracer::render::{RenderOptions, render};
use raytracer::scene::Scene;

use crate::pictures::write_enlarged;
use crate::stats::output_dir;

/// Family-wise false-failure probability of one image comparison.
pub const ALPHA: f64 = 1e-4;

/// Samples per pixel of the stored references (their noise is then a small
/// part of the comparison's variance, which the z-test includes anyway).
pub const REFERENCE_SPP: u32 = 4096;

/// Settings of a comparison, and the renderer's integrator that makes its
/// reference.
pub struct Comparison {
    /// For file names, e.g. `ex11_cornell`.
    pub name: &'static str,
    pub scene: &'static str,
    pub size: u32,
    pub tile: u32,
    /// Samples per pixel of the student's render.
    pub spp: u32,
    /// The renderer's integrator that renders the reference at
    /// [`REFERENCE_SPP`] (any integrator: a path tracer, a light tracer, …).
    pub reference: fn() -> Box<dyn Integrator>,
}

/// Exercise 11: the path tracer (the student samples BRDFs only). The
/// reference has the same expected value but uses MIS: BRDF sampling alone
/// finds the small light rarely, and a reference with such heavy tails can
/// miss light in a tile while its own variance estimate does not show it.
/// For the same reason the student's render is compared in 16-pixel tiles
/// at 256 spp: 65,536 samples per tile make the normal approximation of the
/// z-test hold for the student's BRDF-only estimator too (8-pixel tiles at
/// 64 spp failed 3 of 80 correct renders, at 256 spp and 16-pixel tiles none
/// did, over 40 seeds of the reference solution and 40 of a variant).
pub const EX11_CORNELL: Comparison = Comparison {
    name: "ex11_cornell",
    scene: "cornell",
    size: 32,
    tile: 16,
    spp: 256,
    reference: || {
        Box::new(PathTracer {
            max_depth: Some(5),
            rr_depth: 3,
            strategy: DirectStrategy::Mis,
        })
    },
};

/// Exercise 12: direct light by light sampling alone (the reference combines
/// light and BRDF sampling by MIS: the same expected value, lighter tails).
pub const EX12_CORNELL_DIRECT: Comparison = Comparison {
    name: "ex12_cornell_direct",
    scene: "cornell",
    size: 32,
    tile: 8,
    spp: 32,
    reference: || {
        Box::new(PathTracer {
            max_depth: Some(2),
            rr_depth: 1000,
            strategy: DirectStrategy::Mis,
        })
    },
};

/// Exercise 12 (part 3): the path tracer with next event estimation, at max
/// depth 5 as exercise 11 (the same expected value, so the same reference:
/// `ex12_cornell.exr` is rendered exactly as `ex11_cornell.exr`). Light
/// sampling finds the light at every vertex, so 64 spp in 8-pixel tiles
/// (4,096 samples per tile) suffice.
pub const EX12_CORNELL: Comparison = Comparison {
    name: "ex12_cornell",
    scene: "cornell",
    size: 32,
    tile: 8,
    spp: 64,
    reference: || {
        Box::new(PathTracer {
            max_depth: Some(5),
            rr_depth: 3,
            strategy: DirectStrategy::Mis,
        })
    },
};
/// Exercise 14: the student's light tracer on `caustic` against the
/// renderer's light tracer (the same estimator; the caustic on the floor is
/// found only by light paths). 16-pixel tiles at 64 spp (65 536 light paths):
/// see `tests/tests/fixtures/ex14.rs` for the false-failure rate measured
/// over seeds.
pub const EX14_CAUSTIC: Comparison = Comparison {
    name: "ex14_caustic",
    scene: "caustic",
    size: 32,
    tile: 16,
    spp: 64,
    reference: || {
        Box::new(LightTracer {
            max_depth: crate::ex14_light_tracing::EX14_MAX_DEPTH,
            rr_depth: crate::ex14_light_tracing::EX14_RR_DEPTH,
        })
    },
};

/// Maximum depth of exercise 16's door (its chains run over bidirectional
/// path tracing to this depth).
pub const EX16_DOOR_MAX_DEPTH: u32 = 5;

/// Exercise 16: the student's Metropolis chains on the door, against
/// bidirectional path tracing (the estimator the chains run over, so the
/// same expected image). The grader renders the chains itself
/// ([`crate::ex16_metropolis::check_door`]): `spp` counts the mutations per
/// pixel of all its chains together.
pub const EX16_DOOR: Comparison = Comparison {
    name: "ex16_door",
    scene: "door",
    size: 32,
    tile: 16,
    spp: 128,
    reference: || {
        Box::new(Bdpt {
            max_depth: Some(EX16_DOOR_MAX_DEPTH),
            rr_depth: 5,
            strategy_images: None,
        })
    },
};

/// Exercise 15: bidirectional path tracing at max depth 4 against the
/// renderer's BDPT (the same expected value; the renderer's `s = 1` takes a
/// fresh light sample where the student's joins `y_0`).
pub const EX15_CORNELL: Comparison = Comparison {
    name: "ex15_cornell",
    scene: "cornell",
    size: 32,
    tile: 8,
    spp: 32,
    reference: || {
        Box::new(Bdpt {
            max_depth: Some(4),
            rr_depth: 3,
            strategy_images: None,
        })
    },
};

/// Exercise 13: the MIS path tracer in the Cornell box (the reference is the
/// renderer's path tracer with the same estimator).
pub const EX13_CORNELL: Comparison = Comparison {
    name: "ex13_cornell",
    ..EX12_CORNELL
};

/// Exercise 13: Veach's plates (direct light, max depth 2), square (the
/// grader's images are square: the three smaller lights over all four
/// plates), against the renderer's MIS path tracer. MIS still has rare large
/// samples here, so the tiles are large: 16 pixels at 64 spp failed 0 of 24
/// seeds of the reference solution, 8 pixels at 32 spp 1 of 24.
pub const EX13_VEACH: Comparison = Comparison {
    name: "ex13_veach",
    scene: "veach-mis",
    size: 48,
    tile: 16,
    spp: 64,
    reference: || {
        Box::new(PathTracer {
            max_depth: Some(2),
            rr_depth: 1000,
            strategy: DirectStrategy::Mis,
        })
    },
};

/// Exercise 18 without clamping: instant radiosity with a new VPL set per
/// pixel sample is unbiased, so its reference is the path tracer at the same
/// depth (MIS: the same expected value, lighter tails).
pub const EX18_CORNELL: Comparison = Comparison {
    name: "ex18_cornell",
    scene: "cornell",
    size: 32,
    tile: 16,
    spp: 32,
    reference: || {
        Box::new(PathTracer {
            max_depth: Some(crate::ex18_instant_radiosity::MAX_DEPTH),
            rr_depth: crate::ex18_instant_radiosity::RR_DEPTH,
            strategy: DirectStrategy::Mis,
        })
    },
};

/// Exercise 18 with G clamped: the renderer's instant radiosity with the
/// same bound, over many independent VPL sets
/// ([`crate::ex18_instant_radiosity::VplSetsReference`]).
pub const EX18_CORNELL_CLAMPED: Comparison = Comparison {
    name: "ex18_cornell_clamped",
    scene: "cornell",
    size: 32,
    tile: 8,
    spp: 64,
    reference: || {
        Box::new(crate::ex18_instant_radiosity::VplSetsReference::new(
            crate::ex18_instant_radiosity::CLAMP,
        ))
    },
};

/// Every comparison with a stored reference (`lesson11 references` renders them).
pub const COMPARISONS: &[&Comparison] = &[
    &EX11_CORNELL,
    &EX12_CORNELL_DIRECT,
    &EX12_CORNELL,
    &EX13_CORNELL,
    &EX13_VEACH,
    &EX14_CAUSTIC,
    &EX15_CORNELL,
    &EX16_DOOR,
    &EX18_CORNELL,
    &EX18_CORNELL_CLAMPED,
];

pub fn options(spp: u32, seed: u64, progress: bool, label: &str) -> RenderOptions {
    RenderOptions {
        spp,
        seed,
        threads: None,
        tile_size: 16,
        progress,
        label: label.into(),
    }
}

pub fn scene(c: &Comparison) -> Result<Scene, String> {
    let mut scene = Scene::builtin(c.scene).map_err(|e| format!("grader: {e}"))?;
    scene.set_resolution(c.size, c.size);
    Ok(scene)
}

/// Where the reference of `c` is stored: its mean and the variance of that
/// mean, as EXR files in `tests/references/`.
pub fn reference_paths(c: &Comparison) -> (PathBuf, PathBuf) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("references");
    (
        dir.join(format!("{}.exr", c.name)),
        dir.join(format!("{}-variance.exr", c.name)),
    )
}

/// Renders the reference of `c` at [`REFERENCE_SPP`] with the renderer's own
/// integrator and stores it (the instructor's `lesson11 references`).
pub fn render_reference(c: &Comparison, progress: bool) -> Result<PathBuf, String> {
    let result = render(
        &scene(c)?,
        (c.reference)().as_ref(),
        &options(REFERENCE_SPP, 1, progress, c.name),
    );
    if result.stats.interrupted {
        // A partial render is no reference: the stored files stay as they were.
        return Err(crate::tr!("compare.interrupted", name = c.name));
    }
    let (mean, variance) = reference_paths(c);
    std::fs::create_dir_all(mean.parent().unwrap()).map_err(|e| e.to_string())?;
    result.film.write_exr(&mean).map_err(|e| e.to_string())?;
    result
        .film
        .variance_image()
        .write_exr(&variance)
        .map_err(|e| e.to_string())?;
    Ok(mean)
}

fn load_reference(c: &Comparison) -> Result<(Image, Image), String> {
    let (mean, variance) = reference_paths(c);
    let read = |p: &Path| {
        Image::read_exr(p).map_err(|e| crate::tr!("compare.missing", path = p.display(), e))
    };
    Ok((read(&mean)?, read(&variance)?))
}

/// Renders `student` and z-tests it against the stored reference, tile by
/// tile (threshold for the family of all tiles and channels at level [`ALPHA`]).
/// An error naming both sizes unless the student's image has the reference's.
pub fn same_size(c: &Comparison, reference: &Image, student: &Image) -> Result<(), String> {
    if (student.width, student.height) == (reference.width, reference.height) {
        return Ok(());
    }
    Err(crate::tr!(
        "compare.size",
        name = c.name,
        rw = reference.width,
        rh = reference.height,
        w = student.width,
        h = student.height
    ))
}

pub fn compare(c: &Comparison, student: &dyn Integrator) -> Result<(), String> {
    compare_with_seed(c, student, 11)
}

/// [`compare`] with the seed of the student's render (the self-test checks
/// the false-failure rate over many seeds).
pub fn compare_with_seed(
    c: &Comparison,
    student: &dyn Integrator,
    seed: u64,
) -> Result<(), String> {
    compare_into(c, student, seed, &output_dir())
}

/// [`compare_with_seed`], writing the pictures of a failure into `dir`.
pub fn compare_into(
    c: &Comparison,
    student: &dyn Integrator,
    seed: u64,
    dir: &Path,
) -> Result<(), String> {
    let (bi, bv) = load_reference(c)?;
    let a = render(&scene(c)?, student, &options(c.spp, seed, false, ""));
    let (ai, av) = (a.film.image(), a.film.variance_image());
    same_size(c, &bi, &ai)?;
    let z = z_test(&ai, &av, &bi, &bv, c.tile);
    let tests = z.z.len() * 3;
    let threshold = z_threshold(tests, ALPHA) as f32;
    if z.max_abs_z <= threshold && a.film.nonfinite_count() == 0 {
        return Ok(());
    }
    let written = write_images(dir, c, &ai, &bi, &z.z, z.grid.x, threshold);
    let mean = |img: &Image| raytracer::metrics::mean(img);
    let mut msg = if a.film.nonfinite_count() > 0 {
        crate::tr!(
            "compare.nonfinite",
            scene = c.scene,
            count = a.film.nonfinite_count()
        )
    } else {
        crate::tr!(
            "compare.differs",
            scene = c.scene,
            tile = z.worst_tile,
            z = z.max_abs_z,
            yours = mean(&ai).element_sum() / 3.0,
            reference = mean(&bi).element_sum() / 3.0,
            threshold
        )
    };
    match written {
        Ok(()) => msg.push_str(&crate::tr!(
            "compare.see",
            dir = dir.display(),
            name = c.name
        )),
        Err(e) => msg.push_str(&crate::tr!("compare.no_images", e)),
    }
    Err(msg)
}

fn write_images(
    dir: &std::path::Path,
    c: &Comparison,
    student: &Image,
    reference: &Image,
    z: &[raytracer::math::Color],
    grid_x: u32,
    threshold: f32,
) -> std::io::Result<()> {
    std::fs::create_dir_all(dir)?;
    write_enlarged(student, &dir.join(format!("{}_student.png", c.name)))?;
    write_enlarged(reference, &dir.join(format!("{}_reference.png", c.name)))?;
    // The error image: each pixel shows its tile's |z| / threshold (1 = just failing).
    let zmap = Image::from_fn(student.width, student.height, |x, y| {
        let t = (y / c.tile * grid_x + x / c.tile) as usize;
        z[t].abs() / threshold
    });
    write_enlarged(&zmap, &dir.join(format!("{}_z.png", c.name)))
}
