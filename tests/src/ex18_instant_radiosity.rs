//! Grader of exercise 18 (instant radiosity, Keller): first `gather` alone,
//! exactly, over single VPLs placed by hand in a small scene (a wall, a
//! floor seen from above and from below, a blocker, a light); then
//! `generate_vpls` with `gather` in the emitting furnace, where the answer is
//! known (`L_e Σ ρ^k`, exact for direct light alone); then that no VPL sits
//! on a mirror; then the whole integrator on the Cornell box against stored
//! references, tile by tile, unclamped and clamped.
//!
//! The Cornell renders trace a new VPL set for every pixel sample
//! ([`VplSets::PerSample`]), so that the samples are independent and a
//! tile's variance includes the randomness of the VPLs: with one set shared
//! by the whole picture its error is the same in every pixel and no
//! variance estimate sees it. Unclamped, instant radiosity is unbiased over
//! VPL sets, so its reference is the path tracer at the same depth;
//! clamped, it is the renderer's instant radiosity with the same bound,
//! averaged over many independent VPL sets ([`VplSetsReference`]). The
//! renderer samples the light for direct light where the student gathers
//! the VPLs on the light; the reference clamps the geometry term of its
//! light sample at the same bound, so that both have the same expected
//! value (the light of VPLs on the light, clamped).
//!
//! Tolerances: exact values to 1e-4 relative (deterministic: no false
//! failures); |z| ≤ 5.5 per channel in 3 furnace cases (false failure
//! < 4e-7); each image comparison at family-wise α = 1e-4
//! ([`crate::compare`]).

use std::path::PathBuf;
use std::sync::OnceLock;
use std::sync::atomic::AtomicBool;

use exercises::plug::{GatherFn, GenerateVplsFn, StudentVpl, Vpl, VplSets};
use raytracer::film::Splat;
use raytracer::integrator::shading_normals::importance_correction;
use raytracer::integrator::visible_point::visible_point;
use raytracer::integrator::{InstantRadiosity, Integrator, VplSettings, camera_ray};
use raytracer::math::{Color, Ray, UVec2, Vec3A};
use raytracer::sampling::Sampler;
use raytracer::scene::{Interaction, Scene, SceneOrigin, load_str};

use crate::compare::{EX18_CORNELL, EX18_CORNELL_CLAMPED, compare};
use crate::ex10_naive_recursive::{LE, RHO, series, small_scene};
use crate::stats::{MeanVar, Mistake, fmt3, ratio_near, recognise};

/// The bound on G of the clamped Cornell comparison (the slides' g_max).
pub const CLAMP: f32 = 0.5;
/// Max depth and roulette of the Cornell comparisons.
pub const MAX_DEPTH: u32 = 5;
pub const RR_DEPTH: u32 = 3;
/// Light paths per VPL set in the student's Cornell renders (a new set per
/// pixel sample).
pub const PATHS_PER_SAMPLE: u32 = 2;

/// Light paths per VPL set in the furnace, and estimates per case.
const FURNACE_PATHS: u32 = 4;
const FURNACE_ESTIMATES: u64 = 4000;

/// The student's instant radiosity as the Cornell comparisons render it.
pub fn student(generate: GenerateVplsFn, gather: GatherFn, clamp: Option<f32>) -> StudentVpl {
    StudentVpl::with(
        generate,
        gather,
        PATHS_PER_SAMPLE,
        clamp,
        Some(MAX_DEPTH),
        RR_DEPTH,
        VplSets::PerSample,
    )
}

pub fn check(generate: GenerateVplsFn, gather: GatherFn) -> Result<(), String> {
    check_gather(gather)?;
    check_furnace(generate, gather)?;
    check_mirror(generate)?;
    check_two_lights(generate)?;
    compare(&EX18_CORNELL, &student(generate, gather, None))
        .map_err(|e| crate::tr!("ex18.cornell", MAX_DEPTH, e))?;
    compare(
        &EX18_CORNELL_CLAMPED,
        &student(generate, gather, Some(CLAMP)),
    )
    .map_err(|e| crate::tr!("ex18.cornell_clamped", CLAMP, MAX_DEPTH, e))
}

// ---------------------------------------------------------------------------
// The gather, exactly.

