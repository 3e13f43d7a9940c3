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
            "the light seen in a mirror is missing: after a delta (mirror) bounce the BRDF sample is the only strategy that finds the emitter (no light sample can: f_r is zero for every other direction), so it takes the whole weight".into()
        } else if got.element_sum() < want.element_sum() {
            "the light seen in a mirror is too dark: you applied MIS after a delta (mirror) bounce — a delta lobe's pdf is a probability, not a density per solid angle, and no light sample competes there: that hit takes the whole weight".into()
        } else {
            "the light seen in a mirror is too bright: it counts once, β·L_e, with β = R after the mirror".into()
        }
    })?;
    check_furnaces("path_radiance_mis", f, 130)?;
    check_veach(f)?;
    let student = StudentPathTracer {
        path_radiance: f,
        max_depth: Some(5),
        rr_depth: 3,
    };
    compare(&EX13_CORNELL, &student).map_err(|e| format!("path_radiance_mis at max depth 5: {e}"))
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
        (
            rho * (1.0 + a) as f32,
            "too bright: the emitter found by the BRDF sample counts unweighted while the light sample of the same direction is weighted — the two weights of one direction do not sum to one, and the sky's light is counted more than once",
        ),
        (
            rho * (1.0 + b) as f32,
            "too bright: the light sample counts unweighted while the emitter found by the BRDF sample is weighted — the two weights of one direction do not sum to one",
        ),
        (
            rho * 2.0,
            "twice the light: both strategies count with weight 1 — the direct light is counted twice",
        ),
        (
            rho * a as f32,
            "too dark: only the light samples count (and with their weights): the emitter found by the BRDF sample is missing",
        ),
        (
            rho * b as f32,
            "too dark: only the emitter found by the BRDF sample counts: the light samples are missing",
        ),
    ];
    let advice = named
        .iter()
        .find(|(v, _)| stats.matches(*v))
        .map(|(_, why)| why.to_string());
    let what = "a Lambertian floor (albedo ρ) under a constant sky of radiance 1, max_depth 2 (direct light only): L = ρ";
    stats.check(what, rho, |r| {
        advice.clone().or_else(|| {
            Some(
                if r > 1.0 {
                    "too bright: for every direction the two weights must sum to one"
                } else {
                    "too dark: for every direction the two weights must sum to one"
                }
                .to_string(),
            )
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
        crate::ex13_mis::BALANCE.to_string()
    } else if ks(values.clone(), simulated(3)) <= KS_MAX {
        "that is the power heuristic with exponent 3 (each density cubed): a valid MIS weight, but this exercise asks for exponent 2, as the slide and the renderer use".to_string()
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
            "the weights are swapped: each strategy is weighted by the other's density, so the worse strategy gets the larger weight (unbiased, but the noise of both)".to_string()
        } else {
            "the spread of your estimates is not that of the power heuristic with these two strategies (the light sample from Light::sample_li, the continuation from Brdf::sample), although the mean is right: each sample's weight must grow with its own strategy's density and fall with the other's, as the power heuristic of the slide, both densities of the same direction and per unit solid angle".to_string()
        }
    };
    Err(format!(
        "{what}: your mean is right, but the distribution of your single estimates differs from the power heuristic's (Kolmogorov–Smirnov √(N/2)·D = {d:.1} > {KS_MAX}) — {why}"
    ))
}

/// The message of the balance heuristic.
pub const BALANCE: &str = "that is the balance heuristic (exponent 1): a valid MIS weight, but this exercise asks for the power heuristic with exponent 2, as the slide and the renderer use — each density squared";

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
                Some(format!(
                    "{}: for every direction the two weights must sum to one (expected {})",
                    if r > 1.0 { "too bright" } else { "too dark" },
                    fmt3(self.exact)
                ))
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
        what: "a Lambertian floor under one large square light close by, max_depth 2 (exact: Lambert's polygon formula)".into(),
        scene: scene1,
        ray: r1,
        exact: exact_a,
        named: vec![
            (
                light_w + brdf_area,
                "too bright: the weight of the emitter found by the BRDF sample is computed with the light's density per unit AREA (1/A), not per unit solid angle at the vertex — the two weights of one direction compare densities of the same measure, or they do not sum to one".into(),
            ),
            (
                light_w + exact_a,
                "too bright: the emitter found by the BRDF sample counts unweighted while the light sample is weighted — the weights of one direction do not sum to one: light counted twice in part".into(),
            ),
            (
                exact_a + brdf_w,
                "too bright: the light sample counts unweighted while the emitter found by the BRDF sample is weighted — the weights of one direction do not sum to one".into(),
            ),
            (
                exact_a * 2.0,
                "twice the light: both strategies count with weight 1".into(),
            ),
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
        what: "the floor under two large square lights close by, each chosen with probability 1/2, max_depth 2".into(),
        scene: scene2,
        ray: r2,
        exact: both,
        named: vec![
            (
                correct_light + no_pmf_brdf,
                "too dark: the light-choice probability P(light) is missing from the light strategy's density in the weight of the emitter found by the BRDF sample — the light strategy makes that direction with P(light)·p_ω, so with two lights your BRDF hits get too little weight".into(),
            ),
            (
                no_pmf_light + correct_brdf,
                "too bright: the light-choice probability P(light) is missing from the light strategy's density in the light sample's weight — the light strategy makes that direction with P(light)·p_ω".into(),
            ),
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
    compare(&EX13_VEACH, &student).map_err(|e| format!("Veach's plates (max depth 2): {e}"))?;
    let (brdf, light) = variance_ratios(f)?;
    for (ratio, alone, wins) in [
        (
            brdf,
            "BRDF sampling alone",
            "small lights over rough plates",
        ),
        (
            light,
            "light sampling alone",
            "large lights over shiny plates",
        ),
    ] {
        if ratio > MAX_VARIANCE_RATIO {
            return Err(format!(
                "Veach's plates: your render is right on average, but its variance is {ratio:.2} × that of {alone} (at most {MAX_VARIANCE_RATIO} expected: MIS beats each strategy where the other wins, e.g. {wins}) — your weights do not favour the strategy with the larger density"
            ));
        }
    }
    Ok(())
}
