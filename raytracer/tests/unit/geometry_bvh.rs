//! Unit tests of `geometry/bvh.rs`.

use raytracer::geometry::aabb::Aabb;
use raytracer::geometry::bvh::*;
use raytracer::math::Vec3A;
use raytracer::sampling::Sampler;

fn random_boxes(n: usize, seed: u64) -> Vec<Aabb> {
    (0..n)
        .map(|i| {
            let mut s = Sampler::new(seed, i as u64, 0);
            let c = Vec3A::new(s.next_1d(), s.next_1d(), s.next_1d()) * 10.0;
            let h = Vec3A::new(s.next_1d(), s.next_1d(), s.next_1d()) * 0.2;
            Aabb::new(c - h, c + h)
        })
        .collect()
}

/// Checks that every node's box holds its children / primitives, that
/// every primitive appears once, and returns the depth.
fn check(bvh: &Bvh, boxes: &[Aabb], index: usize, depth: usize) -> usize {
    let node = &bvh.nodes[index];
    let b = node.bounds();
    if node.count() > 0 {
        for k in node.offset()..node.offset() + node.count() {
            let p = boxes[bvh.order[k as usize] as usize];
            assert_eq!(b.union(p), b, "leaf box does not hold its primitive");
        }
        return depth;
    }
    for c in [node.offset() as usize, node.offset() as usize + 1] {
        assert_eq!(b.union(bvh.nodes[c].bounds()), b, "child outside parent");
    }
    let c = node.offset() as usize;
    check(bvh, boxes, c, depth + 1).max(check(bvh, boxes, c + 1, depth + 1))
}

#[test]
fn node_is_32_bytes() {
    assert_eq!(std::mem::size_of::<BvhNode>(), 32);
}

#[test]
fn build_is_consistent() {
    for &n in &[1usize, 2, 7, 100, 20_000] {
        let boxes = random_boxes(n, n as u64);
        let bvh = Bvh::build(&boxes);
        let mut seen = bvh.order.clone();
        seen.sort_unstable();
        assert_eq!(seen, (0..n as u32).collect::<Vec<_>>());
        let depth = check(&bvh, &boxes, 0, 1);
        assert!(depth < STACK, "depth {depth}");
    }
}

#[test]
fn identical_boxes_stay_shallow() {
    // All centroids equal: no SAH split exists, the median split must
    // still give small leaves and a bounded depth.
    let boxes = vec![Aabb::new(Vec3A::ZERO, Vec3A::ONE); 10_000];
    let bvh = Bvh::build(&boxes);
    let depth = check(&bvh, &boxes, 0, 1);
    assert!(depth < STACK);
    assert!(bvh.nodes.iter().all(|n| n.count() as usize <= MAX_LEAF));
}