/// A floor (y = 0, grey) seen from above and below, a second floor under it
/// (y = −1, pale), a tinted wall (x = 1, facing −x), a blocker (y = 1) and a
/// small light (y = 2, facing down); every Lambert two-sided.
const GATHER_SCENE: &str = r#"
[camera]
position = [0, 1, 4]
look_at = [0, 0, 0]
up = [0, 1, 0]
fov = 40

[render]
width = 8
height = 8

[materials.grey]
type = "lambert"
albedo = 0.5

[materials.pale]
type = "lambert"
albedo = 0.8

[materials.tinted]
type = "lambert"
albedo = [0.2, 0.4, 0.6]

[[shapes]]
name = "floor"
type = "quad"
origin = [-2, 0, 2]
edge1 = [4, 0, 0]
edge2 = [0, 0, -4]
material = "grey"

[[shapes]]
name = "under"
type = "quad"
origin = [-2, -1, 2]
edge1 = [4, 0, 0]
edge2 = [0, 0, -4]
material = "pale"

[[shapes]]
name = "wall"
type = "quad"
origin = [1, -1, -2]
edge1 = [0, 0, 4]
edge2 = [0, 3, 0]
material = "tinted"

[[shapes]]
name = "blocker"
type = "quad"
origin = [-0.5, 1, 0.2]
edge1 = [1, 0, 0]
edge2 = [0, 0, 0.8]
material = "grey"

[[shapes]]
name = "light"
type = "quad"
origin = [-0.25, 2, -0.25]
edge1 = [0.5, 0, 0]
edge2 = [0, 0, 0.5]
material = "grey"
emission = [10, 8, 6]
"#;

/// A light path in a room whose floor is a mirror: light (y = 1, facing
/// down) over a mirror floor (y = 0), under a white ceiling (y = 1.2).
const MIRROR_SCENE: &str = r#"
[camera]
position = [0, 0.6, 3]
look_at = [0, 0.5, 0]
up = [0, 1, 0]
fov = 40

[render]
width = 8
height = 8

[materials.mirror]
type = "mirror"

[materials.white]
type = "lambert"
albedo = 0.8

[[shapes]]
name = "floor"
type = "quad"
origin = [-2, 0, 2]
edge1 = [4, 0, 0]
edge2 = [0, 0, -4]
material = "mirror"

[[shapes]]
name = "ceiling"
type = "quad"
origin = [-2, 1.2, -2]
edge1 = [4, 0, 0]
edge2 = [0, 0, 4]
material = "white"

[[shapes]]
name = "light"
type = "quad"
origin = [-0.25, 1, -0.25]
edge1 = [0.5, 0, 0]
edge2 = [0, 0, 0.5]
material = "white"
emission = 5
"#;

fn text_scene(name: &str, text: &str) -> Result<Scene, String> {
    let origin = SceneOrigin::Dir {
        name: name.into(),
        dir: PathBuf::new(),
    };
    let parts = load_str(text, &origin).map_err(|e| format!("grader: {e}"))?;
    Ok(Scene::build(name, parts))
}

/// The hit of the ray from `from` towards `to` (which must lie on the first
/// surface it meets): its `wo` points back to `from`.
fn hit(scene: &Scene, from: Vec3A, to: Vec3A) -> Result<Interaction, String> {
    let ray = Ray::new(from, (to - from).normalize());
    match scene.intersect(&ray) {
        Some(it) if (it.p - to).length() < 1e-3 => Ok(it),
        _ => Err(crate::tr!("ex18.grader_no_hit", to = fmt3(to))),
    }
}

/// A case of the gather: the camera hit, the VPLs, the bound, what it shows.
struct Case {
    x: Interaction,
    vpls: Vec<Vpl>,
    clamp: Option<f32>,
    what: String,
    /// Whether a VPL lies close to x (G far above 1).
    near: bool,
}

