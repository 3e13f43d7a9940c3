//! Grader of exercise 15 (bidirectional connection): the geometry term
//! exactly (the usual mistakes named by comparing all cases at once) and by
//! the irradiance of a disk light (a z-test with the student's own
//! variance), and the multi-strategy power heuristic exactly, by its edge
//! cases and by the unbiasedness of a three-strategy estimator.
//!
//! Tolerances: exact values to 1e-4 relative (G) and 1e-5 absolute
//! (weights); the two estimates |z| ≤ 5.5 (false failure < 8e-8).

use raytracer::math::{Color, PI, Vec3A};
use raytracer::sampling::Sampler;
use raytracer::sampling::warp::concentric_disk;

use crate::cone::{Strategy, exact, g};
use crate::ex13_mis::BALANCE;
use crate::stats::{MeanVar, Mistake, close, fmt3, recognise};

/// The signatures of exercise 15.
pub type GeometryFn = fn(Vec3A, Vec3A, Vec3A, Vec3A) -> f32;
pub type WeightFn = fn(&[f32], usize) -> f32;

/// The grader's geometry term.
pub fn expected_g(x: Vec3A, nx: Vec3A, y: Vec3A, ny: Vec3A) -> f32 {
    let d = y - x;
    let w = d.normalize();
    nx.dot(w).abs() * ny.dot(w).abs() / d.length_squared()
}

/// The grader's power heuristic over many strategies, in f64.
pub fn expected_w(pdfs: &[f32], s: usize) -> f32 {
    let sum: f64 = pdfs.iter().map(|&p| p as f64 * p as f64).sum();
    if sum == 0.0 {
        0.0
    } else {
        (pdfs[s] as f64 * pdfs[s] as f64 / sum) as f32
    }
}

pub const ESTIMATES: u64 = 20_000;

/// A case of the geometry term: `(x, nx, y, ny)`.
type Edge = (Vec3A, Vec3A, Vec3A, Vec3A);

pub fn check(geometry: GeometryFn, weight: WeightFn) -> Result<(), String> {
    check_geometry(geometry)?;
    check_weights(weight)
}

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
            (
                "G is never negative: the normals may face either way, so take the absolute values of the cosines",
                &|e| cx(e) * cy(e) / r2(e),
            ),
            (
                "divide by the SQUARED distance (the solid angle of a patch falls as 1/r²)",
                &|e| (cx(e) * cy(e)).abs() / r2(e).sqrt(),
            ),
            (
                "the cosine at y is missing: G has one cosine at each end of the edge (dω_x = |cos θ_y| dA_y / r²)",
                &|e| cx(e).abs() / r2(e),
            ),
            (
                "the cosine at x is missing: G has one cosine at each end of the edge (|cos θ_x| dω_x)",
                &|e| cy(e).abs() / r2(e),
            ),
            (
                "your G is |cos θ_x cos θ_y| without the 1/‖x − y‖²: divide by the squared distance — or, if you used y − x unnormalized in the dot products, its length r² cancelled it: normalize the edge direction first",
                &|e| (cx(e) * cy(e)).abs(),
            ),
        ];
        let (x, nx, y, ny) = cases[k];
        let why =
            recognise(&cases, &got, &mistakes, |g, a| close(g, a, 1e-4)).unwrap_or_else(|| {
                "G = |cos θ_x| |cos θ_y| / ‖x − y‖², both cosines with the unit edge direction"
                    .to_string()
            });
        return Err(format!(
            "geometry_term(x = {}, nx = {}, y = {}, ny = {}) is {}, expected {} — {why}",
            fmt3(x),
            fmt3(nx),
            fmt3(y),
            fmt3(ny),
            got[k],
            want(&cases[k])
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
        "irradiance under a disk light (R = 0.8, h = 1) as ∫ G dA = πR²/(h² + R²)",
        Color::splat(PI * r * r / (h * h + r * r)),
        |_| None,
    )
}

fn check_weights(weight: WeightFn) -> Result<(), String> {
    let sets: Vec<Vec<f32>> = vec![
        vec![1.0, 2.0, 3.0],
        vec![0.1, 10.0],
        vec![5.0],
        vec![0.0, 1.0, 0.0, 2.0],
        vec![1e-3, 1e3, 1.0, 1.0],
    ];
    let mut cases = Vec::new();
    for set in &sets {
        for s in 0..set.len() {
            cases.push((set.clone(), s));
        }
    }
    let got: Vec<f32> = cases.iter().map(|(p, s)| weight(p, *s)).collect();
    let same = |g: f32, e: f32| (g - e).abs() <= 1e-5;
    if let Some(k) = (0..cases.len()).find(|&k| !same(got[k], expected_w(&cases[k].0, cases[k].1)))
    {
        let mistakes: [Mistake<(Vec<f32>, usize), f32>; 3] = [
            (BALANCE, &|(p, s)| p[*s] / p.iter().sum::<f32>()),
            (
                "weights must sum to one over the strategies: divide by the sum of the squares, not by the largest",
                &|(p, s)| {
                    let m = p.iter().fold(0.0f32, |m, &q| m.max(q));
                    p[*s] * p[*s] / (m * m)
                },
            ),
            (
                "the square of the sum is not the sum of the squares: Σ p_i², each density squared",
                &|(p, s)| {
                    let sum: f32 = p.iter().sum();
                    p[*s] * p[*s] / (sum * sum)
                },
            ),
        ];
        let (pdfs, s) = &cases[k];
        let why = recognise(&cases, &got, &mistakes, same).unwrap_or_else(|| {
            "w_s: the density of strategy s squared, over the sum of all the strategies' squared densities".to_string()
        });
        return Err(format!(
            "bdpt_mis_weight({pdfs:?}, {s}) is {}, expected {} — {why}",
            got[k],
            expected_w(pdfs, *s)
        ));
    }
    let all_zero = weight(&[0.0, 0.0, 0.0], 1);
    if all_zero != 0.0 {
        return Err(format!(
            "bdpt_mis_weight([0, 0, 0], 1) is {all_zero}: when no strategy can make the path, return 0 (as the task says) — not NaN from 0/0"
        ));
    }
    // Unbiasedness: one sample from each of three strategies, combined.
    let strategies = [Strategy::Cosine, Strategy::Uniform, Strategy::Cone];
    let mut stats = MeanVar::default();
    for i in 0..ESTIMATES {
        let mut s = Sampler::new(151, i, 0);
        let mut est = 0.0;
        for (k, st) in strategies.iter().enumerate() {
            let w = st.sample(s.next_2d());
            let pdfs = strategies.map(|o| o.pdf(w));
            if pdfs[k] > 0.0 {
                est += weight(&pdfs, k) * g(w) / pdfs[k];
            }
        }
        stats.add(Color::splat(est));
    }
    stats.check(
        "MIS of three strategies (cosine, uniform, cone) for ∫ cos θ/π over a 40° cone",
        Color::splat(exact()),
        |_| Some("the combined estimator is biased".to_string()),
    )
}
