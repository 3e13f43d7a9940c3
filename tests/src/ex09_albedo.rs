//! Grader of exercise 9 (Monte Carlo directional albedo): a z-test of the
//! mean of many of the student's estimates against the exact albedo, with
//! the student's own variance. The exact albedo of Phong at grazing
//! incidence, where the lobe is cut by the horizon and the renderer's BRDF
//! sampling refuses some draws, comes from a deterministic quadrature.
//!
//! Tolerance: |z| ≤ 5.5 per channel ([`crate::stats::Z_MAX`]), 3 cases × 3
//! channels: a correct estimator fails with probability < 4e-7.

use raytracer::brdf::{Brdf, Lambert, Phong, Texture};
use raytracer::frame::Frame;
use raytracer::math::{Color, Vec3A};
use raytracer::sampling::Sampler;

use crate::stats::{MeanVar, ratio_near};

/// The signature of exercise 9.
pub type AlbedoFn = fn(&Brdf, Vec3A, &mut Sampler, u32) -> Color;

/// Independent estimates per case, and samples per estimate.
pub const ESTIMATES: u64 = 4000;
pub const SAMPLES: u32 = 8;

/// The Phong lobe of the test, seen at normal and at grazing incidence.
pub const PHONG_RHO: f32 = 0.9;
pub const PHONG_N: f32 = 10.0;
/// 75° from the normal.
pub const GRAZING_COS: f32 = 0.258_819;

/// A case: what it is, the BRDF, `wo`, its exact albedo.
pub struct Case {
    pub what: String,
    pub brdf: Brdf,
    pub wo: Vec3A,
    pub exact: Color,
    /// The probability that the renderer's `Brdf::sample` returns a
    /// direction (not `None`) for this `wo`.
    pub accepted: f64,
}

/// The directional albedo `∫ f_r cos θ_i dω_i` and the acceptance
/// probability `∫_{z>0} pdf dω` of the normalized Phong lobe (ρ_s = 1) for
/// `wo`, by the midpoint rule in the lobe's own coordinates
/// (`t = cos α ∈ (0, 1]`, `φ`; `dω = dt dφ`) on a 2000 × 2000 grid, in f64:
/// the integrands are smooth except across the horizon, and the rule is
/// accurate to about 1e-6 here, far below the test's noise (3e-3).
pub fn phong_albedo_and_acceptance(n: f64, wo: Vec3A) -> (f64, f64) {
    let mirror = Vec3A::new(-wo.x, -wo.y, wo.z);
    let frame = Frame::from_normal(mirror);
    let (s, m) = (frame.s, frame.t);
    let (nt, np) = (2000, 2000);
    let (mut albedo, mut accepted) = (0.0, 0.0);
    for i in 0..nt {
        let t = (i as f64 + 0.5) / nt as f64;
        let sin = (1.0 - t * t).sqrt();
        let lobe = t.powf(n) / std::f64::consts::TAU;
        for j in 0..np {
            let phi = std::f64::consts::TAU * (j as f64 + 0.5) / np as f64;
            // z of the direction (sin cos φ, sin sin φ, t) in the lobe's frame.
            let z =
                sin * phi.cos() * s.z as f64 + sin * phi.sin() * m.z as f64 + t * mirror.z as f64;
            if z > 0.0 {
                albedo += (n + 2.0) * lobe * z;
                accepted += (n + 1.0) * lobe;
            }
        }
    }
    let cell = std::f64::consts::TAU / (nt * np) as f64;
    (albedo * cell, accepted * cell)
}

/// The cases: Lambert at 37°, Phong at normal incidence (albedo exactly ρ_s)
/// and at 75° (well below ρ_s, and some BRDF samples refused).
pub fn cases() -> Vec<Case> {
    let rho = Color::new(0.8, 0.5, 0.2);
    let phong = Brdf::Phong(Phong {
        albedo: Color::splat(PHONG_RHO),
        exponent: PHONG_N,
    });
    let grazing = Vec3A::new((1.0 - GRAZING_COS * GRAZING_COS).sqrt(), 0.0, GRAZING_COS);
    let (a, p) = phong_albedo_and_acceptance(PHONG_N as f64, grazing);
    vec![
        Case {
            what: crate::tr!("ex09.lambert"),
            brdf: Brdf::Lambert(Lambert {
                albedo: Texture::Constant(rho),
            }),
            wo: Vec3A::new(0.6, 0.0, 0.8),
            exact: rho,
            accepted: 1.0,
        },
        Case {
            // At normal incidence the normalized Phong's albedo is exactly ρ_s.
            what: crate::tr!("ex09.phong_normal", PHONG_RHO, PHONG_N),
            brdf: phong.clone(),
            wo: Vec3A::Z,
            exact: Color::splat(PHONG_RHO),
            // The lobe about the normal lies wholly above the horizon.
            accepted: 1.0,
        },
        Case {
            what: crate::tr!(
                "ex09.phong_75",
                exact = PHONG_RHO as f64 * a,
                refused = 100.0 * (1.0 - p),
                PHONG_RHO,
                PHONG_N
            ),
            brdf: phong,
            wo: grazing,
            exact: Color::splat((PHONG_RHO as f64 * a) as f32),
            accepted: p,
        },
    ]
}