/// One of the usual mistakes, or none.
#[derive(Clone, Copy, Default)]
struct Slip {
    /// Signed cosines in G.
    signed: bool,
    /// The VPL's cosine taken with its incoming direction.
    incoming: bool,
    /// `1/r` for `1/r²`.
    r: bool,
    /// The bound applied to the contribution (per channel), not to G.
    clamp_light: bool,
    /// The bound ignored.
    no_clamp: bool,
    /// No shadow ray.
    no_shadow: bool,
    /// No BRDF at the VPL.
    no_f_y: bool,
    /// No BRDF at x.
    no_f_x: bool,
    /// No cosine at a VPL on a surface (G with the cosine at x alone).
    no_cos_surface: bool,
    /// No cosine at any VPL, on the light or on a surface.
    no_cos_y: bool,
}

/// The light one VPL sends to `x`, with the slip `s`.
fn one(scene: &Scene, x: &Interaction, vpl: &Vpl, clamp: Option<f32>, s: Slip) -> Color {
    let (p, n, ng) = match vpl {
        Vpl::Light { p, n, .. } => (*p, *n, *n),
        Vpl::Surface { it, .. } => (it.p, it.frame.n, it.ng),
    };
    let to_y = p - x.p;
    let d2 = to_y.length_squared();
    if d2 == 0.0 {
        return Color::ZERO;
    }
    let w = to_y / d2.sqrt();
    let (sent, cos_in) = match vpl {
        Vpl::Light {
            n, light, weight, ..
        } => (scene.emitted_by(*light, *n, -w) * *weight, n.dot(w)),
        Vpl::Surface { it, power, .. } => {
            let f_y = scene
                .brdf(it)
                .eval(it.frame.to_local(it.wo), it.frame.to_local(-w), it.uv);
            let f_y = if s.no_f_y {
                Color::ONE * (f_y != Color::ZERO) as u32 as f32
            } else {
                f_y
            };
            // A VPL is a light-path vertex: on a smooth mesh its BRDF is
            // the adjoint one, as in the renderer's gather (1 where the
            // shading and geometric normals agree, as in every case here).
            let adjoint = importance_correction(it, it.wo, -w);
            (f_y * *power * adjoint, it.frame.n.dot(it.wo))
        }
    };
    let f_x = scene
        .brdf(x)
        .eval(x.frame.to_local(x.wo), x.frame.to_local(w), x.uv);
    let f_x = if s.no_f_x {
        Color::ONE * (f_x != Color::ZERO) as u32 as f32
    } else {
        f_x
    };
    let cos_x = x.frame.n.dot(w);
    let cos_y = if s.incoming {
        cos_in
    } else if s.no_cos_y || (s.no_cos_surface && matches!(vpl, Vpl::Surface { .. })) {
        1.0
    } else {
        n.dot(w)
    };
    let mut g = if s.signed {
        -cos_x * cos_y
    } else {
        (cos_x * cos_y).abs()
    };
    g /= if s.r { d2.sqrt() } else { d2 };
    let mut l = match clamp {
        Some(c) if !s.no_clamp && !s.clamp_light => f_x * g.min(c) * sent,
        _ => f_x * g * sent,
    };
    if let (Some(c), true) = (clamp, s.clamp_light) {
        l = l.min(Color::splat(c));
    }
    if !s.no_shadow && !scene.unoccluded(&Ray::spawn_to(x.p, x.ng, p, ng)) {
        return Color::ZERO;
    }
    l
}

fn value(scene: &Scene, c: &Case, s: Slip) -> Color {
    c.vpls.iter().map(|v| one(scene, &c.x, v, c.clamp, s)).sum()
}

