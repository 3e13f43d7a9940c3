//! Shading normals in importance transport: Veach's adjoint correction.
//!
//! Lecture topic: "Light tracing" — paths built from the lights carry
//! importance-mode throughput (see [`crate::brdf::TransportMode`]). A smooth
//! mesh shades with interpolated normals `n_s` that differ from the
//! geometric normal `n_g` of its flat triangles. Path tracing uses the
//! shading normal in the cosine of the rendering equation, `f_r |ω_i·n_s|`;
//! that makes the scattering at the vertex *not* symmetric in the two
//! directions, so the light side must use its adjoint (Veach's thesis,
//! section 5.3.2, eq. 5.19; pbrt's `CorrectShadingNormal`). With `ω_o`
//! towards the previous vertex of the light path (where the light came from)
//! and `ω_i` towards the next (towards the camera):
//!
//! ```text
//!   f_r(ω_i, ω_o) |ω_i·n_s|  ·  |ω_o·n_s| |ω_i·n_g| / (|ω_o·n_g| |ω_i·n_s|)
//! ```
//!
//! i.e. the light path's usual factor times [`importance_correction`].
//! Without it, light tracing and the light-side strategies of bidirectional
//! tracing converge to a different image of a smooth mesh than path tracing
//! (`tests/shading_normals.rs` shows it on a low-poly ball shaded smooth,
//! where the difference is |z| ≈ 54 in the worst tile; on the finely
//! tessellated torus of `stereo` it is 0.02 % of the mean, too small to see). Where the
//! shading normal is the geometric one (every quad and sphere, flat meshes)
//! the factor is exactly 1.

use crate::geometry::Interaction;
use crate::math::Vec3A;

/// The adjoint correction `|ω_o·n_s| |ω_i·n_g| / (|ω_o·n_g| |ω_i·n_s|)` of a
/// light-path vertex `it` (importance transport), `wo` towards the previous
/// vertex of the light path, `wi` towards the next one (world directions).
/// 1 where `n_s = n_g`; 0 for a direction in the geometric or shading
/// tangent plane (no light crosses there).
#[inline]
pub fn importance_correction(it: &Interaction, wo: Vec3A, wi: Vec3A) -> f32 {
    let (ng, ns) = (it.ng, it.frame.n);
    if ns == ng {
        return 1.0;
    }
    let den = wo.dot(ng).abs() * wi.dot(ns).abs();
    if den == 0.0 {
        return 0.0;
    }
    wo.dot(ns).abs() * wi.dot(ng).abs() / den
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::frame::Frame;
    use crate::math::Vec2;

    fn interaction(ng: Vec3A, ns: Vec3A) -> Interaction {
        Interaction {
            p: Vec3A::ZERO,
            ng,
            frame: Frame::from_normal(ns),
            uv: Vec2::ZERO,
            wo: Vec3A::Y,
            t: 1.0,
            shape: 0,
            p_error: Vec3A::ZERO,
        }
    }

    /// 1 for a flat surface; Veach's ratio for a tilted shading normal,
    /// which makes the adjoint reciprocal: `f* |·n_s|` with the correction
    /// equals the radiance factor with the directions swapped, times
    /// `|ω_i·n_g| / |ω_o·n_g|` — the change of the geometric cosines that
    /// the path's G terms carry.
    #[test]
    fn one_when_flat_and_veachs_ratio_when_tilted() {
        let (wo, wi) = (
            Vec3A::new(0.3, 0.8, 0.1).normalize(),
            Vec3A::new(-0.5, 0.4, 0.2).normalize(),
        );
        assert_eq!(
            importance_correction(&interaction(Vec3A::Y, Vec3A::Y), wo, wi),
            1.0
        );
        let ns = Vec3A::new(0.2, 1.0, 0.0).normalize();
        let it = interaction(Vec3A::Y, ns);
        let c = importance_correction(&it, wo, wi);
        let expect = wo.dot(ns).abs() * wi.y.abs() / (wo.y.abs() * wi.dot(ns).abs());
        assert!((c - expect).abs() < 1e-6 && (c - 1.0).abs() > 0.05, "{c}");
        // Grazing the geometric surface: no transport.
        assert_eq!(importance_correction(&it, Vec3A::X, wi), 0.0);
    }
}
