//! Tests of [`Geometry`]: BVH against brute force, self-intersection, leaks
//! at corners, surface points.

use std::sync::Arc;

use aabb::Aabb;
use bvh::Bvh;
use mesh::Mesh;
use quad::Quad;
use raytracer::geometry::*;
use raytracer::math::{PI, RayEnd, Vec3};
use raytracer::math::{Ray, Vec2, Vec3A};
use raytracer::sampling::Sampler;
use sphere::Sphere;
use transform::Transform;

fn uniform_sphere(s: &mut Sampler) -> Vec3A {
    let z = 1.0 - 2.0 * s.next_1d();
    let r = (1.0 - z * z).max(0.0).sqrt();
    let phi = 2.0 * PI * s.next_1d();
    Vec3A::new(r * phi.cos(), r * phi.sin(), z)
}

fn uniform_box(s: &mut Sampler, half: f32) -> Vec3A {
    Vec3A::new(s.next_1d(), s.next_1d(), s.next_1d()) * (2.0 * half) - Vec3A::splat(half)
}

/// `n` random triangles of size about `size` in `[-1, 1]³`.
fn soup(n: usize, size: f32, seed: u64) -> Mesh {
    let mut mesh = Mesh::default();
    for i in 0..n {
        let mut s = Sampler::new(seed, i as u64, 0);
        let c = uniform_box(&mut s, 1.0);
        for _ in 0..3 {
            mesh.positions.push((c + uniform_box(&mut s, size)).into());
        }
        let k = 3 * i as u32;
        mesh.indices.push([k, k + 1, k + 2]);
    }
    mesh
}

fn cornell_walls() -> Vec<Shape> {
    // Six walls of [-1, 1]³, normals pointing inwards (e1 × e2).
    let q = |o: Vec3A, e1: Vec3A, e2: Vec3A| Shape::Quad(Quad { origin: o, e1, e2 });
    let m = Vec3A::splat(-1.0);
    let (x, y, z) = (2.0 * Vec3A::X, 2.0 * Vec3A::Y, 2.0 * Vec3A::Z);
    vec![
        q(m, z, x),    // floor y = -1, normal +y
        q(-m, -x, -z), // ceiling y = 1, normal -y
        q(m, x, y),    // back z = -1, normal +z
        q(-m, -y, -x), // front z = 1, normal -z
        q(m, y, z),    // left x = -1, normal +x
        q(-m, -z, -y), // right x = 1, normal -x
    ]
}

/// BVH and brute force agree on the closest hit (same `t` bit for bit, same
/// primitive unless two primitives share that `t`) and on occlusion, for
/// random rays through random triangle soups mixed with spheres and quads.
#[test]
fn bvh_matches_brute_force() {
    for (n, size, rays) in [
        (1usize, 0.5, 500usize),
        (10, 0.5, 1000),
        (1000, 0.1, 2000),
        (50_000, 0.02, 600),
    ] {
        let mut shapes = vec![Shape::Mesh(Arc::new(soup(n, size, n as u64)))];
        for k in 0..5 {
            let mut s = Sampler::new(99, k, n as u64);
            shapes.push(Shape::Sphere(Sphere {
                center: uniform_box(&mut s, 1.0),
                radius: 0.05 + 0.2 * s.next_1d(),
            }));
            shapes.push(Shape::Quad(Quad {
                origin: uniform_box(&mut s, 1.0),
                e1: uniform_box(&mut s, 0.3),
                e2: uniform_box(&mut s, 0.3),
            }));
        }
        let g = Geometry::new(shapes);
        assert_eq!(g.primitive_count(), n + 10);
        let mut hits = 0;
        for i in 0..rays {
            let mut s = Sampler::new(7, i as u64, n as u64);
            let o = uniform_box(&mut s, 1.5);
            // Half the rays aim at the objects, half go anywhere.
            let d = if i % 2 == 0 {
                (uniform_box(&mut s, 1.0) - o).normalize()
            } else {
                uniform_sphere(&mut s)
            };
            let t_max = if i % 3 == 0 {
                0.5 + 2.0 * s.next_1d()
            } else {
                f32::INFINITY
            };
            let ray = Ray { o, d, t_max };
            let fast = g.intersect(&ray);
            let slow = g.intersect_brute_force(&ray);
            match (fast, slow) {
                (None, None) => {}
                (Some(a), Some(b)) => {
                    hits += 1;
                    assert_eq!(a.t, b.t, "n={n} ray {i}");
                    if a.prim != b.prim {
                        // A tie: the other primitive must give the same t.
                        let other = g.prims[a.prim as usize].intersect(o, d, f32::INFINITY);
                        assert_eq!(other.map(|h| h.0), Some(b.t), "n={n} ray {i}");
                    } else {
                        assert_eq!(a.uv, b.uv);
                    }
                }
                _ => panic!("n={n} ray {i}: bvh {fast:?} vs brute force {slow:?}"),
            }
            assert_eq!(g.occluded(&ray), slow.is_some(), "n={n} ray {i}");
        }
        // The test is only meaningful if it sees both hits and misses.
        assert!(
            hits > rays / 20 && hits < rays,
            "n={n}: {hits} hits of {rays}"
        );
    }
}