fn gather_cases(scene: &Scene) -> Result<Vec<Case>, String> {
    let v = Vec3A::new;
    let surface = |from, to, power, segments| -> Result<Vpl, String> {
        Ok(Vpl::Surface {
            it: hit(scene, from, to)?,
            power,
            segments,
        })
    };
    let light = |p, weight| Vpl::Light {
        p,
        n: -Vec3A::Y,
        light: 0,
        weight,
    };
    // The floor seen from above, a VPL on the wall that arrived from above.
    let x1 = hit(scene, v(0.1, 1.5, -0.9), v(0.3, 0.0, -0.2))?;
    let on_wall = surface(
        v(0.0, 1.5, -1.5),
        v(1.0, 0.5, -0.6),
        Color::new(1.0, 0.5, 0.25),
        1,
    )?;
    // A floor point and a wall VPL close to the corner they make.
    let x2 = hit(scene, v(0.5, 1.5, -0.5), v(0.93, 0.0, -0.3))?;
    let in_corner = surface(
        v(0.2, 0.8, 0.2),
        v(1.0, 0.06, -0.25),
        Color::new(0.6, 0.6, 0.9),
        2,
    )?;
    // The floor seen from BELOW (its normal, +y, faces away from the VPL),
    // a VPL on the lower floor (its normal faces the connection) that
    // arrived at a grazing angle.
    let x3 = hit(scene, v(0.2, -0.5, -0.3), v(0.3, 0.0, -0.4))?;
    let below = surface(
        v(0.0, -0.9, -0.9),
        v(0.8, -1.0, -0.9),
        Color::new(2.0, 1.0, 0.5),
        1,
    )?;
    // The floor under the blocker.
    let x4 = hit(scene, v(0.0, 0.5, 1.5), v(0.0, 0.0, 0.75))?;
    Ok(vec![
        Case {
            x: x1,
            vpls: vec![on_wall],
            clamp: None,
            what: crate::tr!("ex18.what_wall"),
            near: false,
        },
        Case {
            x: x1,
            vpls: vec![on_wall],
            clamp: Some(100.0),
            what: crate::tr!("ex18.what_wall_clamped"),
            near: false,
        },
        Case {
            x: x2,
            vpls: vec![in_corner],
            clamp: Some(2.0),
            what: crate::tr!("ex18.what_corner_clamped"),
            near: true,
        },
        Case {
            x: x2,
            vpls: vec![in_corner],
            clamp: None,
            what: crate::tr!("ex18.what_corner"),
            near: true,
        },
        Case {
            x: x3,
            vpls: vec![below],
            clamp: None,
            what: crate::tr!("ex18.what_below"),
            near: false,
        },
        Case {
            x: x1,
            vpls: vec![light(v(-0.1, 2.0, -0.2), 0.3)],
            clamp: None,
            what: crate::tr!("ex18.what_light"),
            near: false,
        },
        Case {
            x: x4,
            vpls: vec![light(v(0.05, 2.0, 0.1), 0.5)],
            clamp: None,
            what: crate::tr!("ex18.what_blocker"),
            near: false,
        },
        Case {
            x: x1,
            vpls: vec![on_wall, light(v(0.2, 2.0, 0.15), 0.25), in_corner],
            clamp: None,
            what: crate::tr!("ex18.what_three"),
            near: false,
        },
    ])
}

fn check_gather(gather: GatherFn) -> Result<(), String> {
    let scene = text_scene("grader-ex18", GATHER_SCENE)?;
    let cases = gather_cases(&scene)?;
    let got: Vec<Color> = cases
        .iter()
        .map(|c| gather(&scene, &c.x, &c.vpls, c.clamp))
        .collect();
    let same = |g: Color, e: Color| {
        g.is_finite()
            && (g - e)
                .abs()
                .cmple(1e-4 * e.abs().max(Color::splat(1e-3)))
                .all()
    };
    let right = |c: &Case| value(&scene, c, Slip::default());
    let right = &right;
    let Some(k) = (0..cases.len()).find(|&k| !same(got[k], right(&cases[k]))) else {
        return Ok(());
    };
    // Each usual mistake: what it is called, and the slip that makes it.
    let slips: [(String, Slip); 10] = [
        (
            crate::tr!("ex18.s_signed"),
            Slip {
                signed: true,
                ..Slip::default()
            },
        ),
        (
            crate::tr!("ex18.s_incoming"),
            Slip {
                incoming: true,
                ..Slip::default()
            },
        ),
        (
            crate::tr!("ex18.s_r"),
            Slip {
                r: true,
                ..Slip::default()
            },
        ),
        (
            crate::tr!("ex18.s_clamp_light"),
            Slip {
                clamp_light: true,
                ..Slip::default()
            },
        ),
        (
            crate::tr!("ex18.s_no_clamp"),
            Slip {
                no_clamp: true,
                ..Slip::default()
            },
        ),
        (
            crate::tr!("ex18.s_no_shadow"),
            Slip {
                no_shadow: true,
                ..Slip::default()
            },
        ),
        (
            crate::tr!("ex18.s_no_f_y"),
            Slip {
                no_f_y: true,
                ..Slip::default()
            },
        ),
        (
            crate::tr!("ex18.s_no_f_x"),
            Slip {
                no_f_x: true,
                ..Slip::default()
            },
        ),
        (
            crate::tr!("ex18.s_no_cos_surface"),
            Slip {
                no_cos_surface: true,
                ..Slip::default()
            },
        ),
        (
            crate::tr!("ex18.s_no_cos_y"),
            Slip {
                no_cos_y: true,
                ..Slip::default()
            },
        ),
    ];
    let scene = &scene;
    let answers: Vec<_> = slips
        .iter()
        .map(|&(_, s)| move |c: &Case| value(scene, c, s))
        .collect();
    let mistakes: Vec<Mistake<Case, Color>> = slips
        .iter()
        .zip(&answers)
        .map(|((why, _), answer)| (why.as_str(), answer as &dyn Fn(&Case) -> Color))
        .collect();
    let c = &cases[k];
    let why = recognise(&cases, &got, &mistakes, same).unwrap_or_else(|| {
        // Light missing only where no clamping was asked and G is large.
        let too_dark_unclamped = (0..cases.len()).all(|j| {
            same(got[j], right(&cases[j]))
                || (cases[j].clamp.is_none()
                    && cases[j].near
                    && (got[j].cmplt(right(&cases[j]) * 0.999)).all())
        });
        if too_dark_unclamped {
            crate::tr!("ex18.clamp_always")
        } else {
            let ratio = got[k] / right(c);
            crate::tr!("ex18.gather_unknown", ratio = fmt3(ratio))
        }
    });
    Err(crate::tr!(
        "ex18.gather",
        what = c.what,
        x = fmt3(c.x.p),
        clamp = format!("{:?}", c.clamp),
        got = fmt3(got[k]),
        want = fmt3(right(c)),
        why
    ))
}

