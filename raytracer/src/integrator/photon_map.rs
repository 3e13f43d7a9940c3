//! The photon map and its density estimate.
//!
//! Lecture topic: "photon mapping". The radiance leaving a surface point `x`
//! towards `ω_o` is estimated from the photons that landed near `x`:
//!
//! ```text
//!   L_r(x, ω_o) ≈ Σ_p f_r(x, ω_p, ω_o) Φ_p K(‖x − x_p‖),
//!   K(d) ∝ 1 − d²/r²     for d < r, 0 beyond
//! ```
//!
//! `K` is the **Epanechnikov kernel** on a disk of radius `r`, normalised so
//! that `∫ K dA = 1` over the disk (a density per unit area; exercise 17
//! derives its constant). With the `k` nearest photons, `r` is the distance
//! to the k-th one, which then weighs 0: given `r`, the other `k − 1` are
//! uniform in the disk (where the density is constant) and `π r²` is a
//! Gamma(k) variable, so the expected estimate is the true density `λ` —
//! no bias where the light is uniform (the furnace test holds it
//! exactly). Where it is not, the disk averages the light over its area:
//! blur at a caustic's edge, light from one wall counted on the other at a
//! corner. That is photon mapping's bias; with more photons `r` shrinks and
//! the bias with it.
//!
//! **Shading normals (not applied, by measurement).** A photon's flux per
//! unit area of the true surface is `L_i |n_g(x_p)·ω_p| dω`, while the
//! rendering equation with shading normals weighs `L_i |n_s(x)·ω_p| dω`;
//! the exact estimate carries the factor `|n_s(x)·ω_p| / |n_g(x_p)·ω_p|`
//! per photon (1 wherever the two normals agree: quads, spheres, flat
//! meshes). pbrt omits it, and so does this map (and SPPM's gather). Issue 25
//! measured what it changes on the low-poly smooth ball of
//! `tests/shading_normals.rs`: −1.13 % (z −3.2) without it, +0.44 % (z
//! +0.9) with it computed from the photon's own geometric normal (from
//! `x`'s normal instead, heavy-tailed: +13 to +28 %). On the same ball at
//! 24×24 (k = 30, 20 000 light paths, 64 runs) photon mapping's own blur
//! moves the three-segment light over the ball by +4.8 % and single 6×6
//! tiles by up to +44 % (SPPM at 8 passes: up to ±37 %): the missing factor
//! is a quarter of the blur at the ball's scale and invisible beside it in
//! any tile, while applying it would add a normal per photon (40 → 44
//! bytes) and a field to exercise 17's `Photon`. Revisit if a scene with
//! strongly bent shading normals under smooth light shows it.
//!
//! The photons sit in a [`Grid`] whose cells are as large as the largest
//! search radius.

use std::cell::RefCell;

use super::grid::Grid;
use super::photon::Photon;
use crate::brdf::Brdf;
use crate::geometry::Interaction;
use crate::math::{Color, PI, Vec3A};

/// How far density estimation looks.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Search {
    /// The `k` nearest photons (at most `max_radius` away; with fewer, the
    /// whole disk of `max_radius` is used).
    Nearest { k: usize, max_radius: f32 },
    /// Every photon within a fixed radius.
    Radius(f32),
}

impl Search {
    /// The largest distance it looks at.
    pub fn max_radius(&self) -> f32 {
        match *self {
            Search::Nearest { max_radius, .. } => max_radius,
            Search::Radius(r) => r,
        }
    }
}

/// The normalised Epanechnikov kernel `K(d)` of the module doc (per unit
/// area, 0 from `d = r` on) for `d² = d2`, `r² = r2`.
#[inline]
pub fn epanechnikov(d2: f32, r2: f32) -> f32 {
    if d2 >= r2 {
        0.0
    } else {
        2.0 / (PI * r2) * (1.0 - d2 / r2)
    }
}

/// A photon map: photons in a grid.
#[derive(Clone, Debug)]
pub struct PhotonMap {
    photons: Vec<Photon>,
    grid: Grid,
}

thread_local! {
    /// Candidates of a k-nearest query: (d², index). Reused, not reallocated.
    static CANDIDATES: RefCell<Vec<(f32, u32)>> = const { RefCell::new(Vec::new()) };
}

