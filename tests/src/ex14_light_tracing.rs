//! Grader of exercise 14 (a whole light tracer): furnaces with known answers
//! seen by light tracing alone, then the `caustic` scene against the
//! renderer's light tracer, tile by tile, then a glass furnace.
//!
//! 1. The emitting furnace (camera at the centre of a sphere emitting `L_e`
//!    with albedo ρ) with a second light, a point light outside the sphere
//!    that sends nothing in and is chosen half of the time (lights are chosen
//!    by power): `L = L_e Σ_{k<D} ρ^k` in every pixel — 0.5 at D = 1 (the
//!    lights seen directly, L_e = 0.5), 0.75 at D = 2 (ρ = 0.5), and 1 with
//!    no limit and roulette from the first bounce (L_e = 0.1, ρ = 0.9: long
//!    paths, so that roulette matters). Every vertex is at distance 1 and
//!    faces the camera: these cases test the light's side and `W_e`.
//! 2. `caustic` at 32×32 against the renderer's `LightTracer` (the stored
//!    reference, [`crate::compare::EX14_CAUSTIC`]): distances, cosines at the
//!    surface, shadows, the caustic.
//! 3. A glass furnace: a white (ρ = 1) ball inside a glass ball (η = 1.5),
//!    both inside a black sphere emitting `L_e = 0.5`. In equilibrium the
//!    radiance inside the glass is `η² L_e` in every direction (no
//!    absorption: the white ball reflects all it gets; the renderer's path
//!    tracer agrees), so the camera, inside the glass and filled by the white
//!    ball, sees `η² L_e = 1.125` in every pixel. A light path that reaches
//!    the white ball has entered the glass once more than it has left it:
//!    radiance transport would scale it by `1/η²` and show `L_e`.
//!
//! Every splat the student pushes is checked on the way: on the film, finite
//! and non-negative. A failing mean is compared with what the usual mistakes
//! converge to (the furnaces: exactly; the caustic: by the ratio of the
//! means, in ranges measured with the wrong fixtures of the self-test).
//!
//! Tolerances: each furnace is z-tested tile by tile (2×2-pixel tiles of an
//! 8×8 film) against its exact value with the film's own variance estimate,
//! at family-wise α = 1e-4 ([`raytracer::metrics::z_threshold`] over 16 tiles
//! × 3 channels), and the caustic at α = 1e-4 ([`crate::compare`]): five
//! tests, a false failure below 5e-4 under the normal approximation. Light
//! tracing's splats are heavy-tailed, so that was measured too: 60 gradings
//! (the reference solution and the two correct fixtures, 20 seeds each, the
//! test `ex14_false_failures` in `tests/tests/check_grader.rs`) had
//! no false failure.

use std::sync::Mutex;

use exercises::plug::{LightPathFn, StudentLightTracer};
use raytracer::film::{Image, Splat};
use raytracer::integrator::Integrator;
use raytracer::math::{Color, Ray, UVec2, Vec2};
use raytracer::metrics::{mean, z_test, z_threshold};
use raytracer::render::{RenderOptions, RenderResult, render};
use raytracer::sampling::Sampler;
use raytracer::scene::{Scene, SceneOrigin, builtin, load_str};

use crate::compare::{ALPHA, EX14_CAUSTIC, compare_with_seed, reference_paths};

/// The signature of exercise 14.
pub type LightFn = LightPathFn;

/// Samples per pixel of the furnaces (8×8 film: 131 072 light paths; four
/// times as many for the lights seen directly, which cost one connection).
pub const FURNACE_SPP: u32 = 2048;

/// Tile edge of the furnaces' z-tests: 2×2-pixel tiles, so that a splat
/// that is wrong at the edge of the film and right in the middle (no `W_e`)
/// does not average out in a tile.
pub const FURNACE_TILE: u32 = 2;