// ---------------------------------------------------------------------------
// The furnace: VPLs and gather together.

/// Mean and variance over `FURNACE_ESTIMATES` estimates, each with its own
/// VPL set of `FURNACE_PATHS` light paths, gathered at a camera hit.
fn furnace_stats(
    scene: &Scene,
    generate: GenerateVplsFn,
    gather: GatherFn,
    max_depth: Option<u32>,
    rr_depth: u32,
    seed: u64,
) -> MeanVar {
    let mut stats = MeanVar::default();
    let (w, h) = (scene.camera.width as u64, scene.camera.height as u64);
    for i in 0..FURNACE_ESTIMATES {
        let pixel = UVec2::new((i % w) as u32, ((i / w) % h) as u32);
        let mut sampler = Sampler::new(seed, i, 0);
        let ray = camera_ray(scene, pixel, &mut sampler);
        let Some(x) = scene.intersect(&ray) else {
            continue;
        };
        let vpls = generate(scene, FURNACE_PATHS, max_depth, rr_depth, &mut sampler);
        stats.add(scene.emitted(&x) + gather(scene, &x, &vpls, None));
    }
    stats
}

fn check_furnace(generate: GenerateVplsFn, gather: GatherFn) -> Result<(), String> {
    let furnace = small_scene("furnace")?;
    let n = FURNACE_PATHS as f64;
    for d in [2u32, 3] {
        let stats = furnace_stats(&furnace, generate, gather, Some(d), 1000, 180 + d as u64);
        let exact = series(d, RHO);
        let named = [
            (exact - LE * RHO, crate::tr!("ex18.f_no_light_vpl")),
            (LE + n * (exact - LE), crate::tr!("ex18.f_not_shared", n)),
            (series(d, -RHO), crate::tr!("ex18.f_signed")),
            (series(d + 1, RHO), crate::tr!("ex18.f_more", d)),
            (series(d - 1, RHO), crate::tr!("ex18.f_fewer", d)),
        ];
        let advice = named
            .into_iter()
            .find(|(v, _)| stats.matches(Color::splat(*v as f32)))
            .map(|(_, why)| why);
        stats.check(
            &crate::tr!("ex18.furnace", d, paths = FURNACE_PATHS),
            Color::splat(exact as f32),
            |ratio| {
                advice.clone().or_else(|| {
                    Some(if ratio > 1.0 {
                        crate::tr!("ex18.f_bright", ratio)
                    } else {
                        crate::tr!("ex18.f_dark", ratio)
                    })
                })
            },
        )?;
    }
    let stats = furnace_stats(&furnace, generate, gather, None, 1, 185);
    stats.check(&crate::tr!("ex18.furnace_roulette"), Color::ONE, |ratio| {
        Some(if ratio < 1.0 {
            crate::tr!("ex18.roulette_dark")
        } else {
            crate::tr!("ex18.roulette_bright")
        })
    })
}

