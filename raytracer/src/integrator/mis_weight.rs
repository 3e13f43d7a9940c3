//! The MIS weight of a bidirectional strategy.
//!
//! Lecture topic: "Combining the strategies" — every strategy `(s, t)` can
//! produce the same path, and MIS lets each count where it is good.
//!
//! **MIS** ([`mis_weight`]): the power heuristic (β = 2, thesis eq. 9.13) over
//! all strategies that could have produced the same path,
//! `w_{s,t} = p_s² / Σ_i p_i²` with `p_i` short for `p_{i, s+t−i}`. Only ratios
//! are needed (thesis, eq. 10.9): moving the connection one vertex along the
//! path changes a single factor, `p_{i+1}/p_i = p_rev(x_i) / p_fwd(x_i)`, so
//! `w_{s,t} = 1 / (1 + Σ_{i≠s} (p_i/p_s)²)` is computed from the stored pairs
//! by running products. This is pbrt-v4's `MISWeight` (with the power
//! heuristic instead of the balance heuristic); SmallVCM's running `dVCM/dVC`
//! quantities compute the same sums incrementally.
//!
//! **Deltas.** A strategy that would connect at a delta vertex (mirror,
//! glass), or next to it, has density 0 and is skipped in the sum; its zero
//! pdfs are remapped to 1 so that the running products stay finite. A point
//! light is a delta in position: no path can hit it, so the strategy `s = 0`
//! is skipped for it.

use super::vertex::Vertex;
use crate::scene::Scene;

/// Veach's MIS weight (power heuristic) of strategy `(s, t)` for the path
/// `light[0..s] camera[t−1..0]`. `sampled` replaces `light[0]` (if `s = 1`:
/// the resampled light point, t ≥ 2) or `camera[0]` (if `t = 1`: the lens point of
/// the connection). The connection changes four reverse densities — those of
/// the two endpoints and their predecessors, which now depend on the other
/// subpath — so they are set here and restored afterwards.
///
/// With `r_i = p_i / p_s` built by running products of
/// `p_rev(x)/p_fwd(x)` (thesis eq. 10.9), the weight is `1 / Σ_i r_i²`
/// (power heuristic, `r_s = 1`), skipping strategies whose connection would
/// touch a delta vertex (their density is zero).
pub fn mis_weight(
    scene: &Scene,
    light: &mut [Vertex],
    camera: &mut [Vertex],
    s: usize,
    t: usize,
    sampled: Option<Vertex>,
) -> f32 {
    debug_assert!(
        t >= 1 && s + t >= 2,
        "strategy ({s}, {t}) has no camera vertex"
    );
    // Save what we change.
    let saved_l: [Option<Vertex>; 2] = [
        s.checked_sub(1).map(|i| light[i]),
        s.checked_sub(2).map(|i| light[i]),
    ];
    let saved_c: [Option<Vertex>; 2] = [
        t.checked_sub(1).map(|i| camera[i]),
        t.checked_sub(2).map(|i| camera[i]),
    ];
    if let Some(v) = sampled {
        // (1, 1) resamples the lens point, not the light point.
        if t == 1 {
            camera[0] = v;
        } else if s == 1 {
            light[0] = v;
        }
    }
    // Endpoints are connected deterministically: not deltas for the sums.
    if s > 0 {
        light[s - 1].delta = false;
    }
    if t > 0 {
        camera[t - 1].delta = false;
    }
    let qs = (s > 0).then(|| light[s - 1]);
    let qs_minus = (s > 1).then(|| light[s - 2]);
    let pt = camera[t - 1];
    let pt_minus = (t > 1).then(|| camera[t - 2]);
    // Reverse densities across the connection.
    camera[t - 1].pdf_rev_a = match &qs {
        Some(q) => q.pdf_a(scene, qs_minus.as_ref(), &pt),
        None => pt.pdf_light_origin_a(scene),
    };
    if let Some(pm) = &pt_minus {
        camera[t - 2].pdf_rev_a = match &qs {
            Some(q) => pt.pdf_a(scene, Some(q), pm),
            None => pt.pdf_light_a(scene, pm),
        };
    }
    if let Some(q) = &qs {
        light[s - 1].pdf_rev_a = pt.pdf_a(scene, pt_minus.as_ref(), q);
        if let Some(qm) = &qs_minus {
            light[s - 2].pdf_rev_a = q.pdf_a(scene, Some(&pt), qm);
        }
    }
    #[inline]
    fn remap0(p: f32) -> f32 {
        if p != 0.0 { p } else { 1.0 }
    }
    let mut sum = 0.0f32;
    // Strategies with fewer camera vertices: (s+1, t−1), (s+2, t−2), …, down to t' = 1
    // (a light path cannot hit a pinhole: t' = 0 is never a strategy).
    let mut r = 1.0f32;
    for i in (1..t).rev() {
        r *= remap0(camera[i].pdf_rev_a) / remap0(camera[i].pdf_fwd_a);
        if !camera[i].delta && !camera[i - 1].delta {
            sum += r * r;
        }
    }
    // Strategies with fewer light vertices: (s−1, t+1), …, (0, s+t).
    let mut r = 1.0f32;
    for i in (0..s).rev() {
        r *= remap0(light[i].pdf_rev_a) / remap0(light[i].pdf_fwd_a);
        let delta_before = if i > 0 {
            light[i - 1].delta
        } else {
            light[0].is_delta_light(scene)
        };
        if !light[i].delta && !delta_before {
            sum += r * r;
        }
    }
    // Restore.
    if let Some(v) = saved_l[0] {
        light[s - 1] = v;
    }
    if let Some(v) = saved_l[1] {
        light[s - 2] = v;
    }
    if let Some(v) = saved_c[0] {
        camera[t - 1] = v;
    }
    if let Some(v) = saved_c[1] {
        camera[t - 2] = v;
    }
    let w = 1.0 / (1.0 + sum);
    if w.is_finite() { w } else { 0.0 }
}