/// A ray straight down, `Ray::new((0.3, 1, 0.2), −Y)`, onto a floor of 4×4
/// quads at `y = 0` hits at `t = 1`. Its direction is `(−0.0, −1, −0.0)`:
/// the zero components carry a minus sign, so the reciprocal is −1e30 in x
/// and z, and the four-wide traversal once chose its entry planes by
/// `d.x < 0.0` (false for −0.0), which disagreed with that sign and missed
/// every box. Both signs of zero, and the upward ray from below, must hit.
#[test]
fn rays_with_negative_zero_components_hit() {
    let mut shapes = Vec::new();
    for i in 0..4 {
        for j in 0..4 {
            shapes.push(Shape::Quad(Quad {
                origin: Vec3A::new(i as f32 - 2.0, 0.0, j as f32 - 2.0),
                e1: Vec3A::Z,
                e2: Vec3A::X,
            }));
        }
    }
    let g = Geometry::new(shapes);
    assert!(g.node_count() > 1, "a tree, not a single leaf");
    let down = -Vec3A::Y;
    assert!(down.x.is_sign_negative() && down.z.is_sign_negative());
    for (o, d) in [
        (Vec3A::new(0.3, 1.0, 0.2), down),
        (Vec3A::new(0.3, 1.0, 0.2), Vec3A::new(0.0, -1.0, 0.0)),
        (Vec3A::new(-1.7, 1.0, 1.1), down),
        (Vec3A::new(0.3, -1.0, 0.2), Vec3A::new(-0.0, 1.0, -0.0)),
    ] {
        let ray = Ray::new(o, d);
        let hit = g
            .intersect(&ray)
            .unwrap_or_else(|| panic!("{o} along {d} missed"));
        assert_eq!(hit.t, 1.0, "{o} along {d}");
        assert_eq!(Some(hit), g.intersect_brute_force(&ray));
        assert!(g.occluded(&ray));
        assert_eq!(g.intersect4(&[ray; 4]), [Some(hit); 4]);
    }
}