// ---------------------------------------------------------------------------
// Mirrors.

fn check_mirror(generate: GenerateVplsFn) -> Result<(), String> {
    let scene = text_scene("grader-ex18-mirror", MIRROR_SCENE)?;
    let mut sampler = Sampler::new(183, 0, 0);
    let vpls = generate(&scene, 64, None, 5, &mut sampler);
    let on_mirror = vpls
        .iter()
        .filter(|v| matches!(v, Vpl::Surface { it, .. } if scene.brdf(it).is_delta()))
        .count();
    if on_mirror > 0 {
        return Err(crate::tr!("ex18.on_mirror", on_mirror, total = vpls.len()));
    }
    let on_ceiling = vpls
        .iter()
        .filter(|v| matches!(v, Vpl::Surface { it, .. } if it.p.y > 1.1))
        .count();
    if on_ceiling == 0 {
        return Err(crate::tr!("ex18.none_on_ceiling", total = vpls.len()));
    }
    Ok(())
}

// ---------------------------------------------------------------------------
// Two lights.

/// Two lights of unequal power in a closed box of grey Lambertian walls
/// (one-sided quad lights of 0.5 m × 0.5 m: the upper one emits 8 and faces
/// down, the lower one emits 2 and faces up), so the scene picks them, by
/// power, with probabilities 0.8 and 0.2. Every other scene of the grader
/// has one light, picked with probability 1: there a flux or a weight that
/// leaves out the light's choice is right by chance. Exercise 17 uses it too.
pub const TWO_LIGHTS_SCENE: &str = r#"
[camera]
position = [0, 0, 0.5]
look_at = [0, 0, -1]
up = [0, 1, 0]
fov = 60

[render]
width = 8
height = 8

[materials.grey]
type = "lambert"
albedo = 0.5

[[shapes]]
name = "floor"
type = "quad"
origin = [-1, -1, -1]
edge1 = [0, 0, 2]
edge2 = [2, 0, 0]
material = "grey"

[[shapes]]
name = "ceiling"
type = "quad"
origin = [-1, 1, -1]
edge1 = [2, 0, 0]
edge2 = [0, 0, 2]
material = "grey"

[[shapes]]
name = "left"
type = "quad"
origin = [-1, -1, -1]
edge1 = [0, 2, 0]
edge2 = [0, 0, 2]
material = "grey"

[[shapes]]
name = "right"
type = "quad"
origin = [1, -1, -1]
edge1 = [0, 0, 2]
edge2 = [0, 2, 0]
material = "grey"

[[shapes]]
name = "back"
type = "quad"
origin = [-1, -1, -1]
edge1 = [2, 0, 0]
edge2 = [0, 2, 0]
material = "grey"

[[shapes]]
name = "front"
type = "quad"
origin = [-1, -1, 1]
edge1 = [0, 2, 0]
edge2 = [2, 0, 0]
material = "grey"

[[shapes]]
name = "upper light"
type = "quad"
origin = [-0.25, 0.9, -0.25]
edge1 = [0.5, 0, 0]
edge2 = [0, 0, 0.5]
material = "grey"
emission = 8

[[shapes]]
name = "lower light"
type = "quad"
origin = [-0.25, -0.9, -0.25]
edge1 = [0, 0, 0.5]
edge2 = [0.5, 0, 0]
material = "grey"
emission = 2
"#;

/// The area of each light of [`TWO_LIGHTS_SCENE`] (m²).
pub const TWO_LIGHTS_AREA: f32 = 0.25;

/// The flux the two lights of [`TWO_LIGHTS_SCENE`] emit together: a
/// one-sided Lambertian emitter of area A and radiance L emits π A L, so
/// π · 0.25 · (8 + 2) W. The box is closed and has no mirror: all of it
/// lands on a surface after one segment.
pub const TWO_LIGHTS_FLUX: f32 = std::f32::consts::PI * TWO_LIGHTS_AREA * 10.0;

