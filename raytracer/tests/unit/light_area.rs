//! Unit tests of `light/area.rs`.

use super::light_test_stats::assert_matches;
use raytracer::geometry::{Quad, Sphere};
use raytracer::light::LightSample;
use raytracer::light::area::*;
use raytracer::math::{Color, RayPdf, Vec3A};
use raytracer::sampling::Sampler;

/// A 1 m × 1 m quad at height 2 facing down (`e1 × e2 = x × z = −y`).
fn ceiling_quad() -> Quad {
    Quad {
        origin: Vec3A::new(-0.5, 2.0, -0.5),
        e1: Vec3A::X,
        e2: Vec3A::Z,
    }
}

fn light(shape: AreaShape, two_sided: bool) -> AreaLight {
    AreaLight {
        shape,
        radiance: Color::new(1.0, 2.0, 3.0),
        two_sided,
    }
}

fn corners(q: &Quad) -> [Vec3A; 4] {
    [
        q.origin,
        q.origin + q.e1,
        q.origin + q.e1 + q.e2,
        q.origin + q.e2,
    ]
}

/// Solid angle of a triangle seen from `p` (Van Oosterom and Strackee
/// 1983): `tan(Ω/2) = |R1·(R2×R3)| / (r1r2r3 + (R1·R2)r3 + (R1·R3)r2 + (R2·R3)r1)`.
fn triangle_solid_angle(p: Vec3A, a: Vec3A, b: Vec3A, c: Vec3A) -> f64 {
    let v = |x: Vec3A| glam::DVec3::new(x.x as f64, x.y as f64, x.z as f64);
    let (r1, r2, r3) = (v(a - p), v(b - p), v(c - p));
    let (l1, l2, l3) = (r1.length(), r2.length(), r3.length());
    let num = r1.dot(r2.cross(r3)).abs();
    let den = l1 * l2 * l3 + r1.dot(r2) * l3 + r1.dot(r3) * l2 + r2.dot(r3) * l1;
    2.0 * num.atan2(den)
}

fn quad_solid_angle(p: Vec3A, q: &Quad) -> f64 {
    let c = corners(q);
    triangle_solid_angle(p, c[0], c[1], c[2]) + triangle_solid_angle(p, c[0], c[2], c[3])
}

/// Irradiance at `p` (normal `n`) from a Lambertian polygon of radiance
/// `l` lying wholly above p's tangent plane, by Lambert's contour
/// formula: `E = (L/2) |Σ_i Θ_i (n · Γ_i)|`, with `Θ_i` the angle between
/// the directions to vertices i and i+1 and `Γ_i` the unit normal of the
/// plane through p and that edge.
fn lambert_irradiance(p: Vec3A, n: Vec3A, poly: &[Vec3A], l: f64) -> f64 {
    let v = |x: Vec3A| glam::DVec3::new(x.x as f64, x.y as f64, x.z as f64);
    let n = v(n);
    let mut sum = 0.0;
    for i in 0..poly.len() {
        let a = v(poly[i] - p).normalize();
        let b = v(poly[(i + 1) % poly.len()] - p).normalize();
        let theta = a.dot(b).clamp(-1.0, 1.0).acos();
        sum += theta * n.dot(a.cross(b).normalize());
    }
    0.5 * l * sum.abs()
}

/// Runs `sample_li` from `p` with `n` samples: checks every sample
/// against `pdf_li_w` (relative 1e-3) and returns the samples.
fn samples(l: &AreaLight, p: Vec3A, n: u64, seed: u64) -> Vec<LightSample> {
    let mut out = Vec::new();
    for i in 0..n {
        if let Some(s) = l.sample_li(p, Sampler::new(seed, i, 0).next_2d()) {
            let pdf = l.pdf_li_w(p, s.p, s.n, s.wi);
            assert!(
                (pdf - s.pdf_w).abs() <= 1e-3 * s.pdf_w,
                "pdf_li_w {pdf} vs sample pdf {} from {p}",
                s.pdf_w
            );
            assert!((s.wi.length() - 1.0).abs() < 1e-5);
            assert!(((s.p - p).length() - s.dist).abs() < 1e-4 * s.dist);
            assert!(!s.is_delta && s.li == l.radiance);
            out.push(s);
        }
    }
    out
}

/// (a) pdf_li_w agrees with every sample; (b) mean(1/p_ω) is the quad's
/// exact solid angle (2^16 samples, 5 standard errors, see assert_matches).
#[test]
fn quad_sampling_matches_pdf_and_solid_angle() {
    let q = ceiling_quad();
    let l = light(AreaShape::Quad(q), false);
    for (k, p) in [
        Vec3A::ZERO,
        Vec3A::new(1.5, 0.5, 0.3),
        Vec3A::new(0.2, 1.8, 0.1),
        Vec3A::new(-3.0, 1.0, 2.0),
    ]
    .into_iter()
    .enumerate()
    {
        let n = 1 << 16;
        let s = samples(&l, p, n, 10 + k as u64);
        assert_eq!(
            s.len() as u64,
            n,
            "a receiver in front always gets a sample"
        );
        let inv: Vec<f64> = s.iter().map(|s| 1.0 / s.pdf_w as f64).collect();
        assert_matches(
            &format!("solid angle of the quad from {p}"),
            &inv,
            quad_solid_angle(p, &q),
            0.02,
        );
    }
}