impl PhotonMap {
    /// A map of `photons` for searches up to `max_radius` away.
    pub fn build(photons: Vec<Photon>, max_radius: f32) -> PhotonMap {
        let (mut lo, mut hi) = (Vec3A::splat(f32::MAX), Vec3A::splat(f32::MIN));
        for p in &photons {
            lo = lo.min(p.p.into());
            hi = hi.max(p.p.into());
        }
        let grid = Grid::build(lo, hi, max_radius, photons.len(), |i| {
            (photons[i].p.into(), photons[i].p.into())
        });
        PhotonMap { photons, grid }
    }

    pub fn len(&self) -> usize {
        self.photons.len()
    }

    pub fn is_empty(&self) -> bool {
        self.photons.is_empty()
    }

    pub fn photons(&self) -> &[Photon] {
        &self.photons
    }

    /// Bytes the map holds (photons and grid).
    pub fn bytes(&self) -> usize {
        self.photons.len() * std::mem::size_of::<Photon>() + self.grid.bytes()
    }

    /// Calls `f(index, photon, d²)` for every photon within `r` of `p` that
    /// `keep` accepts.
    #[inline]
    pub fn for_each_within(
        &self,
        p: Vec3A,
        r: f32,
        keep: impl Fn(&Photon) -> bool,
        mut f: impl FnMut(u32, &Photon, f32),
    ) {
        let r2 = r * r;
        self.grid.for_each_near(p, r, |i| {
            let ph = &self.photons[i as usize];
            let d2 = (Vec3A::from(ph.p) - p).length_squared();
            if d2 <= r2 && keep(ph) {
                f(i, ph, d2);
            }
        });
    }

    /// The reflected radiance `L_r(x, ω_o)` at `it` (whose `wo` is `ω_o`)
    /// with BRDF `brdf`, from the photons `keep` accepts (see the module
    /// doc; the BRDF is evaluated in the local frame, both directions
    /// pointing away from `x`).
    pub fn radiance(
        &self,
        it: &Interaction,
        brdf: &Brdf,
        search: Search,
        keep: impl Fn(&Photon) -> bool,
    ) -> Color {
        if self.photons.is_empty() {
            return Color::ZERO;
        }
        let wo = it.frame.to_local(it.wo);
        let f = |ph: &Photon| brdf.eval(wo, it.frame.to_local(ph.wi.into()), it.uv);
        let power = |ph: &Photon| Color::from(ph.power);
        match search {
            Search::Radius(r) => {
                let mut l = Color::ZERO;
                let r2 = r * r;
                self.for_each_within(it.p, r, &keep, |_, ph, d2| {
                    l += f(ph) * power(ph) * epanechnikov(d2, r2);
                });
                l
            }
            Search::Nearest { k, max_radius } => CANDIDATES.with(|c| {
                let mut c = c.borrow_mut();
                c.clear();
                self.for_each_within(it.p, max_radius, &keep, |i, _, d2| c.push((d2, i)));
                // The k nearest (ties by index: the same set on any thread).
                let r2 = if c.len() > k && k > 0 {
                    c.select_nth_unstable_by(k - 1, |a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
                    c.truncate(k);
                    c[k - 1].0
                } else {
                    max_radius * max_radius
                };
                let mut l = Color::ZERO;
                for &(d2, i) in c.iter() {
                    let ph = &self.photons[i as usize];
                    l += f(ph) * power(ph) * epanechnikov(d2, r2);
                }
                l
            }),
        }
    }
}

/// A search radius for `photons` landed on the box `[lo, hi]` such that `k`
/// of them would fall in a disk of that radius if they were spread evenly
/// over the box's surface, times `margin`.
pub fn radius_for(photons: &[Photon], k: usize, margin: f32) -> f32 {
    let (mut lo, mut hi) = (Vec3A::splat(f32::MAX), Vec3A::splat(f32::MIN));
    for p in photons {
        lo = lo.min(p.p.into());
        hi = hi.max(p.p.into());
    }
    if photons.is_empty() {
        return 1.0;
    }
    let d = (hi - lo).max(Vec3A::splat(1e-3));
    let area = 2.0 * (d.x * d.y + d.y * d.z + d.z * d.x);
    margin * (k as f32 * area / (PI * photons.len() as f32)).sqrt()
}