/// Rays with zero direction components of either sign, against brute force,
/// through every traversal: the binary tree, the four-wide tree (closest hit
/// and occlusion) and packets of 4 and 16. The scene is full of axis-aligned
/// quads (a floor of tiles, walls, boxes) whose boxes are flat, so a ray
/// parallel to an axis plane lies exactly in a slab's boundary planes: with
/// `d.x = −0.0` the reciprocal is −∞-like, and a traversal that picks its
/// near and far planes by `d.x < 0.0` (false for −0.0) misses (the four-wide
/// one did: a straight-down ray over a floor of quads found nothing). Each
/// ray aims at a point of a primitive, with 1 or 2 components of its
/// direction replaced by ±0 (the origin moved so that it still aims there).
#[test]
fn signed_zero_directions_match_brute_force_in_every_traversal() {
    let mut shapes = Vec::new();
    let q = |o: Vec3A, e1: Vec3A, e2: Vec3A| Shape::Quad(Quad { origin: o, e1, e2 });
    for i in 0..5 {
        for j in 0..5 {
            let o = Vec3A::new(i as f32 * 0.4 - 1.0, -1.0, j as f32 * 0.4 - 1.0);
            shapes.push(q(o, 0.4 * Vec3A::Z, 0.4 * Vec3A::X));
        }
    }
    shapes.extend(cornell_walls());
    shapes.push(Shape::Mesh(Arc::new(Mesh::cube().transformed(
        &(Transform::translate(Vec3::new(0.3, -0.6, 0.2)) * Transform::scale(Vec3::splat(0.3))),
    ))));
    shapes.push(Shape::Mesh(Arc::new(soup(300, 0.1, 21))));
    shapes.push(Shape::Sphere(Sphere {
        center: Vec3A::new(-0.4, 0.2, -0.3),
        radius: 0.25,
    }));
    let g = Geometry::new(shapes);
    let bounds: Vec<Aabb> = g.prims.iter().map(padded_bounds).collect();
    let binary = Bvh::build(&bounds);
    let binary_closest = |ray: &Ray| {
        let mut best: Option<f32> = None;
        binary.traverse(ray.o, ray.d, ray.t_max, |first, count, t_max| {
            for k in first..first + count {
                let prim = binary.order[k as usize];
                if let Some((t, _)) = g.prims[prim as usize].intersect(ray.o, ray.d, *t_max) {
                    *t_max = t;
                    best = Some(t);
                }
            }
            false
        });
        best
    };
    let mut rays = Vec::new();
    let (mut zeros, mut hits) = ([0usize; 2], 0usize);
    for i in 0..4000u64 {
        let mut s = Sampler::new(31, i, 0);
        let prim = &g.prims[(s.next_1d() * g.prims.len() as f32) as usize % g.prims.len()];
        let b = padded_bounds(prim);
        let target = b.min + (b.max - b.min) * Vec3A::new(s.next_1d(), s.next_1d(), s.next_1d());
        let mut d = uniform_sphere(&mut s);
        // One or two axes, chosen at random, get a signed zero.
        let first = (s.next_1d() * 3.0) as usize % 3;
        let axes = if s.next_1d() < 0.5 {
            vec![first]
        } else {
            vec![first, (first + 1 + (s.next_1d() * 2.0) as usize % 2) % 3]
        };
        for &a in &axes {
            let negative = s.next_1d() < 0.5;
            d[a] = if negative { -0.0 } else { 0.0 };
            zeros[negative as usize] += 1;
        }
        let d = d / d.length();
        let o = target - (0.5 + 2.0 * s.next_1d()) * d;
        let t_max = if i % 5 == 0 { 1.0 } else { f32::INFINITY };
        rays.push(Ray { o, d, t_max });
    }
    assert!(
        zeros.iter().all(|&z| z > 1000),
        "both signs, often: {zeros:?}"
    );
    for (i, ray) in rays.iter().enumerate() {
        let slow = g.intersect_brute_force(ray);
        hits += slow.is_some() as usize;
        let fast = g.intersect(ray);
        assert_eq!(
            fast.map(|h| h.t),
            slow.map(|h| h.t),
            "four-wide, ray {i}: {ray:?}"
        );
        assert_eq!(
            g.occluded(ray),
            slow.is_some(),
            "occlusion, ray {i}: {ray:?}"
        );
        assert_eq!(
            binary_closest(ray),
            slow.map(|h| h.t),
            "binary, ray {i}: {ray:?}"
        );
    }
    assert!(
        hits > rays.len() / 2,
        "{hits} hits: the rays aim at primitives"
    );
    for (k, four) in rays.chunks_exact(4).enumerate() {
        let four: [Ray; 4] = four.try_into().unwrap();
        let got = g.intersect4(&four);
        for j in 0..4 {
            let slow = g.intersect_brute_force(&four[j]);
            assert_eq!(
                got[j].map(|h| h.t),
                slow.map(|h| h.t),
                "packet of 4, ray {}",
                4 * k + j
            );
        }
    }
    for (k, sixteen) in rays.chunks_exact(16).enumerate() {
        let sixteen: [Ray; 16] = sixteen.try_into().unwrap();
        let got = g.intersect16(&sixteen);
        for j in 0..16 {
            let slow = g.intersect_brute_force(&sixteen[j]);
            assert_eq!(
                got[j].map(|h| h.t),
                slow.map(|h| h.t),
                "packet of 16, ray {}",
                16 * k + j
            );
        }
    }
}

