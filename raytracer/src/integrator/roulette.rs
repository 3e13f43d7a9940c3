//! Russian roulette: paths end at no fixed depth and the estimate stays
//! unbiased.
//!
//! Lecture topic: "Russian roulette". Instead of stopping at a fixed depth
//! (biased) or when the throughput is small (biased too), a path continues
//! with probability `q` and what it brings is divided by `q`:
//!
//! ```text
//!   L' = L / q  with probability q,   0 otherwise,   E[L'] = L.
//! ```
//!
//! `q` follows the path's throughput, so a path that carries little is likely
//! to end and one that carries much is likely to go on; it is capped below 1
//! ([`MAX_SURVIVAL`]) so that even a path in a white furnace ends.

use super::dimensions::ROULETTE;
use crate::math::Color;
use crate::sampling::Sampler;

/// The largest survival probability: at least one path in twenty ends at
/// every bounce where roulette is played, whatever its throughput.
pub const MAX_SURVIVAL: f32 = 0.95;

/// Plays Russian roulette for a path whose throughput is `throughput`:
/// survives with `q = min(max channel of throughput · eta_scale,
/// MAX_SURVIVAL)`. `eta_scale` undoes the `1/η²` that refraction put into a
/// radiance throughput, so that a path is judged by what it carries, not by
/// the media it crossed (1 where that does not apply).
///
/// Returns `Some(q)` if the path goes on (the caller divides its throughput
/// by `q`), `None` if it ends. Draws [`ROULETTE`], and nothing when `q ≤ 0`
/// (the path ends for sure).
#[inline]
pub fn russian_roulette(throughput: Color, eta_scale: f32, sampler: &mut Sampler) -> Option<f32> {
    let q = (throughput.max_element() * eta_scale).min(MAX_SURVIVAL);
    if q <= 0.0 || ROULETTE.draw(sampler) >= q {
        return None;
    }
    Some(q)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The survival rate is `q` (capped at `MAX_SURVIVAL`) and the estimate
    /// `L'` stays unbiased: 200 000 plays per case, the mean of `L'/L` within
    /// 5 standard errors of 1 (false failure < 1e-6 per case). A throughput
    /// of zero ends the path without drawing a number.
    #[test]
    fn survivors_divided_by_q_keep_the_mean() {
        for (throughput, eta_scale, q) in [
            (Color::new(0.3, 0.1, 0.2), 1.0, 0.3),
            (Color::splat(0.2), 2.0, 0.4),
            (Color::splat(5.0), 1.0, MAX_SURVIVAL),
        ] {
            let n = 200_000;
            let (mut survived, mut sum) = (0u32, 0.0f64);
            for i in 0..n {
                let mut s = Sampler::new(3, i, 0);
                if let Some(got) = russian_roulette(throughput, eta_scale, &mut s) {
                    assert_eq!(got, q);
                    survived += 1;
                    sum += 1.0 / got as f64;
                }
                assert_eq!(s.dimension(), 1);
            }
            let mean = sum / n as f64;
            // L'/L is 1/q with probability q: variance (1 − q)/q.
            let se = ((1.0 - q as f64) / q as f64 / n as f64).sqrt();
            assert!((mean - 1.0).abs() < 5.0 * se + 1e-9, "{throughput}: {mean}");
            let rate = survived as f64 / n as f64;
            assert!((rate - q as f64).abs() < 0.01, "{throughput}: rate {rate}");
        }
        let mut s = Sampler::new(3, 0, 0);
        assert_eq!(russian_roulette(Color::ZERO, 1.0, &mut s), None);
        assert_eq!(s.dimension(), 0);
    }
}
