//! Grader of exercise 13 (the path tracer with light sampling and BRDF
//! sampling combined by the power heuristic).
//!
//! 1. A Lambertian floor under a constant sky, max depth 2 (direct light
//!    only). Its mean is exactly the albedo ρ; and since both strategies are
//!    fixed here (cosine-weighted BRDF sampling, the sky sampled uniformly
//!    over the sphere) the *distribution* of a single estimate is known for
//!    every weighting: the grader simulates it in closed form and compares
//!    it with the student's estimates by a two-sample Kolmogorov–Smirnov
//!    test. The power heuristic's distribution must fit; the balance
//!    heuristic and the exponent 3 (both unbiased) are recognised by theirs.
//! 2. The floor under a square light, and under two (each chosen with
//!    probability 1/2): exact by Lambert's polygon formula; a failing mean is
//!    compared with what the usual mistakes converge to, by quadrature over
//!    the lights: the emitter hit by the BRDF sample unweighted (counted
//!    twice), the light sample unweighted, the BRDF hit's weight computed
//!    with the light's density per unit area instead of solid angle, the
//!    light-choice probability missing from either weight.
//! 3. A light seen in a mirror (exact `R·L_e`): no MIS after a delta bounce.
//! 4. The furnaces of exercise 12 (exact values).
//! 5. Veach's plates (`veach-mis`, max depth 2) against the renderer's MIS
//!    path tracer tile by tile, and the variance of the student's render
//!    against the renderer's BRDF sampling alone and light sampling alone at
//!    the same samples per pixel: MIS must beat both by far (each strategy
//!    alone fails on some plates).
//! 6. The Cornell box at max depth 5 against the renderer, tile by tile.
//!
//! Tolerances: means |z| ≤ 5.5 per channel with the student's own variance
//! in 6 cases (false failure < 1e-6); the KS test at √(N/2)·D ≤ 2.8 with
//! N = 20,000 per sample (P ≈ 2e^(−2·2.8²) = 3e-7; the balance heuristic
//! scores about 35, the exponent 3 about 29); the mirror exact to 1e-4;
//! image comparisons at family-wise α = 1e-4 each ([`crate::compare`]); the
//! variance ratios: see [`MAX_VARIANCE_RATIO`].

use exercises::plug::StudentPathTracer;
use glam::DVec3;
use raytracer::integrator::{DirectStrategy, PathTracer};
use raytracer::light::{EnvironmentLight, Light};
use raytracer::math::{Color, INV_PI, Ray, Vec3A};
use raytracer::render::render;
use raytracer::sampling::Sampler;
use raytracer::scene::{LightSelection, Scene};

use crate::compare::{EX13_CORNELL, EX13_VEACH, compare, options};
use crate::ex12_nee::{
    FLOOR_ALBEDO, TestLight, X, check_furnaces, check_mirror, exact, scene_with,
};
use crate::stats::{MeanVar, fmt3};

/// The signature of exercise 13.
pub use exercises::plug::PathRadianceFn as PathFn;

/// Estimates per case (and per sample of the KS test).
pub const ESTIMATES: u64 = 20_000;

/// The KS statistic √(N/2)·D above which two samples of N differ
/// (false failure 2·exp(−2·2.8²) ≈ 3e-7).
pub const KS_MAX: f64 = 2.8;

/// The student's MIS render of Veach's plates must have at most this
/// fraction of the summed pixel variance of either strategy alone at the
/// same samples per pixel (48×48, 64 spp, seed 12). Measured: the reference
/// solution 0.45 of BRDF sampling's and 0.17 of light sampling's, a
/// correct variant 0.41 and 0.15, the balance heuristic 0.38 and 0.14;
/// weights 1/2 for both 1.52 and 0.56, swapped weights 5.2 and 1.9
/// (`cargo test -p grading --test check_grader ex13_variance_ratios -- --nocapture`).
pub const MAX_VARIANCE_RATIO: f64 = 0.7;

pub fn check(f: PathFn) -> Result<(), String> {
    check_sky(f)?;
    for case in light_cases() {
        case.check(f)?;
    }
    check_mirror("path_radiance_mis", f, |got, want| {
        if got == Color::ZERO {
            crate::tr!("ex13.mirror_missing")
        } else if got.element_sum() < want.element_sum() {
            crate::tr!("ex13.mirror_dark")
        } else {
            crate::tr!("ex13.mirror_bright")
        }
    })?;
    check_furnaces("path_radiance_mis", f, 130)?;
    check_veach(f)?;
    let student = StudentPathTracer {
        path_radiance: f,
        max_depth: Some(5),
        rr_depth: 3,
    };
    compare(&EX13_CORNELL, &student).map_err(|e| crate::tr!("ex13.cornell", e))
}