/// The student's light tracer, with every splat it pushes checked.
struct Watched {
    inner: StudentLightTracer,
    /// Of the splats that should not have been made, the least by [`BadKey`]:
    /// the render's threads find them in any order, and a report must name
    /// the same splat every time (the self-test compares the English and the
    /// Bulgarian message's numbers). A seed's render makes the same splats
    /// whatever the threads, so the least of them is always the same one.
    bad: Mutex<Option<(BadKey, BadSplat)>>,
}

/// Orders bad splats: the pixel's row and column, then the splat's raster
/// position and value as bits (a total order, not a numeric one).
type BadKey = (u32, u32, [u32; 5]);

/// A splat that should not have been made. Found on the render's threads,
/// put in words on the grader's (whose language a test may have chosen).
enum BadSplat {
    /// Its raster position is not a number.
    NotANumber(Vec2),
    /// Off the film of this width and height.
    OffFilm(Vec2, f32, f32),
    /// Its value is NaN or infinite.
    NotFinite(Color),
    /// Its value is negative.
    Negative(Color),
}

impl BadSplat {
    fn message(&self) -> String {
        match *self {
            BadSplat::NotANumber(r) => crate::tr!("ex14.splat_nan", r),
            BadSplat::OffFilm(r, w, h) => crate::tr!("ex14.splat_off", r, w, h),
            BadSplat::NotFinite(value) => crate::tr!("ex14.splat_nonfinite", value),
            BadSplat::Negative(value) => crate::tr!("ex14.splat_negative", value),
        }
    }
}

impl Integrator for Watched {
    fn name(&self) -> &'static str {
        "student-light"
    }

    fn sample(
        &self,
        scene: &Scene,
        pixel: UVec2,
        sampler: &mut Sampler,
        splats: &mut Vec<Splat>,
    ) -> Color {
        let start = splats.len();
        let c = self.inner.sample(scene, pixel, sampler, splats);
        let (w, h) = (scene.camera.width as f32, scene.camera.height as f32);
        for s in &splats[start..] {
            let r = s.raster;
            let why = if !(r.x.is_finite() && r.y.is_finite()) {
                Some(BadSplat::NotANumber(r))
            } else if !(0.0..w).contains(&r.x) || !(0.0..h).contains(&r.y) {
                Some(BadSplat::OffFilm(r, w, h))
            } else if !s.value.is_finite() {
                Some(BadSplat::NotFinite(s.value))
            } else if s.value.min_element() < 0.0 {
                Some(BadSplat::Negative(s.value))
            } else {
                None
            };
            if let Some(why) = why {
                let at = (
                    pixel.y,
                    pixel.x,
                    [r.x, r.y, s.value.x, s.value.y, s.value.z].map(f32::to_bits),
                );
                let mut bad = self.bad.lock().expect("not poisoned");
                if bad.as_ref().is_none_or(|(first, _)| at < *first) {
                    *bad = Some((at, why));
                }
                break;
            }
        }
        c
    }
}

fn options(spp: u32, seed: u64) -> RenderOptions {
    RenderOptions {
        spp,
        seed,
        threads: None,
        tile_size: 16,
        progress: false,
        label: String::new(),
    }
}

/// Renders `scene` with the student's light tracer; `Err` names the first
/// splat that should not have been made.
fn render_watched(
    scene: &Scene,
    f: LightFn,
    max_depth: Option<u32>,
    rr_depth: u32,
    spp: u32,
    seed: u64,
) -> Result<RenderResult, String> {
    let watched = Watched {
        inner: StudentLightTracer {
            trace_light_path: f,
            max_depth,
            rr_depth,
        },
        bad: Mutex::new(None),
    };
    let result = render(scene, &watched, &options(spp, seed));
    match watched.bad.into_inner().expect("not poisoned") {
        Some((_, why)) => Err(format!("{}: {}", scene.name, why.message())),
        None => Ok(result),
    }
}

