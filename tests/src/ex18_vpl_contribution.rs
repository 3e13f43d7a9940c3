//! Grader of exercise 18 (one VPL's contribution, clamped): the value
//! exactly over edges whose geometry term lies below, at and above the
//! bound, with the bound 0 (no clamping), the usual mistakes named by
//! comparing all cases at once; and clamping never adds light.
//!
//! Tolerances: exact values to 1e-4 relative (deterministic: no false
//! failures).

use raytracer::math::{Color, Vec3A};

use crate::ex15_bdpt::expected_g;
use crate::stats::{Mistake, fmt3, recognise};

/// The signature of exercise 18.
pub type VplFn = fn(Vec3A, Vec3A, Vec3A, Vec3A, Color, f32) -> Color;

/// A case: `(x, nx, y, ny, fff, clamp)`.
type Case = (Vec3A, Vec3A, Vec3A, Vec3A, Color, f32);

/// G clamped as the task says.
fn clamped(g: f32, clamp: f32) -> f32 {
    if clamp > 0.0 { g.min(clamp) } else { g }
}

/// The grader's contribution.
pub fn expected(&(x, nx, y, ny, fff, clamp): &Case) -> Color {
    fff * clamped(expected_g(x, nx, y, ny), clamp)
}

fn cases() -> Vec<Case> {
    let c = Color::new;
    let v = Vec3A::new;
    vec![
        // Far apart: G = 0.25 below every bound.
        (
            Vec3A::ZERO,
            Vec3A::Y,
            v(0.0, 2.0, 0.0),
            -Vec3A::Y,
            c(1.0, 0.5, 0.25),
            1.0,
        ),
        // Close, in a corner: G far above the bound.
        (
            v(0.05, 0.0, 0.0),
            Vec3A::Y,
            v(0.0, 0.1, 0.0),
            Vec3A::X,
            c(0.3, 0.6, 0.9),
            2.0,
        ),
        // The same edge without clamping.
        (
            v(0.05, 0.0, 0.0),
            Vec3A::Y,
            v(0.0, 0.1, 0.0),
            Vec3A::X,
            c(0.3, 0.6, 0.9),
            0.0,
        ),
        // Tilted normals, one facing away from the edge.
        (
            v(0.2, 0.1, -0.3),
            v(0.0, 0.6, 0.8),
            v(-0.4, 0.5, 0.4),
            v(0.6, 0.0, -0.8),
            c(2.0, 1.0, 0.5),
            0.5,
        ),
        (
            v(0.1, 0.0, 0.0),
            -Vec3A::Y,
            v(0.5, 1.2, 0.4),
            Vec3A::Y,
            c(0.8, 0.8, 0.2),
            0.0,
        ),
        // A bright VPL barely below the bound.
        (
            Vec3A::ZERO,
            Vec3A::Y,
            v(0.3, 0.6, 0.0),
            -Vec3A::Y,
            c(5.0, 4.0, 3.0),
            2.0,
        ),
    ]
}

pub fn check(contribution: VplFn) -> Result<(), String> {
    let cases = cases();
    let got: Vec<Color> = cases
        .iter()
        .map(|&(x, nx, y, ny, f, cl)| contribution(x, nx, y, ny, f, cl))
        .collect();
    let same = |g: Color, e: Color| {
        (g - e)
            .abs()
            .cmple(1e-4 * e.abs().max(Color::splat(1e-4)))
            .all()
    };
    if let Some(k) = (0..cases.len()).find(|&k| !same(got[k], expected(&cases[k]))) {
        let g = |&(x, nx, y, ny, ..): &Case| expected_g(x, nx, y, ny);
        let cx = |&(x, nx, y, ..): &Case| nx.dot((y - x).normalize());
        let cy = |&(x, _, y, ny, ..): &Case| ny.dot((x - y).normalize());
        let r2 = |&(x, _, y, ..): &Case| (y - x).length_squared();
        let mistakes: [Mistake<Case, Color>; 8] = [
            (
                "G is not clamped: where G exceeds the bound, use min(G, clamp)",
                &|c| c.4 * g(c),
            ),
            (
                "a bound of 0 means no clamping (the task says so), not that no light passes: clamp only when clamp > 0",
                &|c| c.4 * g(c).min(c.5),
            ),
            (
                "clamping bounds the geometry term G, not the light: min(G, clamp) times fff, the same bound for every colour",
                &|c| {
                    let l = c.4 * g(c);
                    if c.5 > 0.0 {
                        l.min(Color::splat(c.5))
                    } else {
                        l
                    }
                },
            ),
            ("the bound is an upper one: min(G, clamp), not max", &|c| {
                c.4 * if c.5 > 0.0 { g(c).max(c.5) } else { g(c) }
            }),
            (
                "G is never negative: the normals may face either way, so take the absolute values of the cosines",
                &|c| c.4 * clamped(cx(c) * cy(c) / r2(c), c.5),
            ),
            (
                "divide by the SQUARED distance (the solid angle of a patch falls as 1/r²)",
                &|c| c.4 * clamped((cx(c) * cy(c)).abs() / r2(c).sqrt(), c.5),
            ),
            (
                "the cosine at y is missing: G has one cosine at each end of the edge",
                &|c| c.4 * clamped(cx(c).abs() / r2(c), c.5),
            ),
            (
                "your G is |cos θ_x cos θ_y| without the 1/‖x − y‖²: divide by the squared distance — or, if you used y − x unnormalized in the dot products, its length r² cancelled it: normalize the edge direction first",
                &|c| c.4 * clamped((cx(c) * cy(c)).abs(), c.5),
            ),
        ];
        let (x, nx, y, ny, fff, clamp) = cases[k];
        let why = recognise(&cases, &got, &mistakes, same).unwrap_or_else(|| {
            "G = |cos θ_x| |cos θ_y| / ‖x − y‖² with the unit edge direction; min(G, clamp) if clamp > 0; times fff".to_string()
        });
        return Err(format!(
            "vpl_contribution(x = {}, nx = {}, y = {}, ny = {}, fff = {fff}, clamp = {clamp}) is {}, expected {} — {why}",
            fmt3(x),
            fmt3(nx),
            fmt3(y),
            fmt3(ny),
            got[k],
            expected(&cases[k])
        ));
    }
    Ok(())
}
