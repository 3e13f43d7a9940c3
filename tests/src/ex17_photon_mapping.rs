//! Grader of exercise 17 (photon mapping: photon tracing and the radiance
//! estimate), in four layers:
//!
//! 1. the estimate exactly, over hand-made photon maps (a tilted surface, a
//!    glossy and a diffuse BRDF, k nearest with more, exactly and fewer than
//!    k candidates, a fixed radius): the usual mistakes are named by
//!    comparing all cases at once; then its lack of bias where the photon
//!    density is uniform (the k = 20 nearest of 400 photons spread uniformly
//!    over the unit disk: the density 400/π exactly in expectation);
//! 2. the photon tracer in the closed furnace (L_e = 0.5, ρ = 0.5 on the
//!    inside of a unit sphere, emitted flux Φ = π L_e A = 2π²): the photons
//!    that travelled k segments carry Φ ρ^(k−1) in total, k = 1, 2, 3
//!    before roulette and k = 6 after it; every photon lies on the sphere
//!    with `wi` pointing back inside; none is kept on glass (the caustic
//!    scene);
//! 3. the whole photon mapper in the furnace: L = 1 exactly (no bias: the
//!    photon density is uniform, and on a sphere a cap of chord radius r
//!    has area π r² exactly), with the k nearest and with a fixed radius,
//!    over [`FURNACE_MAPS`] independent photon maps;
//! 4. the caustic scene tile by tile against the renderer's photon mapping
//!    with the same photons, radius and roulette ([`compare_caustic`]): the
//!    student's tile means over [`STUDENT_MAPS`] independent photon maps
//!    against the reference's over [`REFERENCE_MAPS`].
//!
//! Tolerances: exact values to 1e-4 relative; the means of layers 1–3
//! |z| ≤ 5.5 with the student's own standard error (false failure below
//! 4e-8 per channel for layers 1 and 2; for layer 3, 40 maps, Student's t
//! with 39 degrees of freedom: below 3e-6 per case); layer 4 at
//! family-wise α = 1e-4 with the t quantile of [`STUDENT_MAPS`] − 1
//! degrees of freedom (the tile means of independent photon maps are
//! independent, so the student's variance estimate includes the photon
//! map's randomness; pixels of one map are not independent of each other,
//! which is why the variance is taken over maps, tile by tile). Measured:
//! over 25 seeds of the reference solution the largest |z| stayed below
//! 0.52 of the threshold, over 24 of a fixture with another roulette below
//! 0.60 (`check_grader`'s `ex17_caustic_comparison_over_seeds`);
//! the whole grading takes about 1 s in the test profile.

use std::path::{Path, PathBuf};

use exercises::plug::{StudentPhotonMapping, trace_photons_with};
use raytracer::brdf::{Brdf, Lambert, Phong, Texture};
use raytracer::film::Image;
use raytracer::frame::Frame;
use raytracer::integrator::photon::{Photon, photon_sample_index};
use raytracer::integrator::photon_map::{PhotonMap, Search};
use raytracer::integrator::{Integrator, PhotonMapping, PhotonSettings};
use raytracer::math::{Color, PI, Ray, Vec2, Vec3, Vec3A};
use raytracer::metrics::tile_means;
use raytracer::render::{RenderOptions, render};
use raytracer::sampling::Sampler;
use raytracer::sampling::warp::concentric_disk;
use raytracer::scene::{Interaction, Scene};

use crate::ex18_instant_radiosity::{
    TWO_LIGHTS_FLUX, flux_without_the_choice, two_lights_choice_left_out, two_lights_scene,
};
use crate::pictures::write_enlarged;
use crate::stats::{MeanVar, fmt3, output_dir};

/// The signatures of exercise 17.
pub use exercises::plug::{PhotonRadianceFn as RadianceFn, TracePhotonPathFn as TraceFn};

/// Trials of the uniform-density estimate, photons per trial, k.
pub const TRIALS: u64 = 1_000;
pub const PHOTONS: u64 = 400;
pub const K: usize = 20;

/// Light paths of the furnace's flux test.
pub const FLUX_PATHS: u64 = 4_000;
/// Roulette from this many bounces on in the flux test.
pub const FLUX_RR: u32 = 3;

/// Independent photon maps of the whole mapper in the furnace, and their size.
pub const FURNACE_MAPS: u64 = 40;
pub const FURNACE_PATHS: u64 = 1_000;

