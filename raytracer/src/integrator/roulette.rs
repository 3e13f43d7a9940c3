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