/// A scene of the grader's from its TOML text, at 8×8 pixels.
fn grader_scene(name: &str, toml: &str) -> Result<Scene, String> {
    let origin = SceneOrigin::Dir {
        name: format!("grader:{name}"),
        dir: std::path::PathBuf::new(),
    };
    let parts = load_str(toml, &origin).map_err(|e| format!("grader: {e}"))?;
    let mut s = Scene::build(name, parts);
    s.set_resolution(8, 8);
    Ok(s)
}

/// The emitting furnace with albedo `rho` and emission `le`, and a point
/// light outside it. Lights are chosen by power: the sphere's
/// `2 · π A L_e = 8π² L_e` (two-sided, A = 4π) and the point light's `4π I`
/// with `I = 2π L_e`: each is chosen with probability 1/2. Its light falls on
/// the outside of the sphere, which scatters nothing inwards (a BRDF reflects
/// on the side it is lit from). `L = L_e Σ_{k<D} ρ^k` in every pixel.
pub fn two_light_furnace(rho: f64, le: f64) -> Result<Scene, String> {
    let furnace = builtin("furnace").ok_or("grader: no built-in furnace")?;
    let point_light = format!(
        "[[lights]]\ntype = \"point\"\nposition = [0, 0, 3]\nintensity = {}\n",
        2.0 * std::f64::consts::PI * le
    );
    let toml = furnace
        .toml
        .replace("albedo = 0.5", &format!("albedo = {rho}"))
        .replace("emission = 0.5", &format!("emission = {le}"))
        + "\n"
        + &point_light;
    grader_scene("furnace-and-point-light", &toml)
}

/// Refractive index of the glass furnace.
pub const ETA: f64 = 1.5;

/// The glass furnace (see the module doc); `η² L_e` in every pixel.
pub const GLASS_FURNACE: &str = r#"
[camera]
position = [0, 0, 0.9]
look_at = [0, 0, 0]
up = [0, 1, 0]
fov = 40

[render]
width = 8
height = 8
spp = 64
max_depth = -1
rr_depth = 5

[materials.black]
type = "lambert"
albedo = 0

[materials.white]
type = "lambert"
albedo = 1

[materials.glass]
type = "glass"
ior = 1.5

[[shapes]]
name = "furnace"
type = "sphere"
center = [0, 0, 0]
radius = 1.05
material = "black"
emission = 0.5
two_sided = true

[[shapes]]
name = "glass-ball"
type = "sphere"
center = [0, 0, 0]
radius = 1
material = "glass"

[[shapes]]
name = "white-ball"
type = "sphere"
center = [0, 0, 0]
radius = 0.5
material = "white"
"#;

/// The mean of a furnace render over the film, and whether every tile
/// agrees with `exact` (`Err`: the message of the worst tile).
fn furnace_tiles(result: &RenderResult, exact: f32) -> (f64, Result<(), String>) {
    let image = result.film.image();
    let var = result.film.variance_image();
    let (w, h) = (image.width, image.height);
    let exact_image = Image::from_fn(w, h, |_, _| Color::splat(exact));
    let zero = Image::from_fn(w, h, |_, _| Color::ZERO);
    let z = z_test(&image, &var, &exact_image, &zero, FURNACE_TILE);
    let threshold = z_threshold(z.z.len() * 3, ALPHA) as f32;
    let m = mean(&image).element_sum() as f64 / 3.0;
    if z.max_abs_z <= threshold {
        return (m, Ok(()));
    }
    (
        m,
        Err(crate::tr!(
            "ex14.tile",
            tile = z.worst_tile,
            size = FURNACE_TILE,
            z = z.max_abs_z,
            threshold,
            m,
            exact
        )),
    )
}

/// Whether `result` is consistent, tile by tile, with `image` (exact).
fn agrees(result: &RenderResult, image: &Image) -> bool {
    let zero = Image::from_fn(image.width, image.height, |_, _| Color::ZERO);
    let z = z_test(
        &result.film.image(),
        &result.film.variance_image(),
        image,
        &zero,
        FURNACE_TILE,
    );
    z.max_abs_z as f64 <= z_threshold(z.z.len() * 3, ALPHA)
}

