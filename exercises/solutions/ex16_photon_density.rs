//! Reference solution of exercise 16 (see `src/ex16_photon_density.rs` for the task).

use raytracer::math::{Color, PI};

/// The radiance estimate from the `k` nearest of `photons` (`(d², f_r·Φ)` pairs).
pub fn photon_radiance(photons: &[(f32, Color)], k: usize, max_r2: f32) -> Color {
    let r2 = if photons.len() < k {
        max_r2
    } else {
        let mut d2: Vec<f32> = photons.iter().map(|p| p.0).collect();
        let (_, kth, _) = d2.select_nth_unstable_by(k - 1, f32::total_cmp);
        *kth
    };
    if r2 <= 0.0 {
        return Color::ZERO;
    }
    let mut sum = Color::ZERO;
    for &(d2, fp) in photons {
        if d2 < r2 {
            sum += fp * (2.0 / (PI * r2) * (1.0 - d2 / r2));
        }
    }
    sum
}
