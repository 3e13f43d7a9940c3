//! The lamp of `cornell` seen directly, against its exact image.
//!
//! At max depth 1 a renderer shows only the emitters seen directly. The
//! lamp is a quad of constant radiance `L` and nothing hides it from the
//! camera, so with a box filter pixel `j` is exactly `L · c_j`, where `c_j`
//! is the fraction of the pixel covered by the lamp's projection — a
//! convex quadrilateral (a pinhole maps lines to lines), clipped against the
//! pixel's square in closed form (Sutherland–Hodgman, then the shoelace
//! formula, in f64). No sampled reference: path tracing and light tracing
//! must both converge to it, pixel by pixel.
//!
//! What it catches: light tracing once stored its first vertex `y_0` at the
//! ray's origin, pushed off the lamp by the ray offset, instead of on the
//! lamp: its `t = 1` connections saw a lamp a few hundredths of a
//! millimetre lower (−0.26 % and +1.7 % on `cornell`'s edge rows, against
//! Mitsuba). The offset follows the coordinates' magnitude, so the same box
//! 100 m up (offsets of 3 mm: 0.27 pixel) makes that a gross error here;
//! a lamp of the wrong size, a wrong importance or a shifted camera ray
//! fail in both boxes.

use crate::common;

use raytracer::film::Film;
use raytracer::geometry::Quad;
use raytracer::integrator::{Integrator, LightTracer, PathTracer};
use raytracer::light::{AreaLight, AreaShape, Light};
use raytracer::math::Vec3A;
use raytracer::metrics::z_threshold;
use raytracer::render::{RenderOptions, render};
use raytracer::scene::Scene;

/// The exact coverage `c_j` of every pixel by the lamp's projection, and of
/// every pixel whether it lies within 0.01 pixel of it.
fn coverage(scene: &Scene) -> (Vec<f64>, Vec<bool>) {
    let (lamp, _) = lamp(scene);
    let eye = scene.camera.position();
    let quad: Vec<[f64; 2]> = [
        lamp.origin,
        lamp.origin + lamp.e1,
        lamp.origin + lamp.e1 + lamp.e2,
        lamp.origin + lamp.e2,
    ]
    .iter()
    .map(|&p| {
        let r = scene.camera.raster_of(p, eye).expect("the lamp is in view");
        [r.x as f64, r.y as f64]
    })
    .collect();
    let (w, h) = (scene.camera.width, scene.camera.height);
    let mut c = Vec::new();
    let mut near = Vec::new();
    for y in 0..h {
        for x in 0..w {
            let (x, y) = (x as f64, y as f64);
            c.push(area(&clip(&quad, [x, y], [x + 1.0, y + 1.0])));
            near.push(area(&clip(&quad, [x - 0.01, y - 0.01], [x + 1.01, y + 1.01])) > 0.0);
        }
    }
    (c, near)
}

/// The lamp's quad and its radiance (red channel).
fn lamp(scene: &Scene) -> (Quad, f64) {
    match &scene.lights[..] {
        [
            Light::Area(AreaLight {
                shape: AreaShape::Quad(q),
                radiance,
                ..
            }),
        ] => (*q, radiance.x as f64),
        other => panic!("cornell has one quad light: {other:?}"),
    }
}

/// The polygon `poly` clipped to the box `[lo, hi]` (Sutherland–Hodgman:
/// one half-plane at a time).
fn clip(poly: &[[f64; 2]], lo: [f64; 2], hi: [f64; 2]) -> Vec<[f64; 2]> {
    let mut out = poly.to_vec();
    for (axis, bound, keep_below) in [
        (0, lo[0], false),
        (0, hi[0], true),
        (1, lo[1], false),
        (1, hi[1], true),
    ] {
        let inside = |p: &[f64; 2]| {
            if keep_below {
                p[axis] <= bound
            } else {
                p[axis] >= bound
            }
        };
        let input = std::mem::take(&mut out);
        for i in 0..input.len() {
            let (a, b) = (input[i], input[(i + 1) % input.len()]);
            let cross = || {
                let t = (bound - a[axis]) / (b[axis] - a[axis]);
                [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]
            };
            match (inside(&a), inside(&b)) {
                (true, true) => out.push(b),
                (true, false) => out.push(cross()),
                (false, true) => {
                    out.push(cross());
                    out.push(b);
                }
                (false, false) => {}
            }
        }
    }
    out
}

/// Area of a simple polygon (shoelace).
fn area(poly: &[[f64; 2]]) -> f64 {
    let n = poly.len();
    (0..n)
        .map(|i| {
            let (a, b) = (poly[i], poly[(i + 1) % n]);
            a[0] * b[1] - b[0] * a[1]
        })
        .sum::<f64>()
        .abs()
        / 2.0
}

fn render_at_depth_1(scene: &Scene, integrator: &dyn Integrator, spp: u32, seed: u64) -> Film {
    let options = RenderOptions {
        spp,
        seed,
        threads: None,
        progress: false,
        ..RenderOptions::default()
    };
    render(scene, integrator, &options).film
}

