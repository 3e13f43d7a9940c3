//! Grader of exercise 15 (bidirectional path tracing): the geometry term
//! exactly; every strategy's connection exactly on subpaths the renderer's
//! random walks grow in a small test scene (Lambert, Phong, a mirror; a quad,
//! a sphere and a point light); the MIS weights exactly against the power
//! heuristic of the strategies' path densities, each computed by the grader
//! as a product of the vertices' area densities, on random paths of 1 to 4
//! segments (and their sum, 1 over the strategies that can make a path);
//! then the whole bidirectional path tracer built from the student's
//! functions against the renderer's BDPT in the Cornell box, tile by tile.
//!
//! Tolerances: G to 1e-4 relative, the disk irradiance |z| ≤ 5.5 (false
//! failure < 8e-8); connections to 1e-3 relative (f32 rounding of a few
//! products; the student may order them otherwise); weights to 1e-3
//! relative or 1e-4 absolute, their sums to 1e-3 (f32 running products of
//! up to five density ratios); the image comparison at family-wise
//! α = 1e-4 ([`crate::compare`]).

use exercises::plug::{BdptConnection, BdptWeightFn, ConnectFn, StudentBdpt};
use raytracer::integrator::subpath::{camera_subpath, light_subpath};
use raytracer::integrator::vertex::{Vertex, VertexKind, visible};
use raytracer::math::{Color, PI, UVec2, Vec2, Vec3A};
use raytracer::sampling::Sampler;
use raytracer::sampling::warp::concentric_disk;
use raytracer::scene::Scene;

use crate::bdpt_paths::{PathCase, random_path, test_scene};
use crate::compare::{EX15_CORNELL, compare};
use crate::stats::{MeanVar, Mistake, close, fmt3, recognise};

/// The signature of part 1.
pub type GeometryFn = fn(Vec3A, Vec3A, Vec3A, Vec3A) -> f32;

/// The grader's geometry term.
pub fn expected_g(x: Vec3A, nx: Vec3A, y: Vec3A, ny: Vec3A) -> f32 {
    let d = y - x;
    let w = d.normalize();
    nx.dot(w).abs() * ny.dot(w).abs() / d.length_squared()
}

pub const ESTIMATES: u64 = 20_000;

/// The Cornell box's max depth D in the image comparison.
pub const MAX_DEPTH: u32 = 4;

pub fn check(geometry: GeometryFn, connect: ConnectFn, weight: BdptWeightFn) -> Result<(), String> {
    check_geometry(geometry)?;
    let scene = test_scene();
    check_connect(&scene, connect)?;
    check_weights(&scene, weight)?;
    let student = StudentBdpt {
        connect,
        weight,
        max_depth: Some(MAX_DEPTH),
        rr_depth: 3,
    };
    compare(&EX15_CORNELL, &student).map_err(|e| crate::tr!("ex15.cornell", e))
}

// ── Part 1: G ────────────────────────────────────────────────────────────

/// A case of the geometry term: `(x, nx, y, ny)`.
type Edge = (Vec3A, Vec3A, Vec3A, Vec3A);