/// [`TWO_LIGHTS_SCENE`], built.
pub fn two_lights_scene() -> Result<Scene, String> {
    let scene = text_scene("grader-two-lights", TWO_LIGHTS_SCENE)?;
    if scene.lights.len() != 2 {
        return Err(crate::tr!(
            "ex18.grader_two_lights",
            count = scene.lights.len()
        ));
    }
    Ok(scene)
}

/// The mean ratio that leaving out the light's choice gives in the
/// two-light box: each light's share comes with the probability of picking
/// it, P_l, and nothing divides it out: Σ_l P_l Φ_l / Σ_l Φ_l.
pub fn two_lights_choice_left_out(scene: &Scene) -> f64 {
    let (p0, p1) = (scene.light_pmf(0) as f64, scene.light_pmf(1) as f64);
    let power = |i: usize| scene.lights[i].power().max_element() as f64;
    let (f0, f1) = (power(0), power(1));
    (p0 * f0 + p1 * f1) / (f0 + f1)
}

/// The advice for a flux in the two-light box off by the ratio `r`, where
/// leaving out the light's choice gives `left_out` (exercises 17 and 18).
pub fn flux_without_the_choice(r: f64, left_out: f64) -> Option<String> {
    Some(if ratio_near(r, left_out) {
        crate::tr!("ex18.choice_flux", r)
    } else {
        no_usual_mistake(r)
    })
}

fn no_usual_mistake(r: f64) -> String {
    crate::tr!("ex18.no_usual_mistake", r)
}

/// Independent VPL sets of the two-light check, and light paths per set.
const TWO_LIGHT_SETS: u64 = 800;
const TWO_LIGHT_PATHS: u32 = 8;

/// The VPLs on each light and the first bounce's flux in the two-light box.
/// Each light's VPLs must weigh, summed over a set, the light's area on
/// average (each stands for its light over all the paths, whichever light
/// they picked); the VPLs one segment from the lights must carry the whole
/// emitted flux. Both are checked by [`MeanVar::check`] (|z| ≤ 5.5: a
/// correct solution fails with probability below 1e-7 per channel).
fn check_two_lights(generate: GenerateVplsFn) -> Result<(), String> {
    let scene = two_lights_scene()?;
    let choice_left_out = two_lights_choice_left_out(&scene);
    let mut on_light = [MeanVar::default(), MeanVar::default()];
    let mut first = MeanVar::default();
    for i in 0..TWO_LIGHT_SETS {
        let mut sampler = Sampler::new(186, i, 0);
        let vpls = generate(&scene, TWO_LIGHT_PATHS, Some(3), 1000, &mut sampler);
        let mut weights = [0.0f32; 2];
        let mut flux = Color::ZERO;
        for v in &vpls {
            match v {
                Vpl::Light { light, weight, .. } if (*light as usize) < 2 => {
                    weights[*light as usize] += weight;
                }
                Vpl::Surface {
                    power, segments: 1, ..
                } => flux += *power,
                _ => {}
            }
        }
        for (stats, w) in on_light.iter_mut().zip(weights) {
            stats.add(Color::splat(w));
        }
        first.add(flux);
    }
    for (l, stats) in on_light.iter().enumerate() {
        let pick = scene.light_pmf(l as u32) as f64;
        stats.check(
            &crate::tr!(
                "ex18.light_weights",
                p0 = scene.light_pmf(0),
                p1 = scene.light_pmf(1),
                l,
                paths = TWO_LIGHT_PATHS,
                area = TWO_LIGHTS_AREA
            ),
            Color::splat(TWO_LIGHTS_AREA),
            |r| {
                Some(if ratio_near(r, pick) {
                    crate::tr!("ex18.choice_weight", r)
                } else {
                    no_usual_mistake(r)
                })
            },
        )?;
    }
    first.check(
        &crate::tr!(
            "ex18.first_flux",
            paths = TWO_LIGHT_PATHS,
            flux = TWO_LIGHTS_FLUX
        ),
        Color::splat(TWO_LIGHTS_FLUX),
        |r| flux_without_the_choice(r, choice_left_out),
    )
}

