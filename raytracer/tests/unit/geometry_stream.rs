//! Unit tests of `geometry/stream.rs`.

use std::sync::Arc;

use raytracer::geometry::Geometry;
use raytracer::geometry::stream::*;
use raytracer::geometry::{Mesh, Quad, Shape, Sphere};
use raytracer::math::{Ray, Vec3A};
use raytracer::sampling::Sampler;

fn point(s: &mut Sampler, half: f32) -> Vec3A {
    (Vec3A::new(s.next_1d(), s.next_1d(), s.next_1d()) * 2.0 - Vec3A::ONE) * half
}

/// Streams of random rays (hits and misses, bounded and unbounded)
/// through triangle soups with spheres and quads: each ray's closest hit
/// is the single-ray traversal's (same `t` bit for bit, same primitive
/// unless another gives that very `t`), and so is its occlusion.
#[test]
fn streams_find_what_single_rays_find() {
    for (n, size) in [(1usize, 0.5f32), (300, 0.1), (20_000, 0.02)] {
        let mut mesh = Mesh::default();
        for i in 0..n {
            let mut s = Sampler::new(5, i as u64, 0);
            let c = point(&mut s, 1.0);
            for _ in 0..3 {
                mesh.positions.push((c + point(&mut s, size)).into());
            }
            let k = 3 * i as u32;
            mesh.indices.push([k, k + 1, k + 2]);
        }
        let mut shapes = vec![Shape::Mesh(Arc::new(mesh))];
        for k in 0..4 {
            let mut s = Sampler::new(6, k, 0);
            shapes.push(Shape::Sphere(Sphere {
                center: point(&mut s, 1.0),
                radius: 0.1 + 0.2 * s.next_1d(),
            }));
            shapes.push(Shape::Quad(Quad {
                origin: point(&mut s, 1.0),
                e1: point(&mut s, 0.4),
                e2: point(&mut s, 0.4),
            }));
        }
        let g = Geometry::new(shapes);
        let rays: Vec<Ray> = (0..3000)
            .map(|i| {
                let mut s = Sampler::new(7, i, n as u64);
                let o = point(&mut s, 1.5);
                let d = (point(&mut s, 1.0) - o).normalize();
                let t_max = if i % 3 == 0 {
                    2.0 * s.next_1d()
                } else {
                    f32::INFINITY
                };
                Ray { o, d, t_max }
            })
            .collect();
        let (mut stream, mut hits, mut blocked) = (RayStream::default(), Vec::new(), Vec::new());
        g.intersect_stream(&rays, &mut hits, &mut stream);
        g.occluded_stream(&rays, &mut blocked, &mut stream);
        let mut found = 0;
        for (i, ray) in rays.iter().enumerate() {
            let single = g.intersect(ray);
            match (hits[i], single) {
                (None, None) => {}
                (Some(a), Some(b)) => {
                    found += 1;
                    assert_eq!(a.t, b.t, "n={n} ray {i}");
                    if a.prim != b.prim {
                        let other = g.prims[b.prim as usize].intersect(ray.o, ray.d, f32::INFINITY);
                        assert_eq!(other.map(|h| h.0), Some(a.t), "n={n} ray {i}");
                    }
                }
                (a, b) => panic!("n={n} ray {i}: stream {a:?} vs single {b:?}"),
            }
            assert_eq!(blocked[i], g.occluded(ray), "n={n} ray {i}");
        }
        assert!(found > 100 && found < rays.len(), "n={n}: {found} hits");
    }
}