/// The power heuristic with exponent `k` for two one-sample strategies.
pub fn heuristic(k: i32, this: f64, other: f64) -> f64 {
    let (a, b) = (this.powi(k), other.powi(k));
    if a + b == 0.0 { 0.0 } else { a / (a + b) }
}

/// The floor of exercise 12's cases under a constant sky of radiance 1
/// (the only light), and the camera ray that hits it at [`X`].
pub fn sky_scene() -> (Scene, Ray) {
    let (mut scene, it) = scene_with(&[], None, 1.0, false);
    let mut env = EnvironmentLight::new(Color::ONE, None);
    env.set_scene_bounds(Vec3A::ZERO, 5.0);
    scene.environment = Some(scene.lights.len() as u32);
    scene.lights.push(Light::Environment(env));
    scene.set_light_selection(LightSelection::Uniform);
    (scene, Ray::new(X + 0.5 * it.wo, -it.wo))
}

/// One estimate of the sky case divided by the albedo, simulated in closed
/// form for the heuristic with exponent `k`: the light sample is a
/// direction uniform on the sphere (p_light = 1/(4π); below the horizon it
/// brings nothing), the BRDF sample cosine-weighted (p_BRDF = cos θ/π),
/// always escaping to the sky. With r = p_BRDF/p_light = 4 cos θ: the light
/// sample brings `4 cos θ · w_light`, the BRDF sample `w_BRDF`.
pub fn sky_estimate(k: i32, s: &mut Sampler) -> f64 {
    let z = 1.0 - 2.0 * s.next_1d() as f64;
    let mut x = 0.0;
    if z > 0.0 {
        x += 4.0 * z * heuristic(k, 0.25 * INV_PI as f64, z * INV_PI as f64);
    }
    let c = (s.next_1d() as f64).sqrt();
    x + heuristic(k, c * INV_PI as f64, 0.25 * INV_PI as f64)
}

/// The mean of [`sky_estimate`]'s two parts, (light sample, BRDF sample),
/// divided by the albedo, by quadrature over cos θ.
pub fn sky_parts(k: i32) -> (f64, f64) {
    let n = 20_000;
    let (mut a, mut b) = (0.0, 0.0);
    for i in 0..n {
        let c = (i as f64 + 0.5) / n as f64;
        let (pl, pb) = (0.25, c);
        // Uniform sphere: density 1/(4π), 2π dc per band: ½ dc.
        a += 0.5 * 4.0 * c * heuristic(k, pl, pb) / n as f64;
        // Cosine: density c/π, 2π dc per band: 2c dc.
        b += 2.0 * c * heuristic(k, pb, pl) / n as f64;
    }
    (a, b)
}

/// The two-sample Kolmogorov–Smirnov statistic √(N M/(N + M))·D.
pub fn ks(mut a: Vec<f64>, mut b: Vec<f64>) -> f64 {
    a.sort_by(f64::total_cmp);
    b.sort_by(f64::total_cmp);
    let (n, m) = (a.len(), b.len());
    let (mut i, mut j, mut d) = (0, 0, 0.0f64);
    while i < n && j < m {
        let x = a[i].min(b[j]);
        while i < n && a[i] <= x {
            i += 1;
        }
        while j < m && b[j] <= x {
            j += 1;
        }
        d = d.max((i as f64 / n as f64 - j as f64 / m as f64).abs());
    }
    d * ((n * m) as f64 / (n + m) as f64).sqrt()
}

