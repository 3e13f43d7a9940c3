//! One ray against four triangles at once, one triangle per SIMD lane.
//!
//! Lecture topic: none of its own (ray-surface intersection).
//!
//! A BVH leaf holds a few triangles; testing them one after the other is a
//! chain of dependent scalar steps per triangle. [`Triangle4`] stores four
//! triangles structure-of-arrays (each vertex coordinate a `Vec4`), so the
//! watertight test of [`super::triangle::intersect_triangle`] runs for all
//! four in the lanes of one register, with the same operations in the same
//! order ([`super::lanes`]): each lane's `t` and barycentrics equal the scalar
//! test's bit for bit, and meshes stay watertight. Unused lanes hold NaN
//! vertices, whose `t` is NaN and fails every comparison.

use super::lanes::{Lanes3, add, cross, dot, splat, sub};
use crate::math::{Vec3A, Vec4};

/// Up to four triangles: `v[k][axis]` holds coordinate `axis` of vertex `k`
/// of the four triangles, one per lane.
#[derive(Clone, Copy, Debug)]
#[repr(C, align(16))]
pub struct Triangle4 {
    v: [Lanes3; 3],
}

/// A ray prepared for [`Triangle4::intersect`]: origin and direction in all
/// four lanes (made once per ray, not once per leaf).
pub struct Ray4 {
    o: Lanes3,
    d: Lanes3,
}

impl Ray4 {
    #[inline(always)]
    pub fn new(o: Vec3A, d: Vec3A) -> Self {
        Ray4 {
            o: splat(o),
            d: splat(d),
        }
    }
}

/// The lanes of a [`Triangle4`] that a ray hits, with their distances (+∞
/// in the other lanes) and barycentrics `(b1, b2)` (meaningful in the lanes
/// of `mask` only).
pub struct Hits4 {
    /// Bit `k` set when triangle `k` is hit with `t ∈ (0, t_max)`.
    pub mask: u32,
    pub t: Vec4,
    pub b1: Vec4,
    pub b2: Vec4,
}

impl Hits4 {
    /// The lane of the nearest hit (the first of equals, as a scalar loop
    /// that keeps only strictly nearer hits would choose); `mask` must not
    /// be zero.
    #[inline(always)]
    pub fn nearest(&self) -> usize {
        let nearest = self.t.cmpeq(Vec4::splat(self.t.min_element())).bitmask() & self.mask;
        nearest.trailing_zeros() as usize
    }
}

impl Triangle4 {
    /// Packs up to four triangles `[v0, v1, v2]`; the lanes after them are
    /// empty (NaN) and never hit.
    pub fn new(triangles: &[[Vec3A; 3]]) -> Self {
        assert!(triangles.len() <= 4, "a Triangle4 holds four triangles");
        let mut v = [[Vec4::NAN; 3]; 3];
        for (lane, tri) in triangles.iter().enumerate() {
            for (k, p) in tri.iter().enumerate() {
                for axis in 0..3 {
                    v[k][axis][lane] = p[axis];
                }
            }
        }
        Triangle4 { v }
    }

