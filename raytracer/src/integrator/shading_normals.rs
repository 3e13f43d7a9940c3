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