/// What a light tracer without `W_e` converges to where the right answer is
/// `exact` in every pixel: `exact / W_e`.
fn without_importance(scene: &Scene, exact: f32) -> Image {
    over_the_film(scene, exact, |ray| 1.0 / scene.camera.we(ray))
}

/// What a light tracer whose connection leaves out the cosine at the lens
/// converges to where the right answer is `exact` in every pixel:
/// `exact / cos θ`, θ the angle between the ray and the view direction.
fn without_lens_cosine(scene: &Scene, exact: f32) -> Image {
    over_the_film(scene, exact, |ray| 1.0 / ray.d.dot(scene.camera.forward()))
}

/// `exact · factor(ray)` averaged over each pixel (a 4×4 grid of rays
/// through the pinhole): the image a mistake that scales each splat by a
/// factor of the camera ray converges to.
fn over_the_film(scene: &Scene, exact: f32, factor: impl Fn(&Ray) -> f32) -> Image {
    let cam = &scene.camera;
    Image::from_fn(cam.width, cam.height, |x, y| {
        let mut sum = 0.0;
        for j in 0..4 {
            for i in 0..4 {
                let raster = Vec2::new(
                    x as f32 + (i as f32 + 0.5) / 4.0,
                    y as f32 + (j as f32 + 0.5) / 4.0,
                );
                sum += factor(&cam.generate_ray(raster, Vec2::splat(0.5)));
            }
        }
        Color::splat(exact * sum / 16.0)
    })
}

/// The usual mistakes by what the mean of the whole image converges to,
/// relative to the right answer, in one case; `None` if none fits.
fn recognise(ratio: f64, named: &[(f64, f64, String)]) -> Option<String> {
    named
        .iter()
        .find(|(lo, hi, _)| (*lo..=*hi).contains(&ratio))
        .map(|(_, _, why)| why.clone())
}

fn too(ratio: f64) -> String {
    if ratio > 1.0 {
        crate::tr!("ex14.too_bright", ratio)
    } else {
        crate::tr!("ex14.too_dark", ratio)
    }
}

pub fn check(f: LightFn) -> Result<(), String> {
    check_with_seed(f, 14)
}

