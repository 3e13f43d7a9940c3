//! Packets of four rays traced together through the binary BVH, for
//! coherent rays such as the primary rays of a 2×2 pixel block.
//!
//! Lecture topic: none of its own (acceleration structures).
//!
//! A single ray's traversal is a chain of dependent steps (load a node, test
//! it, branch, load the next), so the processor waits on latency more than
//! it computes. Four coherent rays walk nearly the same path: testing one box
//! against four rays at once, one ray per SIMD lane, costs about as much as
//! testing it against one, and the node is fetched once for all four (Wald
//! et al., "Interactive Rendering with Coherent Ray Tracing", 2001). A node
//! is entered when any ray of the packet hits its box; rays that miss it
//! simply carry on with their lanes masked off. Each ray gets exactly the
//! hit [`Geometry::intersect`] would give it (same arithmetic per lane).

use super::aabb::InverseDirection;
use super::bvh::BvhNode;
use super::primitive::KIND_TRIANGLE;
use super::{Geometry, Hit};
use crate::math::{Ray, Vec2, Vec3A, Vec4};
use glam::BVec4A;

/// Traversal stack size (see [`super::bvh`]: the tree depth is below 64).
const STACK: usize = 64;

/// Four rays in structure-of-arrays form (one ray per lane).
struct Rays4 {
    o: [Vec4; 3],
    d: [Vec4; 3],
    inv_d: [Vec4; 3],
}

/// Entry distances of the four rays into `node`'s box (+∞ where missed),
/// by the slab test of [`super::aabb::Aabb::intersect_ray`] per lane.
#[inline(always)]
fn enter4(node: &BvhNode, r: &Rays4, t_max: Vec4) -> Vec4 {
    let b = node.bounds();
    let mut near = Vec4::ZERO;
    let mut far = t_max;
    for k in 0..3 {
        let t0 = (Vec4::splat(b.min[k]) - r.o[k]) * r.inv_d[k];
        let t1 = (Vec4::splat(b.max[k]) - r.o[k]) * r.inv_d[k];
        near = near.max(t0.min(t1));
        far = far.min(t0.max(t1));
    }
    Vec4::select(near.cmple(far), near, Vec4::INFINITY)
}

/// `(x·x' + y·y') + z·z'`, the order of glam's `Vec3A::dot`, lane by lane.
#[inline(always)]
fn dot(a: &[Vec4; 3], b: &[Vec4; 3]) -> Vec4 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

