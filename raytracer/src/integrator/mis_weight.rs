//! The MIS weight of a bidirectional strategy.
//!
//! Lecture topic: "Combining the strategies" — every strategy `(s, t)` can
//! produce the same path, and MIS lets each count where it is good.
//!
//! **MIS** ([`mis_weight`]): the power heuristic (β = 2, thesis eq. 9.13) over
//! all strategies that could have produced the same path, each strategy's
//! density being a product of the path's vertices' area densities, from the
//! camera side up to its connection and from the light side after it. Only
//! ratios of these densities are needed (thesis, eq. 10.9), and neighbouring
//! strategies differ in a single vertex, so the weight is computed from the
//! densities every vertex stores, in one pass along each subpath. This is
//! pbrt-v4's `MISWeight` (with the power heuristic instead of the balance
//! heuristic); SmallVCM's running `dVCM/dVC` quantities compute the same sums
//! incrementally.
//!
//! **Deltas.** A strategy that would connect at a delta vertex (mirror,
//! glass), or next to it, has density 0 and is left out; the delta's own
//! density, common to the strategies that remain, cancels. A point light is a
//! delta in position: no path can hit it, so the strategy `s = 0` is skipped
//! for it.

use super::vertex::Vertex;
use crate::scene::Scene;

/// Veach's MIS weight (power heuristic) of strategy `(s, t)` for the path
/// `light[0..s] camera[t−1..0]`. `sampled` replaces `light[0]` (if `s = 1`:
/// the resampled light point, t ≥ 2) or `camera[0]` (if `t = 1`: the lens point of
/// the connection). The connection changes four reverse densities — those of
/// the two endpoints and their predecessors, which now depend on the other
/// subpath — so they are set here and restored afterwards.
///
/// The weight is the power heuristic of the strategies' path densities,
/// computed from their ratios to strategy `s`'s (thesis eq. 10.9), skipping
/// strategies whose connection would touch a delta vertex (their density is
/// zero). Every density is the one
/// its strategy actually samples with, also that of the light point that
/// `s = 1` resamples by next event estimation (a sphere light's cone), so
/// the weights of a path sum to 1 by construction (`tests/unit/integrator_mis_weight.rs`).
pub fn mis_weight(
    scene: &Scene,
    light: &mut [Vertex],
    camera: &mut [Vertex],
    s: usize,
    t: usize,
    sampled: Option<Vertex>,
) -> f32 {
    let (own, others) = power_terms(scene, light, camera, s, t, sampled, |_, _| {});
    weight(own, own + others)
}

/// The weight `mis_weight` gives, as a share of the path's total: 0 where
/// the total is not finite or zero (no strategy could make the path).
#[inline]
fn weight(term: f32, total: f32) -> f32 {
    let w = term / total;
    if w.is_finite() { w } else { 0.0 }
}

/// Every strategy's weight for the path of strategy `(s, t)`, as the
/// inspector shows them: entry `i` is the weight of `(i, s + t − i)`, for
/// `i` from 0 to `s + t − 1` (a strategy with no camera vertex is none
/// here). They are the terms [`mis_weight`] sums, each over the same total,
/// so entry `s` is its weight bit for bit and the entries add up to 1 (up to
/// rounding); a strategy that cannot make the path (it would connect at a
/// delta vertex, or hit a point light) gets 0. Costs an allocation: for
/// recording, not for rendering.
pub fn mis_weights(
    scene: &Scene,
    light: &mut [Vertex],
    camera: &mut [Vertex],
    s: usize,
    t: usize,
    sampled: Option<Vertex>,
) -> Vec<f32> {
    let mut terms = vec![0.0f32; s + t];
    let (own, others) = power_terms(scene, light, camera, s, t, sampled, |i, term| {
        terms[i] = term;
    });
    terms[s] = own;
    let total = own + others;
    terms.into_iter().map(|term| weight(term, total)).collect()
}