/// [`check`] with the seed of every render (the self-test measures the
/// false-failure rate over seeds).
pub fn check_with_seed(f: LightFn, seed: u64) -> Result<(), String> {
    // (albedo, L_e, max depth, roulette depth, the answer, the case)
    type Case = (f64, f64, Option<u32>, u32, f64, String);
    let cases: [Case; 3] = [
        (0.5, 0.5, Some(1), 1000, 0.5, crate::tr!("ex14.case_direct")),
        (
            0.5,
            0.5,
            Some(2),
            1000,
            0.75,
            crate::tr!("ex14.case_bounce"),
        ),
        (0.9, 0.1, None, 1, 1.0, crate::tr!("ex14.case_roulette")),
    ];
    // One light path here first, on this thread: a `todo!()` is reported
    // with its place (a panic inside the parallel render is not).
    f(
        &two_light_furnace(0.5, 0.5)?,
        &mut Sampler::new(seed, 0, 0),
        None,
        1,
        &mut Vec::new(),
    );
    for (k, (rho, le, max_depth, rr_depth, exact, what)) in cases.into_iter().enumerate() {
        let furnace = two_light_furnace(rho, le)?;
        let exact = exact as f32;
        let spp = if max_depth == Some(1) {
            4 * FURNACE_SPP
        } else {
            FURNACE_SPP
        };
        let result = render_watched(&furnace, f, max_depth, rr_depth, spp, seed + k as u64)?;
        let (m, verdict) = furnace_tiles(&result, exact);
        let Err(why) = verdict else { continue };
        let ratio = m / exact as f64;
        let case = crate::tr!("ex14.furnace", what);
        if agrees(&result, &without_importance(&furnace, exact)) {
            let advice = crate::tr!("ex14.no_importance");
            return Err(format!("{}: {} — {}", case, why, advice));
        }
        if agrees(&result, &without_lens_cosine(&furnace, exact)) {
            let advice = crate::tr!("ex14.no_cos_lens");
            return Err(format!("{}: {} — {}", case, why, advice));
        }
        let no_pmf = || crate::tr!("ex14.no_pmf");
        let advice = match max_depth {
            Some(1) => recognise(
                ratio,
                &[
                    (0.45, 0.55, no_pmf()),
                    (0.0, 0.02, crate::tr!("ex14.nothing")),
                ],
            ),
            Some(_) => recognise(
                ratio,
                &[
                    (0.45, 0.55, no_pmf()),
                    (1.25, 1.4, crate::tr!("ex14.cos_light")),
                    (0.62, 0.7, crate::tr!("ex14.one_bounce")),
                ],
            ),
            None => recognise(ratio, &[(0.2, 0.9, crate::tr!("ex14.roulette"))]),
        }
        .unwrap_or_else(|| crate::tr!("ex14.unknown", too = too(ratio)));
        return Err(format!("{}: {} — {}", case, why, advice));
    }
    caustic(f, seed)?;
    // Glass: importance transport.
    let glass = grader_scene("glass-furnace", GLASS_FURNACE)?;
    let exact = (ETA * ETA * 0.5) as f32;
    let result = render_watched(&glass, f, None, 3, FURNACE_SPP, seed + 3)?;
    let (m, verdict) = furnace_tiles(&result, exact);
    if let Err(why) = verdict {
        let ratio = m / exact as f64;
        let advice = recognise(ratio, &[(0.38, 0.5, crate::tr!("ex14.glass_radiance"))])
            .unwrap_or_else(|| too(ratio));
        return Err(crate::tr!("ex14.glass", exact, why, advice));
    }
    Ok(())
}

/// The `caustic` scene against the stored reference of the renderer's light
/// tracer; a failure is named, where it can be, by the ratio of the two
/// images' means.
fn caustic(f: LightFn, seed: u64) -> Result<(), String> {
    let c = &EX14_CAUSTIC;
    let student = StudentLightTracer {
        trace_light_path: f,
        max_depth: EX14_MAX_DEPTH,
        rr_depth: EX14_RR_DEPTH,
    };
    let mut scene = Scene::builtin(c.scene).map_err(|e| format!("grader: {e}"))?;
    scene.set_resolution(c.size, c.size);
    // The splats first: where they land and their sign.
    render_watched(&scene, f, EX14_MAX_DEPTH, EX14_RR_DEPTH, 4, seed)?;
    let Err(why) = compare_with_seed(c, &student, seed) else {
        return Ok(());
    };
    let (mean_path, _) = reference_paths(c);
    let reference = Image::read_exr(&mean_path).map_err(|e| format!("grader: {e}"))?;
    let mine = render(&scene, &student, &options(c.spp, seed)).film.image();
    let ratio = (mean(&mine).element_sum() / mean(&reference).element_sum()) as f64;
    let advice = recognise(
        ratio,
        &[
            (0.3, 0.75, crate::tr!("ex14.caustic_no_importance")),
            (1.6, 3.2, crate::tr!("ex14.caustic_cos")),
            (3.5, 8.0, crate::tr!("ex14.caustic_slow")),
            (12.0, 60.0, crate::tr!("ex14.caustic_flat")),
        ],
    )
    .unwrap_or_else(|| crate::tr!("ex14.caustic_unknown", too = too(ratio)));
    Err(crate::tr!("ex14.caustic", why, ratio, advice))
}

/// Depth of the caustic comparison: the caustic needs 4 light vertices
/// (light, into the ball, out of it, the floor).
pub const EX14_MAX_DEPTH: Option<u32> = Some(8);
/// Roulette depth of the caustic comparison.
pub const EX14_RR_DEPTH: u32 = 3;