#[test]
fn empty_geometry_hits_nothing() {
    let g = Geometry::new(Vec::new());
    let r = Ray::new(Vec3A::ZERO, Vec3A::X);
    assert!(g.intersect(&r).is_none() && !g.occluded(&r));
    assert!(g.bounds().is_empty());
}

/// Points on a surface, found by shooting rays at it from outside.
fn surface_points(g: &Geometry, centre: Vec3A, radius: f32, n: usize) -> Vec<(SurfacePoint, u32)> {
    let mut out = Vec::new();
    for i in 0..n as u64 * 4 {
        let mut s = Sampler::new(3, i, 0);
        let o = centre + 3.0 * radius * uniform_sphere(&mut s);
        let target = centre + 0.8 * radius * uniform_box(&mut s, 1.0);
        let ray = Ray::new(o, (target - o).normalize());
        if let Some(hit) = g.intersect(&ray) {
            out.push((g.surface_point(&ray, &hit), hit.prim));
        }
        if out.len() == n {
            break;
        }
    }
    assert_eq!(out.len(), n);
    out
}

/// Rays spawned on a surface with [`Ray::spawn_from`] and the hit's error
/// bound never hit that surface
/// again at the start point. Every shape here is convex (or flat), so a ray
/// leaving on the outer side must hit nothing at all, and a ray entering
/// must hit another primitive (mesh) or the far side (sphere).
#[test]
fn spawned_rays_do_not_self_intersect() {
    let centre = Vec3A::new(10.0, 5.0, -3.0);
    let ico = Mesh::icosphere(3)
        .transformed(&(Transform::translate(centre.into()) * Transform::scale(Vec3::splat(2.0))));
    let cases: Vec<(Shape, f32)> = vec![
        (
            Shape::Sphere(Sphere {
                center: centre,
                radius: 2.0,
            }),
            2.0,
        ),
        (
            Shape::Sphere(Sphere {
                center: Vec3A::ZERO,
                radius: 0.01,
            }),
            0.01,
        ),
        (
            Shape::Quad(Quad {
                origin: centre - Vec3A::new(1.0, 1.0, 0.3),
                e1: Vec3A::new(2.0, 0.1, 0.0),
                e2: Vec3A::new(0.0, 2.0, 0.5),
            }),
            1.5,
        ),
        (Shape::Mesh(Arc::new(ico)), 2.0),
    ];
    for (case, (shape, radius)) in cases.into_iter().enumerate() {
        let c = match &shape {
            Shape::Sphere(s) => s.center,
            _ => centre,
        };
        let flat = matches!(shape, Shape::Quad(_));
        let g = Geometry::new(vec![shape]);
        for (k, (sp, prim)) in surface_points(&g, c, radius, 2000).into_iter().enumerate() {
            let mut s = Sampler::new(11, k as u64, case as u64);
            let d = uniform_sphere(&mut s);
            let outward = if flat { true } else { d.dot(sp.ng) > 0.0 };
            let end = RayEnd {
                p: sp.p,
                error: sp.p_error,
                n: sp.ng,
            };
            let hit = g.intersect(&Ray::spawn_from(end, d));
            if outward {
                assert!(hit.is_none(), "case {case}, point {k}: re-hit {hit:?}");
            } else if let Some(h) = hit {
                match case {
                    3 => assert_ne!(h.prim, prim, "case {case}, point {k}: own triangle"),
                    // The chord 2r·cos θ, with cos θ of a uniform direction
                    // > 1e-4 except with probability 1e-4 per ray.
                    _ => assert!(h.t > 1e-6 * radius, "case {case}, point {k}: t = {}", h.t),
                }
            } else {
                panic!("case {case}, point {k}: inward ray left a closed surface");
            }
        }
    }
}