/// Flux emitted into the furnace: π L_e A = π · 0.5 · 4π.
const FURNACE_FLUX: f32 = 2.0 * PI * PI;

// ---------------------------------------------------------------------------
// 1. The estimate, exactly.

/// A case: the map, the hit, its BRDF, the search.
type Case = (PhotonMap, Interaction, Brdf, Search);

/// The usual mistakes of the estimate, computed by [`variant`].
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum V {
    #[cfg_attr(not(test), allow(dead_code))]
    Right,
    BoxKernel,
    BoxConstant,
    NoPi,
    RadiusNotSquared,
    HalfRadius,
    KPlusOne,
    MeanDistance,
    FewerFarthest,
    AllWithinMax,
    LinearKernel,
    Cosine,
    WorldFrame,
    TravelDirection,
}

/// What a solution that makes mistake `v` answers in case `c`.
pub fn variant((map, it, brdf, search): &Case, v: V) -> Color {
    let mut near: Vec<(f32, Photon)> = Vec::new();
    map.for_each_within(
        it.p,
        search.max_radius(),
        |_| true,
        |_, ph, d2| near.push((d2, *ph)),
    );
    near.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut r2 = match *search {
        Search::Radius(r) => r * r,
        Search::Nearest { k, max_radius } => {
            if near.len() > k {
                match v {
                    V::KPlusOne => near[k].0,
                    V::MeanDistance => {
                        let m = near[..k].iter().map(|p| p.0.sqrt()).sum::<f32>() / k as f32;
                        m * m
                    }
                    V::AllWithinMax => max_radius * max_radius,
                    _ => near[k - 1].0,
                }
            } else if v == V::FewerFarthest {
                near.last().map_or(0.0, |p| p.0)
            } else {
                max_radius * max_radius
            }
        }
    };
    if v == V::HalfRadius {
        r2 /= 4.0;
    }
    if r2 <= 0.0 {
        return Color::ZERO;
    }
    let wo = it.frame.to_local(it.wo);
    let mut l = Color::ZERO;
    for &(d2, ph) in &near {
        if d2 >= r2 {
            continue;
        }
        let kernel = match v {
            V::BoxKernel => 1.0 / (PI * r2),
            V::BoxConstant => 1.0 / (PI * r2) * (1.0 - d2 / r2),
            V::NoPi => 2.0 / r2 * (1.0 - d2 / r2),
            V::RadiusNotSquared => 2.0 / (PI * r2.sqrt()) * (1.0 - d2 / r2),
            V::LinearKernel => 2.0 / (PI * r2) * (1.0 - (d2 / r2).sqrt()),
            _ => 2.0 / (PI * r2) * (1.0 - d2 / r2),
        };
        let wi_world = Vec3A::from(ph.wi);
        let f = match v {
            V::WorldFrame => brdf.eval(it.wo, wi_world, it.uv),
            V::TravelDirection => brdf.eval(wo, it.frame.to_local(-wi_world), it.uv),
            _ => brdf.eval(wo, it.frame.to_local(wi_world), it.uv),
        };
        let cos = if v == V::Cosine {
            it.frame.n.dot(wi_world).abs()
        } else {
            1.0
        };
        l += f * Color::from(ph.power) * (kernel * cos);
    }
    l
}

/// A hit at `x` with normal `n`, viewed from `wo`.
fn hit(x: Vec3A, n: Vec3A, wo: Vec3A) -> Interaction {
    Interaction {
        p: x,
        ng: n,
        frame: Frame::from_normal(n),
        uv: Vec2::ZERO,
        wo: wo.normalize(),
        t: 1.0,
        shape: 0,
        p_error: Vec3A::ZERO,
    }
}

/// `n` photons around `it.p` in its tangent plane, at distances up to
/// `reach`, from directions all over the upper hemisphere, with varied
/// colours (a fixed stream of numbers per `seed`).
fn photons_around(it: &Interaction, n: u32, reach: f32, seed: u64) -> Vec<Photon> {
    (0..n)
        .map(|i| {
            let mut s = Sampler::new(seed, i as u64, 0);
            let (a, b, c) = (s.next_2d(), s.next_2d(), s.next_2d());
            let d = reach * a.x.sqrt();
            let phi = 2.0 * PI * a.y;
            let local = Vec3A::new(d * phi.cos(), d * phi.sin(), 0.0);
            let z = 0.05 + 0.95 * b.x;
            let r = (1.0 - z * z).sqrt();
            let wi = Vec3A::new(r * (2.0 * PI * b.y).cos(), r * (2.0 * PI * b.y).sin(), z);
            Photon {
                p: Vec3::from(it.p + it.frame.to_world(local)),
                wi: Vec3::from(it.frame.to_world(wi)),
                power: Vec3::new(0.2 + c.x, 0.3 + 0.5 * c.y, 1.2 - c.x),
                segments: 2,
            }
        })
        .collect()
}