    /// The watertight test of [`super::triangle::intersect_triangle`],
    /// lane by lane, for `t ∈ (0, t_max)`.
    #[inline(always)]
    pub fn intersect(&self, ray: &Ray4, t_max: f32) -> Hits4 {
        let [a, b, c] = self.v.map(|p| sub(&p, &ray.o));
        let (e_ca, e_ab, e_bc) = (sub(&c, &a), sub(&a, &b), sub(&b, &c));
        let w1 = dot(&ray.d, &cross(&e_ca, &add(&c, &a)));
        let w2 = dot(&ray.d, &cross(&e_ab, &add(&a, &b)));
        let w0 = dot(&ray.d, &cross(&e_bc, &add(&b, &c)));
        // The scalar test rejects when the smallest is negative and the
        // largest positive: some negative and some positive (NaN neither).
        let negative = w0.cmplt(Vec4::ZERO) | w1.cmplt(Vec4::ZERO) | w2.cmplt(Vec4::ZERO);
        let positive = w0.cmpgt(Vec4::ZERO) | w1.cmpgt(Vec4::ZERO) | w2.cmpgt(Vec4::ZERO);
        let den = w0 + w1 + w2;
        let n = cross(&e_ca, &e_ab);
        let t = dot(&a, &n) / dot(&ray.d, &n);
        let hit = !(negative & positive)
            & den.cmpne(Vec4::ZERO)
            & t.cmpgt(Vec4::ZERO)
            & t.cmplt(Vec4::splat(t_max));
        let mask = hit.bitmask();
        let t = Vec4::select(hit, t, Vec4::INFINITY);
        if mask == 0 {
            return Hits4 {
                mask,
                t,
                b1: w1,
                b2: w2,
            };
        }
        let inv = Vec4::ONE / den;
        Hits4 {
            mask,
            t,
            b1: w1 * inv,
            b2: w2 * inv,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::triangle::intersect_triangle;
    use crate::sampling::Sampler;

    fn point(s: &mut Sampler) -> Vec3A {
        Vec3A::new(s.next_1d(), s.next_1d(), s.next_1d()) * 2.0 - Vec3A::ONE
    }

    /// Every lane gives exactly the scalar test's answer (hit or not, and
    /// then `t`, `b1`, `b2` bit for bit), for random triangles and rays,
    /// with one to four lanes used; the nearest lane is the scalar loop's.
    #[test]
    fn lanes_equal_the_scalar_test() {
        let mut s = Sampler::new(5, 0, 0);
        let mut hits = 0;
        for i in 0..20_000 {
            let n = 1 + i % 4;
            let tris: Vec<[Vec3A; 3]> = (0..n)
                .map(|_| {
                    let c = point(&mut s);
                    [c, c + 0.5 * point(&mut s), c + 0.5 * point(&mut s)]
                })
                .collect();
            // Aimed at a point of the plane of one of the triangles, near
            // it: about half the rays hit that one.
            let [v0, v1, v2] = tris[i % n];
            let (u, w) = (1.4 * s.next_1d() - 0.2, 1.4 * s.next_1d() - 0.2);
            let o = point(&mut s) * 3.0;
            let d = (v0 + u * (v1 - v0) + w * (1.0 - u) * (v2 - v0) - o).normalize();
            let t_max = if i % 3 == 0 { 2.5 } else { f32::INFINITY };
            let h = Triangle4::new(&tris).intersect(&Ray4::new(o, d), t_max);
            let mut scalar_best: Option<(usize, f32)> = None;
            for (k, [v0, v1, v2]) in tris.iter().enumerate() {
                let scalar = intersect_triangle(*v0, *v1, *v2, o, d, t_max);
                assert_eq!(h.mask >> k & 1 != 0, scalar.is_some(), "case {i} lane {k}");
                if let Some((t, b1, b2)) = scalar {
                    hits += 1;
                    assert_eq!((h.t[k], h.b1[k], h.b2[k]), (t, b1, b2), "case {i}");
                    if scalar_best.is_none_or(|(_, best)| t < best) {
                        scalar_best = Some((k, t));
                    }
                }
            }
            assert_eq!(h.mask >> n, 0, "case {i}: an empty lane hit");
            if let Some((k, _)) = scalar_best {
                assert_eq!(h.nearest(), k, "case {i}");
            }
        }
        assert!(hits > 6_000, "{hits} hits: the test tests little");
    }

    /// Equal distances: the first lane wins, as in a scalar loop.
    #[test]
    fn nearest_of_equals_is_the_first() {
        let tri = [
            Vec3A::new(-1.0, -1.0, 0.0),
            Vec3A::new(1.0, -1.0, 0.0),
            Vec3A::Y,
        ];
        let h = Triangle4::new(&[tri, tri, tri]).intersect(
            &Ray4::new(Vec3A::new(0.0, 0.0, 1.0), -Vec3A::Z),
            f32::INFINITY,
        );
        assert_eq!((h.mask, h.nearest()), (0b111, 0));
    }
}
