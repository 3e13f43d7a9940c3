//! Reference solution of exercise 15 (see `src/ex15_bdpt_connection.rs` for the task).

use raytracer::math::Vec3A;

/// The geometry term `G(x ↔ y)`.
pub fn geometry_term(x: Vec3A, nx: Vec3A, y: Vec3A, ny: Vec3A) -> f32 {
    let d = y - x;
    let dist2 = d.length_squared();
    if dist2 == 0.0 {
        return 0.0;
    }
    let w = d / dist2.sqrt();
    nx.dot(w).abs() * ny.dot(w).abs() / dist2
}

/// The power-heuristic weight of strategy `s`.
pub fn bdpt_mis_weight(pdfs: &[f32], s: usize) -> f32 {
    let sum: f32 = pdfs.iter().map(|p| p * p).sum();
    match pdfs.get(s) {
        Some(p) if sum > 0.0 => p * p / sum,
        _ => 0.0,
    }
}