pub fn cases() -> Vec<Case> {
    let glossy = Brdf::Phong(Phong {
        albedo: Color::new(0.8, 0.6, 0.4),
        exponent: 3.0,
    });
    let diffuse = Brdf::Lambert(Lambert {
        albedo: Texture::Constant(Color::new(0.7, 0.5, 0.3)),
    });
    let tilted = Vec3A::new(0.3, 1.0, 0.2).normalize();
    let it = hit(
        Vec3A::new(0.2, -0.1, 0.4),
        tilted,
        Vec3A::new(-0.4, 1.0, 0.3),
    );
    let it2 = hit(
        Vec3A::new(-1.0, 0.5, 0.0),
        Vec3A::Z,
        Vec3A::new(0.5, 0.2, 1.0),
    );
    let map = |it: &Interaction, n, reach, seed, max_r| {
        PhotonMap::build(photons_around(it, n, reach, seed), max_r)
    };
    vec![
        // More candidates than k, some beyond the largest radius.
        (
            map(&it, 30, 0.8, 1, 0.5),
            it,
            glossy.clone(),
            Search::Nearest {
                k: 6,
                max_radius: 0.5,
            },
        ),
        (
            map(&it2, 40, 0.5, 2, 0.4),
            it2,
            diffuse.clone(),
            Search::Nearest {
                k: 9,
                max_radius: 0.4,
            },
        ),
        // Fewer than k within the largest radius: all of them, over its disk.
        (
            map(&it, 7, 0.35, 3, 0.4),
            it,
            glossy.clone(),
            Search::Nearest {
                k: 10,
                max_radius: 0.4,
            },
        ),
        // A fixed radius.
        (
            map(&it2, 25, 0.6, 4, 0.35),
            it2,
            glossy.clone(),
            Search::Radius(0.35),
        ),
        (
            map(&it, 50, 0.5, 5, 0.25),
            it,
            diffuse,
            Search::Nearest {
                k: 12,
                max_radius: 0.25,
            },
        ),
        (map(&it2, 60, 1.2, 6, 0.9), it2, glossy, Search::Radius(0.9)),
    ]
}

fn search_text(s: &Search) -> String {
    match *s {
        Search::Radius(r) => format!("Search::Radius({r})"),
        Search::Nearest { k, max_radius } => {
            format!("Search::Nearest {{ k: {}, max_radius: {} }}", k, max_radius)
        }
    }
}