/// What the usual mistakes converge to in `case`, with their names.
fn mistakes(case: &Case) -> Vec<(Color, String)> {
    let n = SAMPLES as f32;
    // ∫ f_r dω_i over the upper hemisphere: 2ρ for Lambert; for the
    // normalized Phong ρ_s (n+2)/(n+1) times the share of its lobe above the
    // horizon (the acceptance probability).
    let brdf_integral = match &case.brdf {
        Brdf::Phong(p) => {
            Color::splat(PHONG_RHO * (p.exponent + 2.0) / (p.exponent + 1.0) * case.accepted as f32)
        }
        _ => case.exact * 2.0,
    };
    let mut named = vec![
        (brdf_integral, crate::tr!("ex09.no_cos")),
        (brdf_integral * case.wo.z, crate::tr!("ex09.cos_o")),
        (case.exact * (n / (n - 1.0)), crate::tr!("ex09.n_minus_1")),
    ];
    if case.accepted < 1.0 {
        // Dividing by the number K of accepted draws: E[Σ v / K; K > 0]
        // = E[v | accepted] · P(K > 0) = (ρ/p) · (1 − (1 − p)^N).
        let p = case.accepted;
        let left_out = (1.0 - (1.0 - p).powi(SAMPLES as i32)) / p;
        named.push((case.exact * left_out as f32, crate::tr!("ex09.refused")));
    }
    named.push((case.exact / n, crate::tr!("ex09.twice_n")));
    named.push((case.exact * n, crate::tr!("ex09.times_n")));
    named
}

/// Whether the student's mean is what `value` predicts: within the z-test's
/// tolerance, or within 5% of it in every channel (estimators with a missing
/// cosine have heavy tails, 1/cos θ_i under cosine sampling, whose standard
/// error is unreliable). Two mistakes may then both agree in one case (N − 1
/// and a missing cosine lie 4.8% apart at normal incidence): the one named
/// is the one that agrees in every case.
fn agrees(stats: &MeanVar, value: Color) -> bool {
    stats.matches(value)
        || (0..3).all(|k| {
            let v = value[k] as f64;
            v > 0.0 && (stats.mean()[k] / v - 1.0).abs() < 0.05
        })
}

pub fn check(f: AlbedoFn) -> Result<(), String> {
    let cases = cases();
    // Every case first: a mistake is named by what explains all of them
    // (a missing cosine and the cosine of ω_o agree at normal incidence).
    let all: Vec<MeanVar> = cases
        .iter()
        .enumerate()
        .map(|(k, case)| {
            let mut stats = MeanVar::default();
            for i in 0..ESTIMATES {
                let mut sampler = Sampler::new(9 + k as u64, i, 0);
                stats.add(f(&case.brdf, case.wo, &mut sampler, SAMPLES));
            }
            stats
        })
        .collect();
    let named: Vec<_> = cases.iter().map(mistakes).collect();
    let explains = |m: usize| {
        cases
            .iter()
            .zip(&all)
            .zip(&named)
            .all(|((_, stats), list)| list.get(m).is_some_and(|(v, _)| agrees(stats, *v)))
    };
    for (k, (case, stats)) in cases.iter().zip(&all).enumerate() {
        let list = &named[k];
        let here: Vec<usize> = (0..list.len())
            .filter(|&m| agrees(stats, list[m].0))
            .collect();
        let advice = here
            .iter()
            .find(|&&m| explains(m))
            .or(here.first())
            .map(|&m| list[m].1.to_string());
        stats.check(
            &crate::tr!("ex09.what", case = case.what),
            case.exact,
            |r| {
                advice.clone().or_else(|| {
                    Some(
                        if k == 0
                            && (ratio_near(r, 2.0 / (3.0 * std::f64::consts::PI))
                                || ratio_near(r, 1.0 / (2.0 * std::f64::consts::PI)))
                        {
                            crate::tr!("ex09.no_pdf")
                        } else if r > 1.0 {
                            {
                                let energy = if r * case.exact.max_element() as f64 > 1.0 {
                                    crate::tr!("ex09.creates_energy")
                                } else {
                                    String::new()
                                };
                                crate::tr!("ex09.brighter", r, energy)
                            }
                        } else {
                            crate::tr!("ex09.darker", r)
                        },
                    )
                })
            },
        )?;
    }
    Ok(())
}