fn check_geometry(geometry: GeometryFn) -> Result<(), String> {
    // Distances and cosines chosen so that no mistake coincides with another
    // in every case (in one case 1/cos θ may equal r, not in all).
    let cases: Vec<Edge> = vec![
        (Vec3A::ZERO, Vec3A::Y, Vec3A::new(0.0, 2.0, 0.0), -Vec3A::Y),
        (Vec3A::ZERO, Vec3A::Y, Vec3A::new(1.0, 1.0, 0.5), -Vec3A::Y),
        (
            Vec3A::new(0.2, 0.1, -0.3),
            Vec3A::new(0.0, 0.6, 0.8),
            Vec3A::new(-1.0, 0.5, 2.0),
            Vec3A::X,
        ),
        (
            Vec3A::new(0.1, 0.0, 0.0),
            Vec3A::new(0.0, 0.8, 0.6),
            Vec3A::new(0.5, 0.3, 0.4),
            Vec3A::new(-0.6, 0.0, -0.8),
        ),
        // Normals facing away from the edge: the cosines' absolute values.
        (Vec3A::ZERO, -Vec3A::Y, Vec3A::new(0.5, 1.5, 0.0), Vec3A::Y),
        (Vec3A::ZERO, Vec3A::Y, Vec3A::new(0.5, 1.5, 0.0), Vec3A::Y),
    ];
    let got: Vec<f32> = cases
        .iter()
        .map(|&(x, nx, y, ny)| geometry(x, nx, y, ny))
        .collect();
    let want = |&(x, nx, y, ny): &Edge| expected_g(x, nx, y, ny);
    if let Some(k) = (0..cases.len()).find(|&k| !close(got[k], want(&cases[k]), 1e-4)) {
        let cx = |&(x, nx, y, _): &Edge| nx.dot((y - x).normalize());
        let cy = |&(x, _, y, ny): &Edge| ny.dot((x - y).normalize());
        let r2 = |&(x, _, y, _): &Edge| (y - x).length_squared();
        let mistakes: [Mistake<Edge, f32>; 5] = [
            (&crate::tr!("ex15.g_signed"), &|e| cx(e) * cy(e) / r2(e)),
            (&crate::tr!("ex15.g_r"), &|e| {
                (cx(e) * cy(e)).abs() / r2(e).sqrt()
            }),
            (&crate::tr!("ex15.g_no_cos_y"), &|e| cx(e).abs() / r2(e)),
            (&crate::tr!("ex15.g_no_cos_x"), &|e| cy(e).abs() / r2(e)),
            (&crate::tr!("ex15.g_no_falloff"), &|e| (cx(e) * cy(e)).abs()),
        ];
        let (x, nx, y, ny) = cases[k];
        let why = recognise(&cases, &got, &mistakes, |g, a| close(g, a, 1e-4))
            .unwrap_or_else(|| crate::tr!("ex15.g_unknown"));
        return Err(crate::tr!(
            "ex15.g",
            x = fmt3(x),
            nx = fmt3(nx),
            y = fmt3(y),
            ny = fmt3(ny),
            got = got[k],
            why
        ));
    }
    // The irradiance at the centre below a disk light of radiance 1, radius R,
    // height h: E = ∫ G dA = π R² / (h² + R²); uniform points on the disk.
    let (r, h) = (0.8f32, 1.0f32);
    let mut stats = MeanVar::default();
    for i in 0..ESTIMATES {
        let mut s = Sampler::new(15, i, 0);
        let d = r * concentric_disk(s.next_2d());
        let y = Vec3A::new(d.x, h, d.y);
        stats.add(Color::splat(
            geometry(Vec3A::ZERO, Vec3A::Y, y, -Vec3A::Y) * PI * r * r,
        ));
    }
    stats.check(
        &crate::tr!("ex15.disk"),
        Color::splat(PI * r * r / (h * h + r * r)),
        |_| None,
    )
}

// ── Part 2: the connections ──────────────────────────────────────────────

/// How the grader computes a connection: correctly, or with one mistake.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Way {
    Right,
    SignedCosines,
    RNotSquared,
    NoCosLight,
    NoCosCamera,
    CameraBrdfReversed,
    NoVisibility,
    NoBetaLight,
    LensNoCosine,
    PointLightDark,
}

/// The cosine a vertex uses, signed (with the normal it stores).
fn signed_cos(v: &Vertex, w: Vec3A) -> f32 {
    match v.kind {
        VertexKind::Surface => v.it.frame.n.dot(w),
        _ if v.is_on_surface() => v.it.ng.dot(w),
        _ => 1.0,
    }
}

/// The grader's connection of strategy `(s, t)` (`u` the lens sample),
/// computed `way`: the value and, for `t = 1`, the raster position.
fn expected_connect(
    scene: &Scene,
    light: &[Vertex],
    camera: &[Vertex],
    [s, t]: [usize; 2],
    u: Vec2,
    way: Way,
) -> (Color, Option<Vec2>) {
    let none = (Color::ZERO, None);
    if s == 0 {
        let z = &camera[t - 1];
        return (z.beta * z.le_towards(scene, &camera[t - 2]), None);
    }
    let y = &light[s - 1];
    if !y.is_connectible(scene) {
        return none;
    }
    let beta_y = if way == Way::NoBetaLight {
        Color::ONE
    } else {
        y.beta
    };
    if t == 1 {
        let Some(cs) = scene.camera.sample_wi(y.p(), u) else {
            return none;
        };
        let cos = match way {
            Way::LensNoCosine => 1.0,
            _ => y.abs_cos(cs.wi),
        };
        let value = beta_y * y.f_importance(scene, cs.wi) * (cos * cs.we / cs.pdf_w);
        let lens = Vertex::camera(cs.p_lens, Color::ZERO);
        if way != Way::NoVisibility && !visible(scene, y, &lens) {
            return none;
        }
        return (value, Some(cs.raster));
    }
    let z = &camera[t - 1];
    if !z.is_connectible(scene) || (way == Way::PointLightDark && !y.is_on_surface()) {
        return none;
    }
    let d = z.p() - y.p();
    let d2 = d.length_squared();
    let w = d / d2.sqrt();
    let (cy, cz) = (y.abs_cos(w), z.abs_cos(w));
    let g = match way {
        Way::SignedCosines => signed_cos(y, w) * signed_cos(z, -w) / d2,
        Way::RNotSquared => cy * cz / d2.sqrt(),
        Way::NoCosLight => cz / d2,
        Way::NoCosCamera => cy / d2,
        _ => cy * cz / d2,
    };
    let fz = if way == Way::CameraBrdfReversed {
        z.f(scene, w)
    } else {
        z.f(scene, -w)
    };
    let value = beta_y * y.f_importance(scene, w) * g * fz * z.beta;
    if way != Way::NoVisibility && !visible(scene, y, z) {
        return none;
    }
    (value, None)
}