#[inline(always)]
fn cross(a: &[Vec4; 3], b: &[Vec4; 3]) -> [Vec4; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

#[inline(always)]
fn sub(a: &[Vec4; 3], b: &[Vec4; 3]) -> [Vec4; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

#[inline(always)]
fn add(a: &[Vec4; 3], b: &[Vec4; 3]) -> [Vec4; 3] {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// The watertight triangle test of [`super::triangle::intersect_triangle`]
/// for four rays against one triangle: `(t, b1, b2)` per lane and the mask
/// of lanes that hit with `t ∈ (0, t_max)`.
#[inline(always)]
fn triangle4(v: [Vec3A; 3], r: &Rays4, t_max: Vec4) -> (BVec4A, Vec4, Vec4, Vec4) {
    let rel = |p: Vec3A| {
        sub(
            &[Vec4::splat(p.x), Vec4::splat(p.y), Vec4::splat(p.z)],
            &r.o,
        )
    };
    let (a, b, c) = (rel(v[0]), rel(v[1]), rel(v[2]));
    let (e_ca, e_ab, e_bc) = (sub(&c, &a), sub(&a, &b), sub(&b, &c));
    let w1 = dot(&r.d, &cross(&e_ca, &add(&c, &a)));
    let w2 = dot(&r.d, &cross(&e_ab, &add(&a, &b)));
    let w0 = dot(&r.d, &cross(&e_bc, &add(&b, &c)));
    let lo = w0.min(w1).min(w2);
    let hi = w0.max(w1).max(w2);
    let den = w0 + w1 + w2;
    let n = cross(&e_ca, &e_ab);
    let t = dot(&a, &n) / dot(&r.d, &n);
    let straddles = lo.cmplt(Vec4::ZERO) & hi.cmpgt(Vec4::ZERO);
    let ok = !straddles & den.cmpne(Vec4::ZERO) & t.cmpgt(Vec4::ZERO) & t.cmplt(t_max);
    let inv = Vec4::ONE / den;
    (ok, t, w1 * inv, w2 * inv)
}

impl Rays4 {
    fn new(rays: &[Ray]) -> Rays4 {
        let lane =
            |f: &dyn Fn(&Ray) -> f32| Vec4::new(f(&rays[0]), f(&rays[1]), f(&rays[2]), f(&rays[3]));
        let inv = |r: &Ray| InverseDirection::new(r.d).inv_d;
        Rays4 {
            o: [lane(&|r| r.o.x), lane(&|r| r.o.y), lane(&|r| r.o.z)],
            d: [lane(&|r| r.d.x), lane(&|r| r.d.y), lane(&|r| r.d.z)],
            inv_d: [
                lane(&|r| inv(r).x),
                lane(&|r| inv(r).y),
                lane(&|r| inv(r).z),
            ],
        }
    }
}

/// Entry distances of `G` groups of four rays into `node`, and whether any
/// ray enters it.
#[inline(always)]
fn enter<const G: usize>(node: &BvhNode, r: &[Rays4; G], t_max: &[Vec4; G]) -> ([Vec4; G], bool) {
    let mut any = false;
    let t = std::array::from_fn(|g| {
        let t = enter4(node, &r[g], t_max[g]);
        any |= t.cmplt(Vec4::INFINITY).any();
        t
    });
    (t, any)
}

impl Geometry {
    /// The closest hits of four rays (as four calls of
    /// [`Geometry::intersect`], faster when the rays are coherent).
    pub fn intersect4(&self, rays: &[Ray; 4]) -> [Option<Hit>; 4] {
        self.intersect_packet::<1, 4>(rays)
    }

    /// The closest hits of sixteen rays, e.g. a 4×4 pixel block (as sixteen
    /// calls of [`Geometry::intersect`]). Each group of four consecutive rays
    /// shares SIMD lanes, so the most coherent rays should be neighbours.
    pub fn intersect16(&self, rays: &[Ray; 16]) -> [Option<Hit>; 16] {
        self.intersect_packet::<4, 16>(rays)
    }

    /// `N = 4·G` rays in `G` groups of four lanes.
    fn intersect_packet<const G: usize, const N: usize>(
        &self,
        rays: &[Ray; N],
    ) -> [Option<Hit>; N] {
        debug_assert_eq!(N, 4 * G);
        let mut out = [None; N];
        let nodes = &self.binary.nodes[..];
        if nodes.is_empty() {
            return out;
        }
        let r: [Rays4; G] = std::array::from_fn(|g| Rays4::new(&rays[4 * g..4 * g + 4]));
        let mut t_max: [Vec4; G] = std::array::from_fn(|g| {
            Vec4::from_array(std::array::from_fn(|k| rays[4 * g + k].t_max))
        });
        let mut b1 = [Vec4::ZERO; G];
        let mut b2 = [Vec4::ZERO; G];
        let mut prim = [u32::MAX; N];

        if !enter(&nodes[0], &r, &t_max).1 {
            return out;
        }
        // Pending subtrees with the rays' entry distances.
        let mut stack = [(0u32, [Vec4::ZERO; G]); STACK];
        let mut sp = 0usize;
        let mut index = 0usize;
        loop {
            let node = &nodes[index];
            let count = node.count();
            if count > 0 {
                let first = node.offset();
                for p in first..first + count {
                    let rec = &self.prims[p as usize];
                    if rec.kind() == KIND_TRIANGLE {
                        let v = [rec.a, rec.b, rec.c].map(Vec3A::from_vec4);
                        for g in 0..G {
                            let (m, t, u, w) = triangle4(v, &r[g], t_max[g]);
                            let mut mask = m.bitmask();
                            if mask != 0 {
                                t_max[g] = Vec4::select(m, t, t_max[g]);
                                b1[g] = Vec4::select(m, u, b1[g]);
                                b2[g] = Vec4::select(m, w, b2[g]);
                                while mask != 0 {
                                    prim[4 * g + mask.trailing_zeros() as usize] = p;
                                    mask &= mask - 1;
                                }
                            }
                        }
                    } else {
                        for (k, ray) in rays.iter().enumerate() {
                            let (g, l) = (k / 4, k % 4);
                            if let Some((t, uv)) = rec.intersect(ray.o, ray.d, t_max[g][l]) {
                                t_max[g][l] = t;
                                b1[g][l] = uv.x;
                                b2[g][l] = uv.y;
                                prim[k] = p;
                            }
                        }
                    }
                }
            } else {
                let c = node.offset() as usize;
                let (ta, hit_a) = enter(&nodes[c], &r, &t_max);
                let (tb, hit_b) = enter(&nodes[c + 1], &r, &t_max);
                if hit_a && hit_b {
                    // Front to back by the split axis and the direction of
                    // the first ray (the rays of a packet mostly agree).
                    let axis = node.axis();
                    let (near, far, t_far) = if r[0].d[axis].x < 0.0 {
                        (c + 1, c, ta)
                    } else {
                        (c, c + 1, tb)
                    };
                    stack[sp] = (far as u32, t_far);
                    sp += 1;
                    index = near;
                    continue;
                } else if hit_a || hit_b {
                    index = if hit_a { c } else { c + 1 };
                    continue;
                }
            }
            // Next pending subtree that some ray still enters before its t_max.
            loop {
                if sp == 0 {
                    for (k, o) in out.iter_mut().enumerate() {
                        let (g, l) = (k / 4, k % 4);
                        if prim[k] != u32::MAX {
                            *o = Some(Hit {
                                t: t_max[g][l],
                                prim: prim[k],
                                uv: Vec2::new(b1[g][l], b2[g][l]),
                            });
                        }
                    }
                    return out;
                }
                sp -= 1;
                let (i, t) = stack[sp];
                if (0..G).any(|g| t[g].cmplt(t_max[g]).any()) {
                    index = i as usize;
                    break;
                }
            }
        }
    }
}