/// Layer 1: the estimate over hand-made maps, then uniform photons.
pub fn check_estimate(radiance: RadianceFn) -> Result<(), String> {
    let cases = cases();
    let got: Vec<Color> = cases
        .iter()
        .map(|(m, it, b, s)| radiance(m, it, b, *s))
        .collect();
    let expected: Vec<Color> = cases
        .iter()
        .map(|(m, it, b, s)| m.radiance(it, b, *s, |_| true))
        .collect();
    let same = |g: Color, e: Color| {
        let scale = e.abs().max_element().max(1e-3);
        (g - e).abs().max_element() <= 1e-4 * scale
    };
    if let Some(i) = (0..cases.len()).find(|&i| !same(got[i], expected[i])) {
        let named: [(&str, V); 13] = [
            (&crate::tr!("ex17.e_box"), V::BoxKernel),
            (&crate::tr!("ex17.e_box_constant"), V::BoxConstant),
            (&crate::tr!("ex17.e_no_pi"), V::NoPi),
            (&crate::tr!("ex17.e_radius"), V::RadiusNotSquared),
            (&crate::tr!("ex17.e_half_radius"), V::HalfRadius),
            (&crate::tr!("ex17.e_k_plus_one"), V::KPlusOne),
            (&crate::tr!("ex17.e_mean_distance"), V::MeanDistance),
            (&crate::tr!("ex17.e_fewer"), V::FewerFarthest),
            (&crate::tr!("ex17.e_all_within"), V::AllWithinMax),
            (&crate::tr!("ex17.e_linear"), V::LinearKernel),
            (&crate::tr!("ex17.e_cosine"), V::Cosine),
            (&crate::tr!("ex17.e_world"), V::WorldFrame),
            (&crate::tr!("ex17.e_travel"), V::TravelDirection),
        ];
        // The mistake whose answers agree with the student's in every case.
        let known = named
            .iter()
            .find(|(_, v)| {
                cases
                    .iter()
                    .zip(&got)
                    .all(|(c, &g)| same(g, variant(c, *v)))
            })
            .map(|(why, _)| why.to_string());
        let why = known.unwrap_or_else(|| {
            let ratio = got[i].element_sum() / expected[i].element_sum();
            crate::tr!("ex17.e_unknown", ratio)
        });
        let (map, _, brdf, search) = &cases[i];
        let brdf = if matches!(brdf, Brdf::Phong(_)) {
            crate::tr!("ex17.glossy")
        } else {
            crate::tr!("ex17.diffuse")
        };
        return Err(crate::tr!(
            "ex17.estimate",
            photons = map.len(),
            brdf,
            search = search_text(search),
            got = fmt3(got[i]),
            want = fmt3(expected[i]),
            why
        ));
    }
    // No photon near x.
    let (_, it, brdf, _) = &cases[0];
    let far = PhotonMap::build(
        vec![Photon {
            p: Vec3::from(it.p + Vec3A::splat(3.0)),
            wi: Vec3::from(it.frame.n),
            power: Vec3::ONE,
            segments: 2,
        }],
        0.5,
    );
    let none = radiance(
        &far,
        it,
        brdf,
        Search::Nearest {
            k: 3,
            max_radius: 0.5,
        },
    );
    if none != Color::ZERO {
        return Err(crate::tr!("ex17.no_photon", got = fmt3(none)));
    }
    uniform_density(radiance)
}

/// The k nearest of uniform photons: no bias (see the module doc).
fn uniform_density(radiance: RadianceFn) -> Result<(), String> {
    let rho = 0.5;
    let brdf = Brdf::Lambert(Lambert {
        albedo: Texture::Constant(Color::splat(rho)),
    });
    let it = hit(Vec3A::ZERO, Vec3A::Y, Vec3A::new(0.2, 1.0, 0.1));
    let mut stats = MeanVar::default();
    for t in 0..TRIALS {
        let photons = (0..PHOTONS)
            .map(|i| {
                let mut s = Sampler::new(16, t * PHOTONS + i, 0);
                let d = concentric_disk(s.next_2d());
                Photon {
                    p: Vec3::new(d.x, 0.0, d.y),
                    wi: Vec3::new(0.3, 0.9, -0.2).normalize(),
                    power: Vec3::ONE,
                    segments: 2,
                }
            })
            .collect();
        let map = PhotonMap::build(photons, 1.0);
        stats.add(radiance(
            &map,
            &it,
            &brdf,
            Search::Nearest {
                k: K,
                max_radius: 1.0,
            },
        ));
    }
    stats.check(
        &crate::tr!("ex17.uniform"),
        Color::splat(rho / PI * PHOTONS as f32 / PI),
        |ratio| {
            ((ratio - K as f64 / (K - 1) as f64).abs() < 0.01)
                .then(|| crate::tr!("ex17.uniform_edge"))
        },
    )
}

// ---------------------------------------------------------------------------
// 2. The photon tracer.

fn builtin(name: &str) -> Result<Scene, String> {
    Scene::builtin(name).map_err(|e| format!("grader: {e}"))
}