/// The power heuristic's terms of the path of strategy `(s, t)`, relative
/// to strategy `s`'s density: returns `s`'s own term and the sum of the
/// others', handing each other strategy's term to `each(i, term)` (`i`
/// light vertices). See [`mis_weight`].
#[allow(clippy::too_many_arguments)]
#[inline]
fn power_terms(
    scene: &Scene,
    light: &mut [Vertex],
    camera: &mut [Vertex],
    s: usize,
    t: usize,
    sampled: Option<Vertex>,
    mut each: impl FnMut(usize, f32),
) -> (f32, f32) {
    debug_assert!(
        t >= 1 && s + t >= 2,
        "strategy ({s}, {t}) has no camera vertex"
    );
    // The sampled endpoint takes its subpath's place for the moment (and the
    // vertex it replaces is put back at the end); everything else this
    // changes is four reverse densities and two delta flags, saved as
    // numbers: copying whole vertices took an eighth of BDPT's time.
    let replaced = match sampled {
        Some(v) if t == 1 => Some((true, std::mem::replace(&mut camera[0], v))),
        Some(v) if s == 1 => Some((false, std::mem::replace(&mut light[0], v))),
        _ => None,
    };
    // Endpoints are connected deterministically: not deltas for the sums.
    let saved_delta = (
        s.checked_sub(1).map(|i| light[i].delta),
        camera[t - 1].delta,
    );
    if s > 0 {
        light[s - 1].delta = false;
    }
    camera[t - 1].delta = false;
    // Reverse densities across the connection, all from the path as it is:
    // of the camera endpoint and its predecessor, of the light endpoint and
    // its predecessor.
    let (pt_rev, pt_minus_rev, qs_rev, qs_minus_rev) = {
        let qs = s.checked_sub(1).map(|i| &light[i]);
        let qs_minus = s.checked_sub(2).map(|i| &light[i]);
        let pt = &camera[t - 1];
        let pt_minus = t.checked_sub(2).map(|i| &camera[i]);
        (
            match qs {
                Some(q) => q.pdf_a(scene, qs_minus, pt),
                None => pt.pdf_light_origin_a(scene),
            },
            pt_minus.map(|pm| match qs {
                Some(q) => pt.pdf_a(scene, Some(q), pm),
                None => pt.pdf_light_a(scene, pm),
            }),
            qs.map(|q| pt.pdf_a(scene, pt_minus, q)),
            qs.zip(qs_minus).map(|(q, qm)| q.pdf_a(scene, Some(pt), qm)),
        )
    };
    // Set them, keeping the values they replace.
    let set = |v: &mut Vertex, pdf: f32| std::mem::replace(&mut v.pdf_rev_a, pdf);
    let saved_rev = (
        set(&mut camera[t - 1], pt_rev),
        pt_minus_rev.map(|p| set(&mut camera[t - 2], p)),
        qs_rev.map(|p| set(&mut light[s - 1], p)),
        qs_minus_rev.map(|p| set(&mut light[s - 2], p)),
    );
    // The light point y_0 has the density of a light path's origin in every
    // strategy with s ≥ 2 and in (1, 1), which the stored densities use;
    // but (1, t ≥ 2) resamples it by next event estimation from its
    // neighbour x_1, with another density (a sphere's cone). `c1 = p_NEE /
    // p_origin` scales that strategy's density: the ratios below are taken
    // with the origin density everywhere, and strategy 1 counts `c1² r_1²`.
    let c1 = nee_over_origin(scene, light, camera, s, t);
    let c = |strategy: usize| if strategy == 1 { c1 } else { 1.0 };
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
            let cs = c(s + t - i);
            let term = cs * cs * r * r;
            each(s + t - i, term);
            sum += term;
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
            let ci = c(i);
            let term = ci * ci * r * r;
            each(i, term);
            sum += term;
        }
    }
    // Restore.
    camera[t - 1].pdf_rev_a = saved_rev.0;
    if let Some(p) = saved_rev.1 {
        camera[t - 2].pdf_rev_a = p;
    }
    if let Some(p) = saved_rev.2 {
        light[s - 1].pdf_rev_a = p;
    }
    if let Some(p) = saved_rev.3 {
        light[s - 2].pdf_rev_a = p;
    }
    if let Some(d) = saved_delta.0 {
        light[s - 1].delta = d;
    }
    camera[t - 1].delta = saved_delta.1;
    match replaced {
        Some((true, v)) => camera[0] = v,
        Some((false, v)) => light[0] = v,
        None => {}
    }
    (c(s) * c(s), sum)
}

/// `p_NEE(y_0) / p_origin(y_0)` for the path of strategy `(s, t)` (before
/// `mis_weight` changes anything but with `sampled` in place): the density
/// with which next event estimation from `y_0`'s neighbour `x_1` picks the
/// light point, over that of a light path's origin. 1 for paths of two
/// vertices (there strategy 1 is `(1, 1)`, which joins the light path's own
/// origin to the lens), for a quad light (both are `P(light)/A`) and where
/// either density is zero.
fn nee_over_origin(scene: &Scene, light: &[Vertex], camera: &[Vertex], s: usize, t: usize) -> f32 {
    if s + t < 3 {
        return 1.0;
    }
    let (y0, x1) = match s {
        0 => (&camera[t - 1], &camera[t - 2]),
        1 => (&light[0], &camera[t - 1]),
        _ => (&light[0], &light[1]),
    };
    let origin = y0.pdf_light_origin_a(scene);
    let nee = y0.pdf_light_point_a(scene, x1);
    if origin > 0.0 && nee.is_finite() {
        nee / origin
    } else {
        1.0
    }
}