/// A closed box of six quads (the Cornell box with a front wall) and the
/// same box as a triangle mesh: rays from inside aimed exactly at corners
/// and at points of the edges where two walls meet always hit a wall.
#[test]
fn closed_boxes_do_not_leak() {
    let cube = Shape::Mesh(Arc::new(Mesh::cube()));
    for (name, shapes) in [("quads", cornell_walls()), ("cube mesh", vec![cube])] {
        let g = Geometry::new(shapes);
        let mut targets = Vec::new();
        for i in 0..8 {
            targets.push(Vec3A::new(
                if i & 1 == 0 { -1.0 } else { 1.0 },
                if i & 2 == 0 { -1.0 } else { 1.0 },
                if i & 4 == 0 { -1.0 } else { 1.0 },
            ));
        }
        for k in 0..3000u64 {
            let mut s = Sampler::new(5, k, 0);
            // A random point on a random one of the 12 edges (and on the
            // faces' diagonals, where a cube mesh's two triangles meet).
            let e = (s.next_1d() * 12.0) as usize;
            let (axis, a, b) = (e / 4, e & 1, (e >> 1) & 1);
            let mut p = Vec3A::ZERO;
            p[axis] = 2.0 * s.next_1d() - 1.0;
            p[(axis + 1) % 3] = if a == 0 { -1.0 } else { 1.0 };
            p[(axis + 2) % 3] = if b == 0 { -1.0 } else { 1.0 };
            targets.push(p);
            let mut q = Vec3A::splat(2.0 * s.next_1d() - 1.0);
            q[axis] = if a == 0 { -1.0 } else { 1.0 };
            targets.push(q);
        }
        for (k, &target) in targets.iter().enumerate() {
            for j in 0..4u64 {
                let mut s = Sampler::new(6, k as u64, j);
                let o = uniform_box(&mut s, 0.95);
                let ray = Ray::new(o, (target - o).normalize());
                let hit = g.intersect(&ray);
                assert!(hit.is_some(), "{name}: ray from {o} to {target} escaped");
                let dist = (target - o).length();
                assert!((hit.unwrap().t - dist).abs() < 1e-4 * dist.max(1.0));
            }
        }
    }
}