fn check_sky(f: PathFn) -> Result<(), String> {
    let (scene, ray) = sky_scene();
    let mut stats = MeanVar::default();
    let mut values = Vec::with_capacity(ESTIMATES as usize);
    for i in 0..ESTIMATES {
        let c = f(&scene, ray, Some(2), 1000, &mut Sampler::new(131, i, 0));
        stats.add(c);
        values.push(c.x as f64 / FLOOR_ALBEDO.x as f64);
    }
    let (a, b) = sky_parts(2);
    let rho = FLOOR_ALBEDO;
    let named = [
        (rho * (1.0 + a) as f32, crate::tr!("ex13.brdf_unweighted")),
        (rho * (1.0 + b) as f32, crate::tr!("ex13.light_unweighted")),
        (rho * 2.0, crate::tr!("ex13.both_one")),
        (rho * a as f32, crate::tr!("ex13.light_only")),
        (rho * b as f32, crate::tr!("ex13.brdf_only")),
    ];
    let advice = named
        .iter()
        .find(|(v, _)| stats.matches(*v))
        .map(|(_, why)| why.to_string());
    let what = crate::tr!("ex13.sky_floor");
    stats.check(&what, rho, |r| {
        advice.clone().or_else(|| {
            Some(if r > 1.0 {
                crate::tr!("ex13.sum_bright")
            } else {
                crate::tr!("ex13.sum_dark")
            })
        })
    })?;
    let simulated = |k: i32| -> Vec<f64> {
        (0..ESTIMATES)
            .map(|i| sky_estimate(k, &mut Sampler::new(132 + k as u64, i, 0)))
            .collect()
    };
    let d = ks(values.clone(), simulated(2));
    if d <= KS_MAX {
        return Ok(());
    }
    let why = if ks(values.clone(), simulated(1)) <= KS_MAX {
        crate::tr!("ex13.balance")
    } else if ks(values.clone(), simulated(3)) <= KS_MAX {
        crate::tr!("ex13.power3")
    } else {
        let swapped: Vec<f64> = (0..ESTIMATES)
            .map(|i| {
                let mut s = Sampler::new(140, i, 0);
                // Each strategy weighted by the OTHER's density.
                let z = 1.0 - 2.0 * s.next_1d() as f64;
                let mut x = 0.0;
                if z > 0.0 {
                    x += 4.0 * z * heuristic(2, z, 0.25);
                }
                let c = (s.next_1d() as f64).sqrt();
                x + heuristic(2, 0.25, c)
            })
            .collect();
        if ks(values, swapped) <= KS_MAX {
            crate::tr!("ex13.swapped")
        } else {
            crate::tr!("ex13.spread")
        }
    };
    Err(crate::tr!("ex13.distribution", what, d, KS_MAX, why))
}

/// A case of direct light from square lights at [`X`] (max depth 2).
pub struct LightCase {
    pub what: String,
    pub scene: Scene,
    pub ray: Ray,
    pub exact: Color,
    pub named: Vec<(Color, String)>,
}

impl LightCase {
    pub fn check(&self, f: PathFn) -> Result<(), String> {
        let mut stats = MeanVar::default();
        for i in 0..ESTIMATES {
            stats.add(f(
                &self.scene,
                self.ray,
                Some(2),
                1000,
                &mut Sampler::new(133, i, 0),
            ));
        }
        let advice = self
            .named
            .iter()
            .find(|(v, _)| stats.matches(*v))
            .map(|(_, why)| why.clone());
        stats.check(&self.what, self.exact, |r| {
            advice.clone().or_else(|| {
                let want = fmt3(self.exact);
                Some(if r > 1.0 {
                    crate::tr!("ex13.sum_bright_want", want)
                } else {
                    crate::tr!("ex13.sum_dark_want", want)
                })
            })
        })
    }
}

/// `f_r L_e ∫ cos θ_x · g dω` over light `l` seen from [`X`], where `g`
/// receives the light strategy's density per solid angle `p_ω` (without
/// the pmf), the BRDF's `p_BRDF = cos θ_x/π` and the light's area density
/// `1/A`.
fn over_light(l: &TestLight, g: &dyn Fn(f64, f64, f64) -> f64) -> Color {
    let area = l.e1.cross(l.e2).length() as f64;
    let v = l.integrate(X, |w: DVec3, r2, cy| {
        let cos_x = w.y.max(0.0);
        let p_w = r2 / (area * cy);
        cos_x * g(p_w, cos_x / std::f64::consts::PI, 1.0 / area) * cy / r2
    });
    FLOOR_ALBEDO * INV_PI * l.radiance * v as f32
}