/// `P(K ≥ k)` and `P(K ≤ k)` of a binomial `K ~ B(n, p)`, summed exactly
/// in f64 (log space).
fn binomial_tails(n: u64, p: f64, k: u64) -> (f64, f64) {
    if p <= 0.0 {
        return (if k == 0 { 1.0 } else { 0.0 }, 1.0);
    }
    if p >= 1.0 {
        return (1.0, if k == n { 1.0 } else { 0.0 });
    }
    let ln_choose = |i: u64| -> f64 { (1..=i).map(|j| ((n - i + j) as f64 / j as f64).ln()).sum() };
    let pmf = |i: u64| (ln_choose(i) + i as f64 * p.ln() + (n - i) as f64 * (1.0 - p).ln()).exp();
    let upper = (k..=n).map(pmf).sum::<f64>();
    let lower = (0..=k).map(pmf).sum::<f64>();
    (upper.min(1.0), lower.min(1.0))
}

/// Path tracing at max depth 1: a sample is `L` if its camera ray hits the
/// lamp and 0 otherwise, so `N·X̄_j / L` is a binomial count `B(N, c_j)`,
/// tested exactly: each pixel's two-sided tail probability must exceed
/// `1e-4 / pixels` (Bonferroni: the whole image fails a correct renderer
/// with probability below 1e-4). Fully covered and uncovered pixels must
/// be exactly `L` and 0.
fn path_tracing_matches(scene: &Scene, what: &str) {
    let spp = 32;
    let film = render_at_depth_1(
        scene,
        &PathTracer {
            max_depth: Some(1),
            ..PathTracer::default()
        },
        spp,
        7,
    );
    let image = film.image();
    let (c, _) = coverage(scene);
    let (_, l) = lamp(scene);
    let tested = c.iter().filter(|&&c| c > 0.0).count();
    let alpha = 1e-4 / image.pixels.len() as f64;
    let mut partial = 0;
    for (j, (&cj, got)) in c.iter().zip(&image.pixels).enumerate() {
        let got = got.x as f64;
        let k = (got * spp as f64 / l).round() as u64;
        assert!(
            (k as f64 * l / spp as f64 - got).abs() <= 1e-4 * l,
            "{what}: pixel {j} is no multiple of L/N: {got}"
        );
        let (upper, lower) = binomial_tails(spp as u64, cj.clamp(0.0, 1.0), k);
        assert!(
            upper.min(lower) > alpha,
            "{what}: path tracing, pixel ({}, {}): {k} of {spp} samples on the lamp, exact coverage {cj:.4} (tail {:.1e})",
            j % scene.camera.width as usize,
            j / scene.camera.width as usize,
            upper.min(lower)
        );
        partial += (cj > 0.0 && cj < 1.0) as usize;
    }
    eprintln!("{what}: path tracing agrees on {tested} lamp pixels ({partial} partly covered)");
    assert!(
        partial > 80 && tested > 400,
        "{what}: the lamp covers {tested} pixels"
    );
}

/// Light tracing at max depth 1: every light path's first vertex is joined
/// to the lens and splatted. Pixels farther than 0.01 pixel from the lamp's
/// projection get nothing at all; pixels covered by at least 5 % get
/// hundreds of splats each (16 spp: a million light paths on 436 lamp
/// pixels), where the normal approximation holds: |z| with the film's own
/// variance below the Šidák threshold for a family-wise false-failure
/// probability of 1e-4. (Pixels covered by less than 5 % may get too few
/// splats for a z-test; the zero ring around them still pins the edges.)
fn light_tracing_matches(scene: &Scene, what: &str) {
    let film = render_at_depth_1(
        scene,
        &LightTracer {
            max_depth: Some(1),
            rr_depth: 5,
        },
        16,
        8,
    );
    let (image, variance) = (film.image(), film.variance_image());
    let (c, near) = coverage(scene);
    let (_, l) = lamp(scene);
    let tested = c.iter().filter(|&&c| c >= 0.05).count();
    let threshold = z_threshold(tested, 1e-4);
    let mut worst = 0.0f64;
    for (j, &cj) in c.iter().enumerate() {
        let (x, y) = (
            j % scene.camera.width as usize,
            j / scene.camera.width as usize,
        );
        let got = image.pixels[j].x as f64;
        if !near[j] {
            assert_eq!(
                got, 0.0,
                "{what}: light tracing lit pixel ({x}, {y}) away from the lamp"
            );
        }
        if cj >= 0.05 {
            let z = (got - l * cj) / (variance.pixels[j].x as f64).sqrt();
            worst = worst.max(z.abs());
            assert!(
                z.abs() < threshold,
                "{what}: light tracing, pixel ({x}, {y}): {got:.4} vs exact {:.4} (coverage {cj:.4}), |z| = {:.1}",
                l * cj,
                z.abs()
            );
        }
    }
    eprintln!(
        "{what}: light tracing agrees on {tested} lamp pixels, max |z| = {worst:.2} (threshold {threshold:.2})"
    );
}

#[test]
fn cornell_lamp_at_max_depth_1_is_its_exact_coverage() {
    let scene = Scene::builtin("cornell").unwrap();
    path_tracing_matches(&scene, "cornell");
    light_tracing_matches(&scene, "cornell");
}

#[test]
fn the_same_box_100_m_up_too() {
    let scene = common::builtin_moved("cornell", 1.0, Vec3A::new(0.0, 100.0, 0.0));
    path_tracing_matches(&scene, "cornell 100 m up");
    light_tracing_matches(&scene, "cornell 100 m up");
}