/// Sphere seen from outside (cone sampling): samples lie on the sphere,
/// face the receiver and stay in the cone; mean(1/p_ω) is the cap's solid
/// angle `2π(1 − cos θ_max)`, and the irradiance on a receiver facing
/// the centre is `E = π L sin²θ_max` (2^16 samples, 5 standard errors).
/// Seen from inside (a two-sided sphere, sampled by area), the solid
/// angle is 4π.
#[test]
fn sphere_sampling_matches_pdf_solid_angle_and_irradiance() {
    let s = Sphere {
        center: Vec3A::new(0.0, 1.0, 0.0),
        radius: 0.5,
    };
    let l = light(AreaShape::Sphere(s), false);
    for (k, p) in [
        Vec3A::ZERO,
        Vec3A::new(0.3, 1.2, 0.45),
        Vec3A::new(2.0, -1.0, 3.0),
        Vec3A::new(0.0, 1.0, 40.0),
    ]
    .into_iter()
    .enumerate()
    {
        let n = 1 << 16;
        let smp = samples(&l, p, n, 20 + k as u64);
        assert_eq!(smp.len() as u64, n);
        let dc = (s.center - p).length() as f64;
        let sin2 = (s.radius as f64 / dc).powi(2);
        let cos_max = (1.0 - sin2).sqrt();
        let axis = (s.center - p).normalize();
        for x in &smp {
            assert!(((x.p - s.center).length() - s.radius).abs() < 1e-4);
            assert!(x.n.dot(x.wi) <= 1e-4, "the sampled point faces p");
            assert!(x.wi.dot(axis) as f64 >= cos_max - 1e-5, "inside the cone");
        }
        let inv: Vec<f64> = smp.iter().map(|s| 1.0 / s.pdf_w as f64).collect();
        let cap = 2.0 * std::f64::consts::PI * sin2 / (1.0 + cos_max);
        assert_matches(&format!("cone from {p}"), &inv, cap, 0.02);
        let e: Vec<f64> = smp
            .iter()
            .map(|s| (s.li.x * s.wi.dot(axis) / s.pdf_w) as f64)
            .collect();
        let exact = std::f64::consts::PI * sin2;
        assert_matches(&format!("sphere irradiance at {p}"), &e, exact, 0.02);
    }
    // Inside: a one-sided sphere shows its back, a two-sided one covers 4π.
    let inside = Vec3A::new(0.1, 1.2, -0.05);
    assert!(samples(&l, inside, 256, 30).is_empty());
    let l2 = light(AreaShape::Sphere(s), true);
    let smp = samples(&l2, inside, 1 << 16, 31);
    assert_eq!(smp.len(), 1 << 16);
    let inv: Vec<f64> = smp.iter().map(|s| 1.0 / s.pdf_w as f64).collect();
    assert_matches("sphere from inside", &inv, 4.0 * std::f64::consts::PI, 0.02);
}

/// Seen from outside, a sphere is sampled in the cone of the cap the
/// receiver sees: `pdf_li_w` of a point off that cap is 0, also for a
/// two-sided sphere whose far side faces the receiver from inside (it
/// used to return the cone's density for any point, right only because
/// a ray cannot reach the far side through the sphere). Points of the
/// cap keep the cone's density.
#[test]
fn sphere_pdf_is_zero_off_the_visible_cap() {
    let s = Sphere {
        center: Vec3A::new(0.0, 1.0, 0.0),
        radius: 0.5,
    };
    for two_sided in [false, true] {
        let l = light(AreaShape::Sphere(s), two_sided);
        let p = Vec3A::new(0.4, -1.0, 1.5);
        for smp in samples(&l, p, 256, 70) {
            let far = s.center - (smp.p - s.center);
            let n = (far - s.center).normalize();
            let wi = (far - p).normalize();
            assert_eq!(l.pdf_li_w(p, far, n, wi), 0.0, "far side {far}");
            assert_eq!(l.pdf_li_w(p, smp.p, smp.n, smp.wi), smp.pdf_w);
        }
    }
}

/// Next event estimation `mean(L cos θ / p_ω)` against Lambert's exact
/// irradiance, for receivers facing up and tilted (the quad stays above
/// their tangent planes). 2^16 samples, 5 standard errors.
#[test]
fn quad_irradiance_matches_lambert_formula() {
    let q = ceiling_quad();
    let l = light(AreaShape::Quad(q), false);
    let cases = [
        (Vec3A::ZERO, Vec3A::Y),
        (Vec3A::new(0.7, 1.0, -0.2), Vec3A::Y),
        (
            Vec3A::new(0.0, 0.5, 0.0),
            Vec3A::new(0.3, 1.0, 0.2).normalize(),
        ),
        (
            Vec3A::new(2.0, 1.0, 0.0),
            Vec3A::new(-1.0, 0.5, 0.0).normalize(),
        ),
    ];
    for (k, (p, n)) in cases.into_iter().enumerate() {
        assert!(corners(&q).iter().all(|c| (*c - p).dot(n) > 0.0));
        let e: Vec<f64> = samples(&l, p, 1 << 16, 40 + k as u64)
            .iter()
            .map(|s| (s.li.y * s.wi.dot(n).max(0.0) / s.pdf_w) as f64)
            .collect();
        let exact = lambert_irradiance(p, n, &corners(&q), l.radiance.y as f64);
        assert_matches(&format!("irradiance at {p}, n = {n}"), &e, exact, 0.02);
    }
}