#[test]
fn surface_points_are_sane() {
    let obj = "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n";
    let textured = Mesh::from_obj_str(obj, "wall.obj").unwrap();
    let ico = Mesh::icosphere(4).transformed(&Transform::translate(Vec3::new(0.0, 3.0, 0.0)));
    let shapes = vec![
        Shape::Sphere(Sphere {
            center: Vec3A::new(3.0, 0.0, 0.0),
            radius: 0.5,
        }),
        Shape::Quad(Quad {
            origin: Vec3A::new(-3.0, -0.5, -0.5),
            e1: Vec3A::new(0.0, 1.0, 0.0),
            e2: Vec3A::new(0.0, 0.0, 1.0),
        }),
        Shape::Mesh(Arc::new(textured)),
        Shape::Mesh(Arc::new(ico)),
    ];
    let g = Geometry::new(shapes);
    let centres = [
        Vec3A::new(3.0, 0.0, 0.0),
        Vec3A::new(-3.0, 0.0, 0.0),
        Vec3A::new(0.0, 0.0, -1.0),
        Vec3A::new(0.0, 3.0, 0.0),
    ];
    let mut seen = [0; 4];
    for i in 0..4000u64 {
        let mut s = Sampler::new(8, i, 0);
        let shape = (i % 4) as usize;
        let target = centres[shape]
            + uniform_box(&mut s, 0.4) * Vec3A::new(1.0, 1.0, if shape == 2 { 0.0 } else { 1.0 });
        let o = Vec3A::new(0.0, 0.0, 6.0) + uniform_box(&mut s, 0.5);
        let ray = Ray::new(o, (target - o).normalize());
        let Some(hit) = g.intersect(&ray) else {
            continue;
        };
        let sp = g.surface_point(&ray, &hit);
        assert!((sp.ng.length() - 1.0).abs() < 1e-5 && (sp.ns.length() - 1.0).abs() < 1e-5);
        assert!(sp.ns.dot(sp.ng) > 0.0);
        assert!(
            (0.0..=1.0).contains(&sp.uv.x) && (0.0..=1.0).contains(&sp.uv.y),
            "{sp:?}"
        );
        assert!((sp.p - ray.at(hit.t)).length() < 1e-4, "{sp:?}");
        seen[sp.shape as usize] += 1;
        match sp.shape {
            0 => {
                let r = sp.p - centres[0];
                assert!((r.length() - 0.5).abs() < 1e-6);
                assert!((sp.ng - r / 0.5).length() < 1e-5);
                // Latitude: v = θ/π with cos θ = n_y.
                assert!((sp.uv.y - sp.ng.y.clamp(-1.0, 1.0).acos() / PI).abs() < 1e-5);
            }
            1 => {
                assert_eq!(sp.ng, Vec3A::X);
                assert!((sp.uv - Vec2::new(sp.p.y + 0.5, sp.p.z + 0.5)).length() < 1e-5);
            }
            2 => {
                assert!((sp.ng - Vec3A::Z).length() < 1e-6);
                // uv = (x + 1, y + 1) / 2 from the file's texture coordinates.
                let expect = Vec2::new(sp.p.x + 1.0, sp.p.y + 1.0) * 0.5;
                assert!((sp.uv - expect).length() < 1e-5, "{sp:?}");
            }
            _ => {
                // Smooth normal ≈ radial direction; faceted ng within a few degrees.
                let radial = (sp.p - centres[3]).normalize();
                assert!((sp.ns - radial).length() < 1e-3, "{sp:?}");
                assert!(sp.ng.dot(radial) > 0.99);
            }
        }
    }
    assert!(seen.iter().all(|&c| c > 200), "{seen:?}");
}

/// The Cornell box's small box: cube → Mitsuba transform → world AABB as
/// in the reference (raytracer/tests/data/cornell_box_mitsuba.txt §4).
#[test]
fn transformed_cube_matches_mitsuba() {
    let t = Transform::translate(Vec3::new(0.335, -0.7, 0.38))
        * Transform::rotate(Vec3::Y, -17.0)
        * Transform::scale(Vec3::splat(0.3));
    let g = Geometry::new(vec![Shape::Mesh(Arc::new(Mesh::cube().transformed(&t)))]);
    let b = g.bounds();
    assert!(
        (b.min - Vec3A::new(-0.039603, -1.0, 0.005397))
            .abs()
            .max_element()
            < 1e-4
    );
    assert!(
        (b.max - Vec3A::new(0.709603, -0.4, 0.754603))
            .abs()
            .max_element()
            < 1e-4
    );
    let area = match &g.shapes()[0] {
        Shape::Mesh(m) => m.area(),
        _ => unreachable!(),
    };
    assert!((area - 2.16).abs() < 1e-4);
}

/// The binary tree (which the four-wide one is collapsed from) finds the
/// same closest hits as brute force.
#[test]
fn binary_bvh_matches_brute_force() {
    let g = Geometry::new(vec![Shape::Mesh(Arc::new(soup(5000, 0.05, 1)))]);
    let bounds: Vec<Aabb> = g.prims.iter().map(padded_bounds).collect();
    let bvh = Bvh::build(&bounds);
    for i in 0..500u64 {
        let mut s = Sampler::new(9, i, 0);
        let o = uniform_box(&mut s, 1.5);
        let ray = Ray::new(o, (uniform_box(&mut s, 1.0) - o).normalize());
        let mut best = None;
        bvh.traverse(ray.o, ray.d, ray.t_max, |first, count, t_max| {
            for k in first..first + count {
                let prim = bvh.order[k as usize];
                if let Some((t, _)) = g.prims[prim as usize].intersect(ray.o, ray.d, *t_max) {
                    *t_max = t;
                    best = Some(t);
                }
            }
            false
        });
        assert_eq!(best, g.intersect_brute_force(&ray).map(|h| h.t), "ray {i}");
    }
}