// ---------------------------------------------------------------------------
// The clamped comparison's reference.

/// Independent VPL sets of the renderer's instant radiosity.
pub const REFERENCE_SETS: u64 = 4096;
/// Light paths per set of the reference.
pub const REFERENCE_PATHS: u64 = 16;

/// The renderer's instant radiosity averaged over [`REFERENCE_SETS`]
/// independent VPL sets: each pixel sample picks a set at random (its first
/// number) and gathers its VPLs with `InstantRadiosity::gather`; direct
/// light comes from one light sample whose geometry term is clamped at the
/// same bound (the renderer's own light sample is not clamped, the
/// student's VPLs on the light are). With one set, the reference would carry that set's error in
/// every pixel; the mixture's mean is the average over all the sets, whose
/// error is that of 65,536 light paths, far below a tile's noise in the
/// student's render.
#[derive(Debug)]
pub struct VplSetsReference {
    pub clamp: f32,
    sets: OnceLock<Vec<InstantRadiosity>>,
}

impl VplSetsReference {
    pub fn new(clamp: f32) -> Self {
        VplSetsReference {
            clamp,
            sets: OnceLock::new(),
        }
    }
}

impl Integrator for VplSetsReference {
    fn name(&self) -> &'static str {
        "vpl-sets"
    }

    fn sample(
        &self,
        scene: &Scene,
        pixel: UVec2,
        sampler: &mut Sampler,
        _splats: &mut Vec<Splat>,
    ) -> Color {
        let sets = self.sets.get_or_init(|| {
            (0..REFERENCE_SETS)
                .map(|seed| {
                    InstantRadiosity::build(
                        scene,
                        VplSettings {
                            paths: REFERENCE_PATHS,
                            clamp: self.clamp,
                            max_depth: Some(MAX_DEPTH),
                            rr_depth: RR_DEPTH,
                            seed,
                        },
                        &AtomicBool::new(false),
                    )
                    .expect("valid settings")
                })
                .collect()
        });
        let i = ((sampler.next_1d() * sets.len() as f32) as usize).min(sets.len() - 1);
        let ir = &sets[i];
        // The renderer's instant radiosity, its light sample with G clamped
        // as the VPLs' (see the type's doc).
        let vp = visible_point(scene, pixel, sampler, Some(MAX_DEPTH));
        let Some(x) = vp.hit else {
            return vp.le;
        };
        if vp.depth >= MAX_DEPTH {
            return vp.le;
        }
        let direct = clamped_light_sample(scene, &x, self.clamp, sampler);
        vp.le + vp.beta * (direct + ir.gather(scene, &x, vp.depth))
    }
}

/// Direct light at `x` from one light sample, with the geometry term
/// between `x` and the light point clamped at `clamp`: its expected value is
/// the light of VPLs on the lights, clamped as in the exercise.
fn clamped_light_sample(
    scene: &Scene,
    x: &Interaction,
    clamp: f32,
    sampler: &mut Sampler,
) -> Color {
    let Some(choice) = scene.choose_light(sampler.next_1d()) else {
        return Color::ZERO;
    };
    let Some(ls) = choice.light.sample_li(x.p, sampler.next_2d()) else {
        return Color::ZERO;
    };
    if ls.pdf_w <= 0.0 || ls.is_delta || !ls.dist.is_finite() {
        return Color::ZERO;
    }
    let f_x = scene
        .brdf(x)
        .eval(x.frame.to_local(x.wo), x.frame.to_local(ls.wi), x.uv);
    let cos_y = ls.n.dot(ls.wi).abs();
    let d2 = ls.dist * ls.dist;
    if f_x == Color::ZERO || cos_y == 0.0 {
        return Color::ZERO;
    }
    // The density per unit area of the light point, and G.
    let pdf_a = ls.pdf_w * cos_y / d2 * choice.pmf;
    let g = (x.frame.n.dot(ls.wi).abs() * cos_y / d2).min(clamp);
    if !scene.unoccluded(&Ray::spawn_to(x.p, x.ng, ls.p, ls.n)) {
        return Color::ZERO;
    }
    f_x * g * ls.li / pdf_a
}
