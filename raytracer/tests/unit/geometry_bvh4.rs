//! Unit tests of `geometry/bvh4.rs`.

use raytracer::geometry::bvh4::*;

#[test]
fn node_is_two_cache_lines() {
    assert_eq!(std::mem::size_of::<Bvh4Node>(), 128);
}