/// One connection case: the two subpaths of a pixel sample and `(s, t)`.
struct Case {
    light: Vec<Vertex>,
    camera: Vec<Vertex>,
    st: [usize; 2],
}

/// A colour in scientific notation (connections span many magnitudes).
fn sci(c: Color) -> String {
    format!("({:.4e}, {:.4e}, {:.4e})", c.x, c.y, c.z)
}

fn same_color(a: Color, b: Color) -> bool {
    (a - b)
        .abs()
        .cmple(Color::splat(1e-3) * b.abs().max(Color::splat(1e-6)))
        .all()
        || (a - b).abs().max_element() <= 1e-6
}

fn check_connect(scene: &Scene, connect: ConnectFn) -> Result<(), String> {
    let (w, h) = (scene.camera.width, scene.camera.height);
    let mut cases = Vec::new();
    let (mut camera, mut light) = (Vec::new(), Vec::new());
    for i in 0..400u64 {
        let mut sampler = Sampler::new(1515, i, 0);
        let pixel = UVec2::new((i * 37 % w as u64) as u32, (i * 53 % h as u64) as u32);
        camera_subpath(scene, pixel, &mut sampler, &mut camera, 5, 1000);
        light_subpath(scene, &mut sampler, &mut light, 4, 1000);
        for t in 1..=camera.len() {
            for s in 0..=light.len() {
                if s + t < 2 || s + t > 5 {
                    continue;
                }
                cases.push(Case {
                    light: light.clone(),
                    camera: camera.clone(),
                    st: [s, t],
                });
            }
        }
    }
    let u = Vec2::new(0.5, 0.5);
    let got: Vec<(Color, Option<Vec2>)> = cases
        .iter()
        .enumerate()
        .map(|(k, c)| {
            let mut sampler = Sampler::new(1516, k as u64, 0);
            match connect(scene, &c.light, &c.camera, c.st[0], c.st[1], &mut sampler) {
                Some(BdptConnection { value, raster, .. }) => (value, raster),
                None => (Color::ZERO, None),
            }
        })
        .collect();
    let want = |c: &Case, way| expected_connect(scene, &c.light, &c.camera, c.st, u, way);
    let wrong = |k: usize| {
        let (g, e) = (got[k], want(&cases[k], Way::Right));
        !same_color(g.0, e.0)
            || (e.0 != Color::ZERO && e.1.is_some() != g.1.is_some()
                || e.1.zip(g.1).is_some_and(|(a, b)| a.distance(b) > 1e-3))
    };
    let Some(k) = (0..cases.len()).find(|&k| wrong(k)) else {
        return Ok(());
    };
    let values: Vec<Color> = got.iter().map(|g| g.0).collect();
    let model = |way: Way| move |c: &Case| want(c, way).0;
    let m9 = model(Way::PointLightDark);
    let (m1, m2, m3, m4, m5, m6, m7, m8) = (
        model(Way::SignedCosines),
        model(Way::RNotSquared),
        model(Way::NoCosLight),
        model(Way::NoCosCamera),
        model(Way::CameraBrdfReversed),
        model(Way::NoVisibility),
        model(Way::NoBetaLight),
        model(Way::LensNoCosine),
    );
    let mistakes: [Mistake<Case, Color>; 9] = [
        (&crate::tr!("ex15.c_signed"), &m1),
        (&crate::tr!("ex15.c_r"), &m2),
        (&crate::tr!("ex15.c_no_cos_light"), &m3),
        (&crate::tr!("ex15.c_no_cos_camera"), &m4),
        (&crate::tr!("ex15.c_brdf_reversed"), &m5),
        (&crate::tr!("ex15.c_no_visibility"), &m6),
        (&crate::tr!("ex15.c_no_beta_light"), &m7),
        (&crate::tr!("ex15.c_lens_no_cosine"), &m8),
        (&crate::tr!("ex15.c_point_light"), &m9),
    ];
    let why = recognise(&cases, &values, &mistakes, same_color).unwrap_or_else(|| {
        let [s, t] = cases[k].st;
        match (s, t) {
            (0, _) => crate::tr!("ex15.c_s0"),
            (_, 1) => crate::tr!("ex15.c_t1"),
            (1, _) => crate::tr!("ex15.c_s1"),
            _ => crate::tr!("ex15.c_edge"),
        }
    });
    let c = &cases[k];
    let e = want(c, Way::Right);
    let raster = match (got[k].1, e.1) {
        (g, Some(r)) if g.is_none_or(|g| g.distance(r) > 1e-3) => {
            crate::tr!("ex15.raster", r = format!("{r:?}"), g = format!("{g:?}"))
        }
        _ => String::new(),
    };
    Err(crate::tr!(
        "ex15.connect",
        s = c.st[0],
        t = c.st[1],
        camera = c.camera.len(),
        light = c.light.len(),
        got = sci(got[k].0),
        want = sci(e.0),
        raster,
        why
    ))
}

