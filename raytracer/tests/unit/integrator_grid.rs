//! Unit tests of `integrator/grid.rs`.

use raytracer::integrator::grid::*;
use raytracer::math::Vec3A;

/// 2000 points of a 3-d Kronecker sequence in [-1, 1]³.
fn points() -> Vec<Vec3A> {
    let g = Vec3A::new(0.819_172_5, 0.671_043_5, 0.549_700_5);
    (1..=2000)
        .map(|i| (g * i as f32).fract() * 2.0 - Vec3A::ONE)
        .collect()
}

/// A radius query finds exactly the points a brute-force scan finds.
#[test]
fn radius_queries_find_what_a_scan_finds() {
    let pts = points();
    let grid = Grid::build(-Vec3A::ONE, Vec3A::ONE, 0.1, pts.len(), |i| {
        (pts[i], pts[i])
    });
    for (k, q) in pts.iter().step_by(97).enumerate() {
        let r = 0.05 + 0.03 * k as f32;
        let mut found = Vec::new();
        grid.for_each_near(*q, r, |i| {
            if pts[i as usize].distance(*q) <= r {
                found.push(i)
            }
        });
        found.sort();
        let scan: Vec<u32> = (0..pts.len() as u32)
            .filter(|&i| pts[i as usize].distance(*q) <= r)
            .collect();
        assert_eq!(found, scan);
    }
}

/// Spheres are found from every point inside them, and a grid asked for
/// too many cells coarsens them.
#[test]
fn spheres_are_held_by_every_cell_they_touch() {
    let pts = points();
    let r = |i: usize| 0.02 + 0.1 * (i % 7) as f32;
    let grid = Grid::build(
        -Vec3A::splat(2.0),
        Vec3A::splat(2.0),
        0.15,
        pts.len(),
        |i| (pts[i] - Vec3A::splat(r(i)), pts[i] + Vec3A::splat(r(i))),
    );
    for q in points().iter().map(|p| *p * 0.9) {
        let held = grid.at(q);
        for (i, p) in pts.iter().enumerate() {
            if p.distance(q) < r(i) {
                assert!(held.contains(&(i as u32)), "{i}");
            }
        }
    }
    assert!(grid.at(Vec3A::splat(5.0)).is_empty());
    let big = Grid::build(Vec3A::ZERO, Vec3A::splat(1000.0), 1e-3, 1, |_| {
        (Vec3A::ZERO, Vec3A::ZERO)
    });
    assert!(big.start.len() <= MAX_CELLS + 1 && big.cell_size() > 1.0);
    assert!(
        Grid::build(Vec3A::ZERO, Vec3A::ONE, 0.1, 0, |_| unreachable!())
            .at(Vec3A::ZERO)
            .is_empty()
    );
}