/// A one-sided light gives nothing behind it: no samples, zero pdf,
/// zero `L_e`. A two-sided one lights both sides equally (mirror points
/// have the same irradiance: both estimates within 5 combined standard
/// errors of the exact value).
#[test]
fn one_sided_gives_nothing_behind_two_sided_does() {
    let q = ceiling_quad();
    let n = q.e1.cross(q.e2).normalize();
    let one = light(AreaShape::Quad(q), false);
    let two = light(AreaShape::Quad(q), true);
    let behind = Vec3A::new(0.1, 3.0, 0.2);
    assert!(samples(&one, behind, 1024, 50).is_empty());
    let on_light = Vec3A::new(0.0, 2.0, 0.0);
    let wi = (on_light - behind).normalize();
    assert_eq!(one.pdf_li_w(behind, on_light, n, wi), 0.0);
    assert_eq!(one.le(n, -wi), Color::ZERO);
    assert_eq!(one.le(n, wi), one.radiance);
    assert_eq!(two.le(n, -wi), two.radiance);
    assert!(two.pdf_li_w(behind, on_light, n, wi) > 0.0);
    let mirror = Vec3A::new(0.1, 1.0, 0.2);
    for (p, up) in [(behind, -Vec3A::Y), (mirror, Vec3A::Y)] {
        let e: Vec<f64> = samples(&two, p, 1 << 16, 51)
            .iter()
            .map(|s| (s.li.x * s.wi.dot(up).max(0.0) / s.pdf_w) as f64)
            .collect();
        let exact = lambert_irradiance(p, up, &corners(&q), two.radiance.x as f64);
        assert_matches(&format!("two-sided at {p}"), &e, exact, 0.02);
    }
}

/// Flux by light tracing's estimator `L_e |cos θ| / (p_A p_ω)` equals
/// `π A L` per side and `power()`; `pdf_le` agrees with each emission,
/// whose point lies on the light's surface and whose ray leaves it on an
/// emitting side. With
/// cosine sampling the estimator is constant (rounding tolerance only);
/// a two-sided light must pick each side half the time (2^14 samples,
/// std. error 0.0039, tolerance 0.03 > 7 σ: false failure < 1e-11).
#[test]
fn emitted_power_matches() {
    let shapes = [
        AreaShape::Quad(ceiling_quad()),
        AreaShape::Sphere(Sphere {
            center: Vec3A::new(1.0, 0.0, -1.0),
            radius: 0.3,
        }),
    ];
    for shape in shapes {
        for two_sided in [false, true] {
            let l = light(shape, two_sided);
            let n = 1 << 14;
            let mut flux = Vec::new();
            let mut front = 0;
            for i in 0..n {
                let mut smp = Sampler::new(60, i, 0);
                let u_pos = smp.next_2d();
                let e = l.sample_le(u_pos, smp.next_2d()).unwrap();
                let RayPdf { pdf_a, pdf_w } = l.pdf_le(e.p, e.n, e.ray.d);
                // The vertex on the surface (light tracing once stored
                // the offset origin: the lamp moved by the offset), the
                // ray's origin just off it, on the side it leaves to.
                assert_eq!(l.shape.sample_area(u_pos).0, e.p);
                let side = (e.ray.o - e.p).dot(e.n) * e.ray.d.dot(e.n);
                assert!(e.ray.o != e.p && side > 0.0, "{e:?}");
                assert!((pdf_a - e.pdf_a).abs() <= 1e-5 * e.pdf_a);
                assert!((pdf_w - e.pdf_w).abs() <= 1e-3 * e.pdf_w);
                let cos = e.n.dot(e.ray.d);
                if cos > 0.0 {
                    front += 1;
                }
                assert!(two_sided || cos > 0.0, "a one-sided light emits in front");
                assert!(l.le(e.n, e.ray.d) == e.le && e.le == l.radiance);
                flux.push((e.le.z * cos.abs() / (e.pdf_a * e.pdf_w)) as f64);
            }
            let exact = l.radiance.z as f64
                * shape.area() as f64
                * std::f64::consts::PI
                * if two_sided { 2.0 } else { 1.0 };
            assert_matches("emitted flux", &flux, exact, 0.02);
            assert!((l.power().z as f64 - exact).abs() < 1e-4 * exact);
            let frac = front as f64 / n as f64;
            let expect = if two_sided { 0.5 } else { 1.0 };
            assert!((frac - expect).abs() < 0.03, "front fraction {frac}");
        }
    }
}
