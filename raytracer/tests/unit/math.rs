//! Unit tests of `math.rs`.

use glam::Vec3A;
use raytracer::math::*;

#[test]
fn offset_origin_moves_to_the_side_of_the_direction() {
    for &p in &[
        Vec3A::new(0.3, -1.0, 0.2),
        Vec3A::new(100.0, 2000.0, -3.0),
        Vec3A::ZERO,
    ] {
        let n = Vec3A::Y;
        let e = gamma(4) * p.abs();
        let up = offset_ray_origin(p, e, n, Vec3A::Y);
        let down = offset_ray_origin(p, e, n, -Vec3A::Y);
        assert!(up.y > p.y && down.y < p.y, "{p} -> {up} / {down}");
        // Tiny compared with the scale of the point.
        assert!((up - p).length() <= 1e-3 * (1.0 + p.abs().max_element()));
    }
}

/// A point with a coordinate of `-0.0` is pushed off along `-x`: the
/// offset used to add ulps to the float's bits, and `-0.0`'s bits
/// (`i32::MIN`) plus a negative offset overflowed — "attempt to add with
/// overflow" in dev and test builds (OBJ files write `-0.000000`). Every
/// sign of zero, either side, every axis.
#[test]
fn offset_of_signed_zero_coordinates_does_not_overflow() {
    for z in [0.0f32, -0.0] {
        for axis in [Vec3A::X, Vec3A::Y, Vec3A::Z] {
            for side in [1.0, -1.0] {
                let n = side * axis;
                for p in [
                    Vec3A::splat(z),
                    Vec3A::new(z, 1.0, 0.0),
                    Vec3A::new(z, z, -2.0),
                ] {
                    let moved = offset_ray_origin(p, gamma(4) * p.abs(), n, n);
                    assert!(moved.is_finite());
                    assert!((moved - p).dot(n) > 0.0, "{p} along {n}: {moved}");
                }
            }
        }
    }
    let q = offset_ray_origin(
        Vec3A::new(-0.0, 1.0, 0.0),
        Vec3A::ZERO,
        -Vec3A::X,
        -Vec3A::X,
    );
    assert!(q.x < 0.0 && q.y == 1.0);
}

/// The offset is the same fraction of the scene at every scale, up to
/// the granularity of floats (it is a few ulps of the coordinate, and an
/// ulp is between 2⁻²⁴ and 2⁻²³ of it: within a factor 2): a point of a
/// 2-metre box and the same point of the box scaled by 10⁻³ or 10³, and
/// the scaled box's 1 cm lamp gap stays far wider than the offset (it
/// was not: 1.5e-5 absolute below 1/32).
#[test]
fn offset_scales_with_the_scene() {
    let p = Vec3A::new(0.13, 0.999, -0.4);
    let off = |p: Vec3A| Ray::spawn(p, -Vec3A::Y, -Vec3A::Y).o;
    let base = (off(p) - p).length() / 0.999;
    for scale in [1e-3f32, 1e3, 1.0 / 1024.0] {
        let q = p * scale;
        let moved = (off(q) - q).length() / (0.999 * scale);
        assert!(
            (0.5..=2.0).contains(&(moved / base)),
            "scale {scale}: {moved} vs {base}"
        );
        // Below 1% of the (scaled) 1 cm gap between lamp and ceiling.
        assert!(
            moved * 0.999 * scale < 0.01 * (0.01 * scale),
            "the lamp gap"
        );
    }
}

/// The shadow ray ends exactly at the target pushed off its surface, by
/// the offset of the coordinates' magnitude (the ray used to stop 1e-4 of
/// its length short as well: 0.1 m over 1 km, where the offset is 3 cm).
#[test]
fn spawn_to_ends_at_the_offset_target() {
    let r = Ray::spawn_to(Vec3A::ZERO, Vec3A::Y, Vec3A::new(0.0, 1.0, 0.0), -Vec3A::Y);
    assert!(r.t_max < 1.0 && r.t_max > 1.0 - 1e-4);
    assert!((r.d - Vec3A::Y).length() < 1e-6);
    let far = Vec3A::new(0.0, 1000.0, 0.0);
    let r = Ray::spawn_to(Vec3A::ZERO, Vec3A::Y, far, -Vec3A::Y);
    let end = r.at(r.t_max).y;
    assert!(
        end < 1000.0 && end > 1000.0 - 2.0 * ray_offset(1000.0),
        "{end}"
    );
    assert!(1000.0 - end < 0.04, "{end}");
    // To a point light (no normal): exactly there.
    let r = Ray::spawn_to(Vec3A::ZERO, Vec3A::Y, far, Vec3A::ZERO);
    assert_eq!(r.o + r.d * r.t_max, far);
}
