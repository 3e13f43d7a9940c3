//! Grader of exercise 13 (bidirectional connection): the geometry term
//! exactly and by the irradiance of a disk light (a z-test with the student's
//! own variance), and the multi-strategy MIS weight by its properties and by
//! the unbiasedness of a three-strategy estimator.

use raytracer::math::{Color, PI, Vec3A};
use raytracer::sampling::Sampler;
use raytracer::sampling::warp::concentric_disk;

use crate::cone::{Strategy, exact, g};
use crate::stats::{MeanVar, close, fmt3};

/// The signatures of exercise 13.
pub type GeometryFn = fn(Vec3A, Vec3A, Vec3A, Vec3A) -> f32;
pub type WeightFn = fn(&[f32], usize) -> f32;

/// The grader's geometry term.
pub fn expected_g(x: Vec3A, nx: Vec3A, y: Vec3A, ny: Vec3A) -> f32 {
    let d = y - x;
    let w = d.normalize();
    nx.dot(w).abs() * ny.dot(w).abs() / d.length_squared()
}

pub const ESTIMATES: u64 = 20_000;

pub fn check(geometry: GeometryFn, weight: WeightFn) -> Result<(), String> {
    let cases = [
        (Vec3A::ZERO, Vec3A::Y, Vec3A::new(0.0, 2.0, 0.0), -Vec3A::Y),
        (Vec3A::ZERO, Vec3A::Y, Vec3A::new(1.0, 1.0, 0.5), -Vec3A::Y),
        (
            Vec3A::new(0.2, 0.1, -0.3),
            Vec3A::new(0.0, 0.6, 0.8),
            Vec3A::new(-1.0, 0.5, 2.0),
            Vec3A::X,
        ),
        // Normals facing away from the edge: the cosines' absolute values.
        (Vec3A::ZERO, -Vec3A::Y, Vec3A::new(0.5, 1.5, 0.0), Vec3A::Y),
        (Vec3A::ZERO, Vec3A::Y, Vec3A::new(0.5, 1.5, 0.0), Vec3A::Y),
    ];
    for (x, nx, y, ny) in cases {
        let (got, want) = (geometry(x, nx, y, ny), expected_g(x, nx, y, ny));
        if close(got, want, 1e-4) {
            continue;
        }
        let d = y - x;
        let why = if close(got, -want, 1e-4) {
            "G is never negative: take the absolute values of the cosines"
        } else if close(got, want * d.length(), 1e-4) {
            "divide by the SQUARED distance"
        } else if close(got, want * d.length_squared(), 1e-4) {
            "divide by the squared distance"
        } else {
            "G = |cos θ_x| |cos θ_y| / ‖x − y‖², both cosines with the unit edge direction"
        };
        return Err(format!(
            "geometry_term(x = {}, nx = {}, y = {}, ny = {}) is {got}, expected {want} — {why}",
            fmt3(x),
            fmt3(nx),
            fmt3(y),
            fmt3(ny)
        ));
    }
    // The irradiance at the centre below a disk light of radiance 1, radius R,
    // height h: E = ∫ G dA = π R² / (h² + R²); uniform points on the disk.
    let (r, h) = (0.8f32, 1.0f32);
    let mut stats = MeanVar::default();
    for i in 0..ESTIMATES {
        let mut s = Sampler::new(13, i, 0);
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
    )?;
    // MIS weights over many strategies.
    let sets: [&[f32]; 5] = [
        &[1.0, 2.0, 3.0],
        &[0.1, 10.0],
        &[5.0],
        &[0.0, 1.0, 0.0, 2.0],
        &[1e-3, 1e3, 1.0, 1.0],
    ];
    for pdfs in sets {
        let ws: Vec<f32> = (0..pdfs.len()).map(|s| weight(pdfs, s)).collect();
        let sum: f32 = ws.iter().sum();
        if ws
            .iter()
            .any(|w| !(w.is_finite() && (0.0..=1.0).contains(w)))
            || (sum - 1.0).abs() > 1e-4
        {
            return Err(format!(
                "bdpt_mis_weight over the densities {pdfs:?} gives {ws:?} (sum {sum}): the weights of all strategies must be in [0, 1] and sum to one"
            ));
        }
        let best = (0..pdfs.len())
            .max_by(|&a, &b| pdfs[a].total_cmp(&pdfs[b]))
            .unwrap_or(0);
        if ws.iter().any(|&w| w > ws[best] + 1e-6) {
            return Err(format!(
                "bdpt_mis_weight over the densities {pdfs:?} gives {ws:?}: the strategy with the largest density must get the largest weight"
            ));
        }
        if let Some(z) = pdfs.iter().position(|&p| p == 0.0)
            && ws[z] != 0.0
        {
            return Err(format!(
                "bdpt_mis_weight({pdfs:?}, {z}) is {}: a strategy that cannot make the path (density 0) gets weight 0",
                ws[z]
            ));
        }
    }
    // Unbiasedness: one sample from each of three strategies, combined.
    let strategies = [Strategy::Cosine, Strategy::Uniform, Strategy::Cone];
    let mut stats = MeanVar::default();
    for i in 0..ESTIMATES {
        let mut s = Sampler::new(131, i, 0);
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
