//! Grader of exercise 10 (next event estimation): the change of measure
//! exactly, then direct light in the Cornell box against the renderer's
//! light-sampling path tracer at depth 2, tile by tile.

use exercises::plug::StudentDirect;
use raytracer::math::Vec3A;

use crate::compare::{EX10_CORNELL_DIRECT, compare};
use crate::stats::{close, fmt3};

/// The signatures of exercise 10.
pub type AreaPdfFn = fn(f32, Vec3A, Vec3A, Vec3A) -> f32;
pub use exercises::plug::EstimateDirectFn as DirectFn;

/// The grader's conversion.
pub fn expected_pdf(pdf_a: f32, x: Vec3A, y: Vec3A, n_y: Vec3A) -> f32 {
    let d = x - y;
    pdf_a * d.length_squared() / (n_y.dot(d.normalize())).abs()
}

pub fn check(to_solid_angle: AreaPdfFn, direct: DirectFn) -> Result<(), String> {
    let cases = [
        (0.25, Vec3A::ZERO, Vec3A::new(0.0, 2.0, 0.0), -Vec3A::Y),
        (0.25, Vec3A::ZERO, Vec3A::new(1.0, 2.0, 0.5), -Vec3A::Y),
        (
            1.0,
            Vec3A::new(0.3, -1.0, 0.2),
            Vec3A::new(-0.2, 0.99, 0.1),
            Vec3A::new(0.0, -1.0, 0.0),
        ),
        // The light's normal faces away: the density uses |cos θ_y|.
        (
            2.0,
            Vec3A::ZERO,
            Vec3A::new(0.5, 1.0, -1.0),
            Vec3A::new(0.0, 0.6, 0.8),
        ),
    ];
    for (pdf_a, x, y, n) in cases {
        let got = to_solid_angle(pdf_a, x, y, n);
        let want = expected_pdf(pdf_a, x, y, n);
        if close(got, want, 1e-4) {
            continue;
        }
        let d = x - y;
        let cos_y = n.dot(d.normalize()).abs();
        let why = if close(got, pdf_a, 1e-4) {
            "that is still the density per unit AREA: multiply by ‖x − y‖² / |cos θ_y|"
        } else if close(got, -want, 1e-4) {
            "a density is never negative: take |cos θ_y|"
        } else if close(got, pdf_a * d.length() / cos_y, 1e-4) {
            "use the SQUARED distance"
        } else if close(got, pdf_a * d.length_squared(), 1e-4) {
            "divide by |cos θ_y|, the cosine at the light"
        } else if close(got, pdf_a * cos_y / d.length_squared(), 1e-4) {
            "upside down: p_ω = p_A · r² / |cos θ_y| (dω = |cos θ_y| dA / r²)"
        } else {
            "p_ω = p_A · ‖x − y‖² / |cos θ_y|, θ_y between n_y and the direction y → x"
        };
        return Err(format!(
            "area_pdf_to_solid_angle({pdf_a}, x = {}, y = {}, n_y = {}) is {got}, expected {want} — {why}",
            fmt3(x),
            fmt3(y),
            fmt3(n)
        ));
    }
    compare(&EX10_CORNELL_DIRECT, &StudentDirect(direct))
        .map_err(|e| format!("direct light by your estimate_direct: {e}"))
}