/// Layer 2: the flux per depth in the furnace, where the photons lie, and
/// none on glass.
pub fn check_tracing(trace: TraceFn) -> Result<(), String> {
    let furnace = builtin("furnace")?;
    let depths = [1u32, 2, 3, 6];
    let mut stats: Vec<MeanVar> = depths.iter().map(|_| MeanVar::default()).collect();
    let mut photons = Vec::new();
    for i in 0..FLUX_PATHS {
        photons.clear();
        let mut sampler = Sampler::new(5, i, photon_sample_index(0));
        trace(&furnace, FLUX_PATHS, FLUX_RR, &mut sampler, &mut photons);
        for ph in &photons {
            let p = Vec3A::from(ph.p);
            if (p.length() - 1.0).abs() > 1e-3 {
                return Err(crate::tr!("ex17.not_on_sphere", p = fmt3(p)));
            }
            let wi = Vec3A::from(ph.wi);
            if (wi.length() - 1.0).abs() > 1e-3 || wi.dot(-p) <= 0.0 {
                return Err(crate::tr!("ex17.wi_back", p = fmt3(p), wi = fmt3(wi)));
            }
            if ph.segments == 0 {
                return Err(crate::tr!("ex17.zero_segments"));
            }
            if !Vec3A::from(ph.power).is_finite() {
                return Err(crate::tr!(
                    "ex17.power_nonfinite",
                    power = fmt3(Vec3A::from(ph.power))
                ));
            }
        }
        for (s, &k) in stats.iter_mut().zip(&depths) {
            let total: Vec3A = photons
                .iter()
                .filter(|p| p.segments == k)
                .map(|p| Vec3A::from(p.power))
                .sum();
            s.add(total * FLUX_PATHS as f32);
        }
    }
    for (s, &k) in stats.iter().zip(&depths) {
        let exact = FURNACE_FLUX * 0.5f32.powi(k as i32 - 1);
        let n = FLUX_PATHS as f64;
        s.check(
            &crate::tr!(
                "ex17.flux",
                k,
                paths = FLUX_PATHS,
                rr = FLUX_RR,
                exponent = k - 1
            ),
            Color::splat(exact),
            |r| {
                Some(if (r / n - 1.0).abs() < 0.05 {
                    crate::tr!("ex17.flux_not_shared")
                } else if (r - 2.0 / 3.0).abs() < 0.03 {
                    crate::tr!("ex17.flux_cos_hit")
                } else if k == 1 && (r - 2.0).abs() < 0.3 {
                    crate::tr!("ex17.flux_cos_light", r)
                } else if k == 1 && (r - 0.5).abs() < 0.03 {
                    crate::tr!("ex17.flux_sides")
                } else if k == 1 {
                    crate::tr!("ex17.flux_start", r)
                } else if k <= FLUX_RR + 1 {
                    crate::tr!("ex17.flux_bounce", bounces = k - 1, r)
                } else if r < 1.0 {
                    crate::tr!("ex17.flux_roulette_dark", r)
                } else {
                    crate::tr!("ex17.flux_roulette_bright", r)
                })
            },
        )?;
    }
    // No photon on glass: the caustic scene's glass ball.
    let caustic = builtin("caustic")?;
    let photons = trace_photons_with(&caustic, trace, 3_000, 5, 7);
    for ph in &photons {
        let (p, wi) = (Vec3A::from(ph.p), Vec3A::from(ph.wi));
        let probe = Ray::new(p + 1e-3 * wi, -wi);
        if let Some(it) = caustic.intersect(&probe)
            && it.t < 2e-3
            && caustic.brdf(&it).is_delta()
        {
            return Err(crate::tr!("ex17.on_glass", p = fmt3(p)));
        }
    }
    if !photons.iter().any(|p| p.segments >= 3) {
        return Err(crate::tr!("ex17.no_caustic_photons"));
    }
    Ok(())
}

// ---------------------------------------------------------------------------
// 3. The whole photon mapper in the furnace.

/// Light paths traced in the two-light box, and the N that shares their flux.
const TWO_LIGHT_TRACED: u64 = 400;
const TWO_LIGHT_PATHS: u64 = 16;

/// Two lights of unequal power in a closed box (exercise 18's
/// [`crate::ex18_instant_radiosity::TWO_LIGHTS_SCENE`]): the photon one
/// segment from the light, times the N paths that share the flux, must
/// carry the whole emitted flux, whichever light the path picked. Checked
/// by [`MeanVar::check`] (|z| ≤ 5.5: a correct tracer fails with
/// probability below 1e-7 per channel). Roulette from the second bounce
/// ends the paths in the closed box; it does not touch the first photons.
pub fn check_two_lights(trace: TraceFn) -> Result<(), String> {
    let scene = two_lights_scene()?;
    let choice_left_out = two_lights_choice_left_out(&scene);
    let mut first = MeanVar::default();
    let mut photons = Vec::new();
    for i in 0..TWO_LIGHT_TRACED {
        photons.clear();
        let mut sampler = Sampler::new(17, i, photon_sample_index(0));
        trace(&scene, TWO_LIGHT_PATHS, 2, &mut sampler, &mut photons);
        let flux: Vec3A = photons
            .iter()
            .filter(|p| p.segments == 1)
            .map(|p| Vec3A::from(p.power))
            .sum();
        first.add(flux * TWO_LIGHT_PATHS as f32);
    }
    first.check(
        &crate::tr!(
            "ex17.two_lights",
            p0 = scene.light_pmf(0),
            p1 = scene.light_pmf(1),
            paths = TWO_LIGHT_PATHS,
            flux = TWO_LIGHTS_FLUX
        ),
        Color::splat(TWO_LIGHTS_FLUX),
        |r| flux_without_the_choice(r, choice_left_out),
    )
}