// ── Part 3: the weights ──────────────────────────────────────────────────

/// A weight computed from a path, its strategies' densities and the possible ones.
type WeightOf<'a> = dyn Fn(&PathCase, &[f64], &[usize]) -> f64 + 'a;

/// One weight case: a path and a strategy.
struct WeightCase {
    path: usize,
    s: usize,
}

fn same_weight(a: f32, b: f32) -> bool {
    (a - b).abs() <= 1e-4_f32.max(1e-3 * b.abs())
}

fn check_weights(scene: &Scene, weight: BdptWeightFn) -> Result<(), String> {
    let mut paths = Vec::new();
    let mut sampler = Sampler::new(1517, 0, 0);
    for n in 2..=5usize {
        for light in 0..3u32 {
            for mirror in [false, true] {
                if mirror && n < 4 {
                    continue;
                }
                let mut found = 0;
                let mut tries = 0;
                while found < 6 && tries < 500 {
                    tries += 1;
                    if let Some(p) = random_path(scene, n, light, mirror, &mut sampler) {
                        paths.push(p);
                        found += 1;
                    }
                }
            }
        }
    }
    let mut cases = Vec::new();
    for (k, p) in paths.iter().enumerate() {
        // Not s = 0 on a point light: no camera path ends there, and
        // bidirectional tracing never asks.
        for s in (0..p.n()).filter(|&s| s > 0 || !p.point_light) {
            cases.push(WeightCase { path: k, s });
        }
    }
    let got: Vec<f32> = cases
        .iter()
        .map(|c| {
            let p = &paths[c.path];
            let (light, camera) = p.subpaths(c.s);
            let t = p.n() - c.s;
            weight(scene, &light, &camera, c.s, t, None)
        })
        .collect();
    let expected: Vec<f32> = cases
        .iter()
        .map(|c| paths[c.path].expected(c.s) as f32)
        .collect();
    let Some(k) = (0..cases.len()).find(|&k| !same_weight(got[k], expected[k])) else {
        return Ok(());
    };
    // What the usual mistakes give.
    let possible = |p: &PathCase| (0..p.n()).filter(|&i| p.possible(i)).collect::<Vec<_>>();
    let with = |c: &WeightCase, f: &WeightOf<'_>| {
        let p = &paths[c.path];
        if !p.possible(c.s) {
            return 0.0;
        }
        f(p, &p.densities(), &possible(p)) as f32
    };
    let balance = |c: &WeightCase| {
        with(c, &|_, d, ok| {
            d[c.s] / ok.iter().map(|&i| d[i]).sum::<f64>()
        })
    };
    let by_max = |c: &WeightCase| {
        with(c, &|_, d, ok| {
            let m = ok.iter().map(|&i| d[i]).fold(0.0, f64::max);
            d[c.s] * d[c.s] / (m * m)
        })
    };
    let solid_angle = |c: &WeightCase| {
        with(c, &|p, _, ok| {
            let d: Vec<f64> = (0..p.n())
                .map(|s| p.density(s, &p.w_cam, &p.w_light))
                .collect();
            p.power(c.s, &d, ok.iter().copied())
        })
    };
    let solid_angle_edge = |c: &WeightCase| {
        with(c, &|p, _, ok| {
            // Only the four densities across the edge in solid angle.
            let n = p.n();
            let t = n - c.s;
            let mut cam = p.p_cam.clone();
            let mut light = p.p_light.clone();
            for j in [t, t + 1] {
                if j < n {
                    cam[j] = p.w_cam[j];
                }
            }
            for j in [t.wrapping_sub(1), t.wrapping_sub(2)] {
                if (1..n - 1).contains(&j) {
                    light[j] = p.w_light[j];
                }
            }
            let d: Vec<f64> = (0..n).map(|s| p.density(s, &cam, &light)).collect();
            p.power(c.s, &d, ok.iter().copied())
        })
    };
    let no_s0 = |c: &WeightCase| {
        with(c, &|p, d, ok| {
            let ok: Vec<usize> = ok.iter().copied().filter(|&i| i != 0 || c.s == 0).collect();
            p.power(c.s, d, ok.into_iter())
        })
    };
    let no_t1 = |c: &WeightCase| {
        with(c, &|p, d, ok| {
            let n = p.n();
            let ok: Vec<usize> = ok
                .iter()
                .copied()
                .filter(|&i| i != n - 1 || c.s == n - 1)
                .collect();
            p.power(c.s, d, ok.into_iter())
        })
    };
    let deltas_counted = |c: &WeightCase| {
        let p = &paths[c.path];
        if !p.possible(c.s) {
            return 0.0;
        }
        let d = p.densities();
        let all = (0..p.n()).filter(|&i| i > 0 || !p.point_light);
        p.power(c.s, &d, all) as f32
    };
    let stale = |c: &WeightCase| {
        // The reverse densities next to the edge used as stored (stale).
        with(c, &|p, _, ok| {
            let n = p.n();
            let t = n - c.s;
            let mut cam = p.p_cam.clone();
            let mut light = p.p_light.clone();
            for j in [t, t + 1] {
                if j < n {
                    cam[j] *= 0.5;
                }
            }
            for j in [t.wrapping_sub(1), t.wrapping_sub(2)] {
                if (1..n).contains(&j) {
                    light[j] *= 0.5;
                }
            }
            let d: Vec<f64> = (0..n).map(|s| p.density(s, &cam, &light)).collect();
            p.power(c.s, &d, ok.iter().copied())
        })
    };
    let mistakes: [Mistake<WeightCase, f32>; 8] = [
        (&crate::tr!("ex15.w_balance"), &balance),
        (&crate::tr!("ex15.w_by_max"), &by_max),
        (&crate::tr!("ex15.w_solid_angle"), &solid_angle),
        (&crate::tr!("ex15.w_solid_angle_edge"), &solid_angle_edge),
        (&crate::tr!("ex15.w_no_s0"), &no_s0),
        (&crate::tr!("ex15.w_no_t1"), &no_t1),
        (&crate::tr!("ex15.w_delta"), &deltas_counted),
        (&crate::tr!("ex15.w_stale"), &stale),
    ];
    let c = &cases[k];
    let p = &paths[c.path];
    let n = p.n();
    let light = match p.light_side[n - 1].light {
        0 => crate::tr!("ex15.quad_lamp"),
        1 => crate::tr!("ex15.sphere_lamp"),
        _ => crate::tr!("ex15.point_light"),
    };
    let mirror = if p.delta.iter().any(|&d| d) {
        crate::tr!("ex15.with_mirror")
    } else {
        String::new()
    };
    let what = crate::tr!("ex15.weight_what", s = c.s, t = n - c.s, n, light, mirror);
    if !p.possible(c.s) && got[k] != 0.0 {
        return Err(crate::tr!("ex15.impossible", what, got = got[k]));
    }
    if !got[k].is_finite() {
        return Err(crate::tr!("ex15.not_a_number", what, got = got[k]));
    }
    let why = recognise(&cases, &got, &mistakes, same_weight).unwrap_or_else(|| {
        let sum: f32 = cases
            .iter()
            .zip(&got)
            .filter(|(d, _)| d.path == c.path)
            .map(|(_, &g)| g)
            .sum();
        if (sum - 1.0).abs() > 1e-3 && sum > 1.0 {
            crate::tr!("ex15.sum_bright", sum)
        } else if (sum - 1.0).abs() > 1e-3 {
            crate::tr!("ex15.sum_dark", sum)
        } else {
            crate::tr!("ex15.not_power")
        }
    });
    Err(crate::tr!(
        "ex15.weight",
        what,
        got = got[k],
        want = expected[k],
        why
    ))
}
