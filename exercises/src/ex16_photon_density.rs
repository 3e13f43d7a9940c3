//! Exercise 16 — photon mapping: the radiance estimate from the nearest photons.
//!
//! Slides: "Photon mapping" ("Photon mapping"),
//! "Density estimation" ("Оценка на плътността").
//!
//! Photons traced from the lights land on the surfaces; the light that
//! leaves a point x towards the viewer is estimated from the photons that
//! landed near x. Each photon p found near x is given as a pair
//! `(d2, fp)`: its squared distance to x, and `f_r(x; ω_p, ω_o) · Φ_p`, the
//! BRDF at x for the direction it came from times its power (computed by
//! the caller). They come in no particular order, all within the largest
//! search radius, whose square is `max_r2`.
//!
//! Task: the estimate from the `k` nearest photons under the Epanechnikov
//! kernel of the renderer (`epanechnikov` in `raytracer::integrator::photon_map`):
//!
//! ```text
//!   L ≈ Σ_p K(d_p², r²) · fp_p,   K(d², r²) = 2/(π r²) · (1 − d²/r²) for d² < r², else 0
//! ```
//!
//! where r² is the squared distance of the k-th nearest photon (that photon
//! itself then weighs 0). With fewer than k photons, use them all with
//! r² = `max_r2`. The kernel is normalized over the disk of radius r
//! (its integral over the disk's area π r² is 1). If r² is 0, return black.
//!
//! Receives: the photons near x, k ≥ 1, the squared largest radius.
//! Returns: the estimate of the radiance leaving x (RGB).

use raytracer::math::Color;

/// The radiance estimate from the `k` nearest of `photons` (`(d², f_r·Φ)` pairs).
pub fn photon_radiance(photons: &[(f32, Color)], k: usize, max_r2: f32) -> Color {
    // TODO: find r², then add up every photon's kernel-weighted light.
    todo!()
}