/// Layer 3: L = 1 in the furnace, with the k nearest and with a radius.
pub fn check_furnace(trace: TraceFn, radiance: RadianceFn) -> Result<(), String> {
    let mut furnace = builtin("furnace")?;
    furnace.set_resolution(8, 8);
    for (what, k, radius) in [
        (crate::tr!("ex17.furnace_nearest"), 20, None),
        (crate::tr!("ex17.furnace_radius"), 20, Some(0.25f32)),
    ] {
        let mut stats = MeanVar::default();
        for m in 0..FURNACE_MAPS {
            let pm = StudentPhotonMapping::with(
                trace,
                radiance,
                settings(FURNACE_PATHS, k, radius, 3, 100 + m),
            );
            let r = render(&furnace, &pm, &options(2, m));
            stats.add(raytracer::metrics::mean(&r.film.image()));
        }
        stats.check(
            &crate::tr!(
                "ex17.furnace",
                maps = FURNACE_MAPS,
                paths = FURNACE_PATHS,
                what
            ),
            Color::ONE,
            |r| {
                let f = (r - 0.75) / 0.25;
                let why = if (f - PI as f64).abs() < 0.1 {
                    crate::tr!("ex17.furnace_pi")
                } else if (f - 2.0 / 3.0).abs() < 0.05 {
                    crate::tr!("ex17.furnace_cos")
                } else if f < 0.05 {
                    crate::tr!("ex17.furnace_nothing")
                } else {
                    String::new()
                };
                Some(crate::tr!("ex17.furnace_share", f, why))
            },
        )?;
    }
    Ok(())
}

// ---------------------------------------------------------------------------
// 4. The caustic scene against the renderer.

/// The caustic comparison: 32×32, 8-pixel tiles.
pub const SIZE: u32 = 32;
pub const TILE: u32 = 8;
/// Photon paths per map, the fixed radius, roulette, camera samples per
/// pixel per map.
pub const CAUSTIC_PATHS: u64 = 20_000;
pub const CAUSTIC_RADIUS: f32 = 0.1;
pub const CAUSTIC_RR: u32 = 5;
pub const CAUSTIC_SPP: u32 = 4;
/// Independent photon maps of the student's render, and of the reference.
pub const STUDENT_MAPS: u64 = 32;
pub const REFERENCE_MAPS: u64 = 1024;
/// Family-wise false-failure probability of the comparison.
pub const ALPHA: f64 = 1e-4;