/// Packets give each ray exactly its single-ray hit, for coherent camera
/// rays and for random rays through a soup of triangles, spheres and quads.
#[test]
fn packets_match_single_rays() {
    let mut shapes = vec![
        Shape::Mesh(Arc::new(soup(3000, 0.1, 4))),
        Shape::Mesh(Arc::new(Mesh::icosphere(3))),
        Shape::Sphere(Sphere {
            center: Vec3A::new(0.5, 0.5, 0.0),
            radius: 0.3,
        }),
    ];
    shapes.extend(cornell_walls().into_iter().take(3));
    let g = Geometry::new(shapes);
    for i in 0..2000u64 {
        let mut s = Sampler::new(12, i, 0);
        let coherent = i % 2 == 0;
        let base = Vec3A::new(0.0, 0.0, 3.0) + uniform_box(&mut s, 0.5);
        let rays: [Ray; 4] = std::array::from_fn(|k| {
            if coherent {
                let d = Vec3A::new(s.next_1d() * 0.02 - 0.01, s.next_1d() * 0.02 - 0.01, 0.0)
                    + (uniform_box(&mut Sampler::new(13, i, 0), 0.6) - base).normalize();
                Ray {
                    o: base,
                    d: d.normalize(),
                    t_max: if k == 3 { 2.5 } else { f32::INFINITY },
                }
            } else {
                let o = uniform_box(&mut s, 1.5);
                Ray::new(o, uniform_sphere(&mut s))
            }
        });
        let packet = g.intersect4(&rays);
        for k in 0..4 {
            assert_eq!(packet[k], g.intersect(&rays[k]), "packet {i} ray {k}");
        }
        // Sixteen rays: these four, and three more fours shifted a little.
        let rays16: [Ray; 16] = std::array::from_fn(|k| {
            let mut r = rays[k % 4];
            r.o += Vec3A::splat(0.003 * (k / 4) as f32);
            r
        });
        let packet = g.intersect16(&rays16);
        for k in 0..16 {
            assert_eq!(
                packet[k],
                g.intersect(&rays16[k]),
                "packet {i} ray {k} of 16"
            );
        }
    }
}

/// Where a primary ray's time goes (run by hand with `--ignored --nocapture`):
/// traversal alone versus traversal with the primitive tests.
#[test]
#[ignore = "a measurement, not a test"]
fn profile_primary_rays() {
    let g = Geometry::new(vec![Shape::Mesh(Arc::new(Mesh::icosphere(6)))]);
    let t = 20f32.to_radians().tan();
    let s = |k: usize| (k as f32 + 0.5) / 1000.0 * 2.0 - 1.0;
    let rays: Vec<Ray> = (0..1_000_000)
        .map(|k| {
            Ray::new(
                Vec3A::new(0.0, 0.0, 3.0),
                Vec3A::new(s(k % 1000) * t, -s(k / 1000) * t, -1.0).normalize(),
            )
        })
        .collect();
    let (mut leaves, mut tris) = (0usize, 0usize);
    let mut best = [f64::INFINITY; 2];
    for _ in 0..5 {
        let t0 = std::time::Instant::now();
        for r in &rays {
            g.bvh.traverse(r.o, r.d, r.t_max, |_, c, _| {
                leaves += 1;
                tris += c as usize;
                false
            });
        }
        best[0] = best[0].min(t0.elapsed().as_secs_f64());
        let t0 = std::time::Instant::now();
        let hits = rays.iter().filter(|r| g.intersect(r).is_some()).count();
        best[1] = best[1].min(t0.elapsed().as_secs_f64());
        assert!(hits > 700_000);
    }
    println!(
        "traversal only (no culling by t): {:.0} ns/ray, {:.2} leaves and {:.2} primitives per ray; closest hit {:.0} ns/ray",
        best[0] * 1e3,
        leaves as f64 / 5e6,
        tris as f64 / 5e6,
        best[1] * 1e3
    );
}