/// The cases with square lights.
pub fn light_cases() -> Vec<LightCase> {
    // Large lights close to x: the densities of the two strategies are of
    // the same order here (p_ω ≈ 0.3–1 sr⁻¹, p_BRDF ≤ 1/π), so a wrong
    // weight changes the mean by far more than the noise.
    let a = TestLight::tilted(
        Vec3A::new(-1.0, 1.2, 0.0),
        0.0,
        2.0,
        Color::new(1.0, 1.5, 2.0),
    );
    let b = TestLight::tilted(
        Vec3A::new(1.2, 1.0, 0.3),
        0.3,
        1.8,
        Color::new(2.0, 1.0, 0.5),
    );
    let h = |x, y| heuristic(2, x, y);
    let ray = |s: &Scene, it_wo: Vec3A| {
        let _ = s;
        Ray::new(X + 0.5 * it_wo, -it_wo)
    };
    let mut out = Vec::new();

    // One light (pmf 1).
    let (scene1, it1) = scene_with(&[a], None, 1.0, false);
    let exact_a = exact(&[a]);
    let light_w = over_light(&a, &|pw, pb, _| h(pw, pb));
    let brdf_w = over_light(&a, &|pw, pb, _| h(pb, pw));
    let brdf_area = over_light(&a, &|_, pb, pa| h(pb, pa));
    let r1 = ray(&scene1, it1.wo);
    out.push(LightCase {
        what: crate::tr!("ex13.near_light"),
        scene: scene1,
        ray: r1,
        exact: exact_a,
        named: vec![
            (light_w + brdf_area, crate::tr!("ex13.area_weight")),
            (light_w + exact_a, crate::tr!("ex13.brdf_unweighted2")),
            (exact_a + brdf_w, crate::tr!("ex13.light_unweighted2")),
            (exact_a * 2.0, crate::tr!("ex13.both_one2")),
        ],
    });

    // Two lights, each chosen with probability 1/2.
    let (mut scene2, it2) = scene_with(&[a, b], None, 1.0, false);
    scene2.set_light_selection(LightSelection::Uniform);
    let both = exact(&[a, b]);
    let sum = |g: &dyn Fn(f64, f64, f64) -> f64| over_light(&a, g) + over_light(&b, g);
    let correct_light = sum(&|pw, pb, _| h(0.5 * pw, pb));
    let correct_brdf = sum(&|pw, pb, _| h(pb, 0.5 * pw));
    let no_pmf_brdf = sum(&|pw, pb, _| h(pb, pw));
    let no_pmf_light = sum(&|pw, pb, _| h(pw, pb));
    let r2 = ray(&scene2, it2.wo);
    out.push(LightCase {
        what: crate::tr!("ex13.two_lights"),
        scene: scene2,
        ray: r2,
        exact: both,
        named: vec![
            (correct_light + no_pmf_brdf, crate::tr!("ex13.pmf_brdf")),
            (no_pmf_light + correct_brdf, crate::tr!("ex13.pmf_light")),
        ],
    });
    out
}

/// Summed pixel variances of Veach's plates rendered by `integrator`.
fn summed_variance(integrator: &dyn raytracer::integrator::Integrator) -> Result<f64, String> {
    let scene = crate::compare::scene(&EX13_VEACH)?;
    let r = render(&scene, integrator, &options(EX13_VEACH.spp, 12, false, ""));
    let v = r.film.variance_image();
    Ok(v.pixels.iter().map(|c| c.element_sum() as f64).sum())
}

/// The variance of the student's MIS render of Veach's plates divided by
/// that of BRDF sampling alone and of light sampling alone (the renderer's).
pub fn variance_ratios(f: PathFn) -> Result<(f64, f64), String> {
    let student = StudentPathTracer {
        path_radiance: f,
        max_depth: Some(2),
        rr_depth: 1000,
    };
    let mine = summed_variance(&student)?;
    let alone = |strategy| PathTracer {
        max_depth: Some(2),
        rr_depth: 1000,
        strategy,
    };
    let brdf = summed_variance(&alone(DirectStrategy::BrdfOnly))?;
    let light = summed_variance(&alone(DirectStrategy::LightOnly))?;
    Ok((mine / brdf, mine / light))
}

fn check_veach(f: PathFn) -> Result<(), String> {
    let student = StudentPathTracer {
        path_radiance: f,
        max_depth: Some(2),
        rr_depth: 1000,
    };
    compare(&EX13_VEACH, &student).map_err(|e| crate::tr!("ex13.veach", e))?;
    let (brdf, light) = variance_ratios(f)?;
    for (ratio, alone, wins) in [
        (
            brdf,
            crate::tr!("ex13.brdf_alone"),
            crate::tr!("ex13.brdf_wins"),
        ),
        (
            light,
            crate::tr!("ex13.light_alone"),
            crate::tr!("ex13.light_wins"),
        ),
    ] {
        if ratio > MAX_VARIANCE_RATIO {
            return Err(crate::tr!(
                "ex13.variance",
                ratio,
                alone,
                MAX_VARIANCE_RATIO,
                wins
            ));
        }
    }
    Ok(())
}