fn settings(
    photons: u64,
    k: usize,
    radius: Option<f32>,
    rr_depth: u32,
    seed: u64,
) -> PhotonSettings {
    PhotonSettings {
        photons,
        k,
        radius,
        final_gather: 0,
        max_depth: None,
        rr_depth,
        seed,
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

fn caustic_scene() -> Result<Scene, String> {
    let mut scene = builtin("caustic")?;
    scene.set_resolution(SIZE, SIZE);
    Ok(scene)
}

/// Where the reference is stored: the mean image, and an image of the
/// variance of each tile's mean (every pixel of a tile holds that tile's
/// variance times the tile's pixel count, so that
/// `raytracer::metrics::tile_variances` gives it back).
pub fn reference_paths() -> (PathBuf, PathBuf) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("references");
    (
        dir.join("ex17_caustic.exr"),
        dir.join("ex17_caustic-variance.exr"),
    )
}

/// `maps` renders of `integrator(seed)` for seeds `first..first + maps`:
/// the mean image and each tile's mean per render.
fn many_maps(
    scene: &Scene,
    maps: u64,
    first: u64,
    integrator: impl Fn(u64) -> Box<dyn Integrator>,
    progress: bool,
) -> (Image, Vec<Vec<Color>>) {
    let mut sum = Image::new(SIZE, SIZE);
    let mut tiles = Vec::new();
    for m in 0..maps {
        let r = render(
            scene,
            integrator(first + m).as_ref(),
            &options(CAUSTIC_SPP, first + m),
        );
        let img = r.film.image();
        for (s, p) in sum.pixels.iter_mut().zip(&img.pixels) {
            *s += *p;
        }
        tiles.push(tile_means(&img, TILE));
        if progress {
            eprint!("\r  map {}/{maps}", m + 1);
        }
    }
    if progress {
        eprintln!();
    }
    for s in &mut sum.pixels {
        *s /= maps as f32;
    }
    (sum, tiles)
}

/// Per tile: the mean over the maps, and the variance of that mean.
fn tile_stats(tiles: &[Vec<Color>]) -> Vec<(Vec3A, Vec3A)> {
    let n = tiles.len() as f32;
    (0..tiles[0].len())
        .map(|t| {
            let mean = tiles.iter().map(|m| m[t]).sum::<Vec3A>() / n;
            let var = tiles
                .iter()
                .map(|m| (m[t] - mean) * (m[t] - mean))
                .sum::<Vec3A>()
                / (n - 1.0);
            (mean, var / n)
        })
        .collect()
}

/// Renders the reference of the caustic comparison (the renderer's photon
/// mapping, [`REFERENCE_MAPS`] independent maps) and stores it (the
/// instructor's `lesson11 references`).
pub fn render_reference(progress: bool) -> Result<PathBuf, String> {
    let scene = caustic_scene()?;
    let (mean, tiles) = many_maps(
        &scene,
        REFERENCE_MAPS,
        1_000_000,
        |seed| {
            Box::new(
                PhotonMapping::build(
                    &scene,
                    settings(CAUSTIC_PATHS, 50, Some(CAUSTIC_RADIUS), CAUSTIC_RR, seed),
                    &std::sync::atomic::AtomicBool::new(false),
                )
                .expect("valid settings"),
            )
        },
        progress,
    );
    if raytracer::render::interrupted() {
        // Some maps were cut short: the stored files stay as they were.
        return Err(crate::tr!("compare.interrupted", name = "ex17_caustic"));
    }
    let stats = tile_stats(&tiles);
    let grid_x = SIZE.div_ceil(TILE);
    let per_tile = (TILE * TILE) as f32;
    let variance = Image::from_fn(SIZE, SIZE, |x, y| {
        stats[(y / TILE * grid_x + x / TILE) as usize].1 * per_tile
    });
    let (mp, vp) = reference_paths();
    std::fs::create_dir_all(mp.parent().unwrap()).map_err(|e| e.to_string())?;
    mean.write_exr(&mp).map_err(|e| e.to_string())?;
    variance.write_exr(&vp).map_err(|e| e.to_string())?;
    Ok(mp)
}

/// The upper `p` quantile of Student's t with `nu` degrees of freedom
/// (bisection on the tail, integrated numerically).
pub fn t_quantile(nu: u32, p: f64) -> f64 {
    let nu_f = nu as f64;
    // Γ((ν+1)/2) / Γ(ν/2) for integer ν, by the half-integer recurrence.
    // Γ((ν+1)/2) / Γ(ν/2): 1/√π at ν = 1, √π/2 at ν = 2, and ×(ν+1)/ν per step of 2.
    let mut ratio = if nu % 2 == 1 {
        1.0 / std::f64::consts::PI.sqrt()
    } else {
        std::f64::consts::PI.sqrt() / 2.0
    };
    let mut x = if nu % 2 == 1 { 1.0 } else { 2.0 };
    while x < nu_f {
        ratio *= (x + 1.0) / x;
        x += 2.0;
    }
    let c = ratio / (nu_f * std::f64::consts::PI).sqrt();
    let density = |t: f64| c * (1.0 + t * t / nu_f).powf(-(nu_f + 1.0) / 2.0);
    // P(T > x) = ∫_0^1 f(x/u) x/u² du (Simpson).
    let tail = |x: f64| {
        let n = 4000;
        let h = 1.0 / n as f64;
        let g = |u: f64| {
            if u <= 0.0 {
                0.0
            } else {
                density(x / u) * x / (u * u)
            }
        };
        let mut s = g(0.0) + g(1.0);
        for i in 1..n {
            s += g(i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 };
        }
        s * h / 3.0
    };
    let (mut lo, mut hi) = (0.5f64, 200.0f64);
    for _ in 0..80 {
        let mid = 0.5 * (lo + hi);
        if tail(mid) > p {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// Layer 4: the student's photon mapper over [`STUDENT_MAPS`] independent
/// maps (seed `seed`, `seed + 1`, …) against the stored reference, tile by
/// tile: z = (m_a − m_b)/√(v_a + v_b) with the variances of the tile means
/// over the maps; threshold the t quantile (ν = maps − 1) at α/(2·tests).
pub fn compare_caustic(trace: TraceFn, radiance: RadianceFn, seed: u64) -> Result<(), String> {
    compare_caustic_z(trace, radiance, seed, None)
}

/// [`compare_caustic`], also giving the largest |z| over the threshold
/// (the self-test measures the margin over many seeds).
pub fn compare_caustic_z(
    trace: TraceFn,
    radiance: RadianceFn,
    seed: u64,
    largest_z: Option<&mut f64>,
) -> Result<(), String> {
    let scene = caustic_scene()?;
    let (mp, vp) = reference_paths();
    let read = |p: &Path| {
        Image::read_exr(p).map_err(|e| crate::tr!("compare.missing", path = p.display(), e))
    };
    let (bi, bv) = (read(&mp)?, read(&vp)?);
    let (ai, tiles) = many_maps(
        &scene,
        STUDENT_MAPS,
        seed,
        |s| {
            Box::new(StudentPhotonMapping::with(
                trace,
                radiance,
                settings(CAUSTIC_PATHS, 50, Some(CAUSTIC_RADIUS), CAUSTIC_RR, s),
            ))
        },
        false,
    );
    if let Some(bad) = ai
        .pixels
        .iter()
        .find(|p| !p.is_finite() || p.min_element() < 0.0)
    {
        return Err(crate::tr!("ex17.caustic_nonfinite", pixel = fmt3(*bad)));
    }
    let a = tile_stats(&tiles);
    let (mb, vb) = (
        tile_means(&bi, TILE),
        raytracer::metrics::tile_variances(&bv, TILE),
    );
    let tests = a.len() * 3;
    let threshold = t_quantile(STUDENT_MAPS as u32 - 1, ALPHA / (2.0 * tests as f64));
    let grid_x = SIZE.div_ceil(TILE);
    let mut worst = (0.0f64, 0usize);
    let mut z = Vec::with_capacity(a.len());
    for (t, &(ma, va)) in a.iter().enumerate() {
        let zt: [f32; 3] = std::array::from_fn(|c| {
            let d = ma[c] as f64 - mb[t][c] as f64;
            let v = va[c] as f64 + vb[t][c] as f64;
            if d == 0.0 { 0.0 } else { (d / v.sqrt()) as f32 }
        });
        let zt = Color::from_array(zt);
        if zt.abs().max_element() as f64 > worst.0 {
            worst = (zt.abs().max_element() as f64, t);
        }
        z.push(zt);
    }
    if let Some(out) = largest_z {
        *out = worst.0 / threshold;
    }
    if worst.0 <= threshold {
        return Ok(());
    }
    let (t, tx, ty) = (worst.1, worst.1 as u32 % grid_x, worst.1 as u32 / grid_x);
    let dir = output_dir();
    let written = (|| -> std::io::Result<()> {
        std::fs::create_dir_all(&dir)?;
        write_enlarged(&ai, &dir.join("ex17_caustic_student.png"))?;
        write_enlarged(&bi, &dir.join("ex17_caustic_reference.png"))?;
        let zmap = Image::from_fn(SIZE, SIZE, |x, y| {
            z[(y / TILE * grid_x + x / TILE) as usize].abs() / threshold as f32
        });
        write_enlarged(&zmap, &dir.join("ex17_caustic_z.png"))
    })();
    let ratio = a[t].0.element_sum() / mb[t].element_sum();
    let whole =
        raytracer::metrics::mean(&ai).element_sum() / raytracer::metrics::mean(&bi).element_sum();
    let mut msg = crate::tr!(
        "ex17.caustic_differs",
        maps = STUDENT_MAPS,
        paths = CAUSTIC_PATHS,
        radius = CAUSTIC_RADIUS,
        tx,
        ty,
        z = worst.0,
        threshold,
        ratio,
        whole
    );
    match written {
        Ok(()) => msg.push_str(&crate::tr!(
            "compare.see",
            dir = dir.display(),
            name = "ex17_caustic"
        )),
        Err(e) => msg.push_str(&crate::tr!("compare.no_images", e)),
    }
    Err(msg)
}

pub fn check(trace: TraceFn, radiance: RadianceFn) -> Result<(), String> {
    check_estimate(radiance)?;
    check_tracing(trace)?;
    check_two_lights(trace)?;
    check_furnace(trace, radiance)?;
    compare_caustic(trace, radiance, 11)
}
