//! Unit tests of `light/environment.rs`.

use super::light_test_stats::assert_matches;
use raytracer::light::environment::*;
use raytracer::math::{Color, RayPdf, Vec2, Vec3A, luminance};
use raytracer::sampling::Sampler;
use raytracer::sampling::warp::uniform_sphere;
use std::f64::consts::PI as PI64;
use std::sync::Arc;

/// An 8 × 4 map, dim everywhere (grey 0.2) but for one bright cell (50)
/// in row 1, column 5.
fn bright_cell_map() -> Arc<EnvironmentMap> {
    let mut pixels = vec![Color::splat(0.2); 32];
    pixels[8 + 5] = Color::new(50.0, 40.0, 30.0);
    Arc::new(EnvironmentMap {
        width: 8,
        height: 4,
        pixels,
    })
}

#[test]
fn lat_long_convention() {
    let close = |a: Vec2, b: Vec2| assert!((a - b).length() < 1e-5, "{a} vs {b}");
    close(direction_to_uv(-Vec3A::Z), Vec2::new(0.0, 0.5));
    close(direction_to_uv(Vec3A::X), Vec2::new(0.25, 0.5));
    close(direction_to_uv(Vec3A::Z), Vec2::new(0.5, 0.5));
    close(direction_to_uv(-Vec3A::X), Vec2::new(0.75, 0.5));
    assert!(
        direction_to_uv(Vec3A::Y).y.abs() < 1e-6,
        "up is the top row"
    );
    assert!((direction_to_uv(-Vec3A::Y).y - 1.0).abs() < 1e-6);
    for i in 0..200 {
        let d = uniform_sphere(Sampler::new(1, i, 0).next_2d());
        assert!((uv_to_direction(direction_to_uv(d)) - d).length() < 1e-4);
    }
    let m = bright_cell_map();
    assert_eq!(m.lookup(5.5 / 8.0, 1.5 / 4.0).x, 50.0);
    assert_eq!(m.lookup(5.5 / 8.0 + 1.0, 1.5 / 4.0).x, 50.0, "u wraps");
    assert_eq!(m.lookup(0.0, 1.0).x, 0.2, "v = 1 is the bottom row");
}

/// On the bright-cell map: (a) `pdf_li_w` agrees with every sample;
/// (b) mean(1/p_ω) = 4π (every cell has light, so the whole sphere is
/// covered) and mean(L/p_ω) = ∫ L dω = Σ L_ij ΔΩ_ij (importance sampling
/// is unbiased); both 2^16 samples, 5 standard errors; (c) chi-square:
/// the cells are hit with probabilities `lum_ij sin θ_j / Σ` (31 degrees
/// of freedom; the 1e-6 upper quantile is ≈ 84, Wilson–Hilferty).
#[test]
fn map_sampling_follows_brightness() {
    let env = EnvironmentLight::new(Color::splat(2.0), Some(bright_cell_map()));
    let map = bright_cell_map();
    let n = 1u64 << 16;
    let mut inv = Vec::new();
    let mut flux = Vec::new();
    let mut counts = [0u64; 32];
    for i in 0..n {
        let p = Vec3A::new(0.3, -0.2, 0.1);
        let s = env.sample_li(p, Sampler::new(70, i, 0).next_2d()).unwrap();
        let pdf = env.pdf_li_w(s.wi);
        assert!(
            (pdf - s.pdf_w).abs() <= 1e-3 * s.pdf_w,
            "{pdf} vs {}",
            s.pdf_w
        );
        assert!(s.dist.is_infinite() && s.n == Vec3A::ZERO);
        assert!((s.li - env.environment_radiance(s.wi)).length() < 1e-6);
        inv.push(1.0 / s.pdf_w as f64);
        flux.push((s.li.x / s.pdf_w) as f64);
        let uv = direction_to_uv(s.wi);
        let cell = ((uv.y * 4.0) as usize).min(3) * 8 + ((uv.x * 8.0) as usize).min(7);
        counts[cell] += 1;
    }
    assert_matches("env solid angle", &inv, 4.0 * PI64, 0.02);
    let mut integral = 0.0f64;
    let mut weights = [0.0f64; 32];
    for j in 0..4 {
        let (t0, t1) = (PI64 * j as f64 / 4.0, PI64 * (j + 1) as f64 / 4.0);
        for i in 0..8 {
            let c = map.pixels[j * 8 + i];
            integral += 2.0 * c.x as f64 * (2.0 * PI64 / 8.0) * (t0.cos() - t1.cos());
            weights[j * 8 + i] = luminance(c) as f64 * (0.5 * (t0 + t1)).sin();
        }
    }
    assert_matches("∫ L dω of the map", &flux, integral, 0.02);
    assert!((env.power().x as f64 - PI64 * integral).abs() < 1e-4 * PI64 * integral);
    let total: f64 = weights.iter().sum();
    let chi2: f64 = (0..32)
        .map(|c| {
            let expected = n as f64 * weights[c] / total;
            (counts[c] as f64 - expected).powi(2) / expected
        })
        .sum();
    eprintln!(
        "env map chi-square {chi2:.2} (31 dof); bright cell hits {}",
        counts[13]
    );
    assert!(chi2 < 84.0, "chi-square {chi2}");
    assert!(
        counts[13] as f64 > 0.5 * n as f64,
        "the bright cell dominates"
    );
}

/// Constant environment: uniform directions of density 1/(4π), and the
/// emission: rays start on the disk beyond the bounding sphere, head into
/// it (their closest approach to the centre is at most r), `pdf_le`
/// agrees, and `mean(le / (p_A p_ω))` is the flux π r² ∫ L dω = power()
/// (constant: exact; map: 2^16 samples, 5 standard errors).
#[test]
fn emission_enters_the_scene_and_carries_the_power() {
    let center = Vec3A::new(1.0, 2.0, -1.0);
    let r = 3.0;
    for map in [None, Some(bright_cell_map())] {
        let mut env = EnvironmentLight::new(Color::new(0.5, 1.0, 1.5), map.clone());
        env.set_scene_bounds(center, r);
        let light = raytracer::light::Light::Environment(env.clone());
        let n = 1u64 << 16;
        let mut flux = Vec::new();
        for i in 0..n {
            let mut smp = Sampler::new(80, i, 0);
            let e = env.sample_le(smp.next_2d(), smp.next_2d()).unwrap();
            let to_c = center - e.ray.o;
            let along = to_c.dot(e.ray.d);
            assert!(along > 0.0, "the ray heads into the scene");
            assert!((to_c - along * e.ray.d).length() <= r * (1.0 + 1e-4));
            assert!((e.ray.o - center).length() >= r * (1.0 - 1e-4));
            assert!((e.n - e.ray.d).length() < 1e-6);
            let RayPdf { pdf_a, pdf_w } = env.pdf_le(e.ray.d);
            assert_eq!(RayPdf { pdf_a, pdf_w }, light.pdf_le(e.ray.o, e.n, e.ray.d));
            assert!((pdf_a - e.pdf_a).abs() <= 1e-5 * e.pdf_a);
            assert!((pdf_w - e.pdf_w).abs() <= 1e-3 * e.pdf_w);
            assert_eq!(e.le, env.environment_radiance(-e.ray.d));
            flux.push((e.le.y / (e.pdf_a * e.pdf_w)) as f64);
        }
        assert_matches("environment flux", &flux, env.power().y as f64, 0.02);
        if map.is_none() {
            let expect = PI64 * 9.0 * 4.0 * PI64;
            assert!((env.power().y as f64 - expect).abs() < 1e-4 * expect);
        }
    }
}

#[test]
fn load_reports_missing_file() {
    let path = std::env::temp_dir().join("no_such_dir_light_test/missing_sky.exr");
    let err = EnvironmentMap::load(&path).unwrap_err();
    assert!(err.contains("missing_sky.exr"), "{err}");
}

/// A Radiance HDR map (the format of public HDRI libraries) loads with
/// its values (RGBE holds 1, 0.5, 2 and 0.25 exactly), top row first;
/// a header claiming 40 000 × 40 000 pixels is refused before pixels are
/// read; a truncated file is named in one line.
#[test]
fn load_reads_radiance_hdr_and_refuses_what_it_must() {
    let dir = std::env::temp_dir().join(format!("light_hdr_test_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("tiny_sky.hdr");
    let values = [
        [1.0f32, 0.5, 2.0],
        [0.25, 1.0, 0.5],
        [2.0, 2.0, 2.0],
        [0.5, 0.25, 1.0],
    ];
    let px: Vec<image::Rgb<f32>> = values.iter().map(|v| image::Rgb(*v)).collect();
    image::codecs::hdr::HdrEncoder::new(std::fs::File::create(&path).unwrap())
        .encode(&px, 2, 2)
        .unwrap();
    let m = EnvironmentMap::load(&path).unwrap();
    assert_eq!((m.width, m.height), (2, 2));
    for (p, v) in m.pixels.iter().zip(values) {
        assert_eq!(*p, Color::from(v));
    }
    let huge = dir.join("huge.hdr");
    std::fs::write(
        &huge,
        b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 40000 +X 40000\n",
    )
    .unwrap();
    let err = EnvironmentMap::load(&huge).unwrap_err();
    assert!(
        err.contains("huge.hdr") && err.contains("40000×40000"),
        "{err}"
    );
    let bytes = std::fs::read(&path).unwrap();
    let cut = dir.join("cut.hdr");
    std::fs::write(&cut, &bytes[..bytes.len() - 5]).unwrap();
    let err = EnvironmentMap::load(&cut).unwrap_err();
    assert!(err.contains("cut.hdr") && !err.contains('\n'), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

/// Radiance is never negative: a map with a negative pixel is refused,
/// naming the pixel, as a NaN pixel is (it used to be clamped silently).
#[test]
fn load_refuses_negative_pixels() {
    let dir = std::env::temp_dir().join(format!("light_neg_exr_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("negative.exr");
    exr::prelude::write_rgb_file(&path, 2, 1, |x, _| {
        if x == 1 {
            (1.0f32, -0.5f32, 1.0f32)
        } else {
            (1.0, 1.0, 1.0)
        }
    })
    .unwrap();
    let err = EnvironmentMap::load(&path).unwrap_err();
    std::fs::remove_dir_all(&dir).ok();
    assert!(
        err.contains("negative.exr") && err.contains("pixel (1, 0) is negative"),
        "{err}"
    );
}

/// Writes a 4 × 2 RGB EXR with the exr crate and loads it back: same
/// size, same pixels, top row first.
#[test]
fn load_round_trips_an_exr_file() {
    let dir = std::env::temp_dir().join(format!("light_exr_test_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("tiny_sky.exr");
    let value = |x: usize, y: usize| (x as f32 + 0.5, y as f32 * 10.0, 0.25 * x as f32);
    exr::prelude::write_rgb_file(&path, 4, 2, value).unwrap();
    let m = EnvironmentMap::load(&path).unwrap();
    std::fs::remove_dir_all(&dir).ok();
    assert_eq!((m.width, m.height, m.pixels.len()), (4, 2, 8));
    for y in 0..2 {
        for x in 0..4 {
            let (r, g, b) = value(x, y);
            assert_eq!(m.pixels[y * 4 + x], Color::new(r, g, b), "pixel ({x}, {y})");
        }
    }
    // Pixel (3, 0) is the top row: directions near +y, at u ∈ [3/4, 1).
    let up_ish = uv_to_direction(Vec2::new(0.8, 0.2));
    let env = EnvironmentLight::new(Color::ONE, Some(Arc::new(m)));
    assert_eq!(env.environment_radiance(up_ish), Color::new(3.5, 0.0, 0.75));
}

/// A file whose header claims 100000 × 100000 pixels is refused before
/// 120 GB of pixels are allocated.
#[test]
fn a_map_declaring_too_many_pixels_is_refused() {
    let dir = std::env::temp_dir().join(format!("light_huge_exr_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("huge.exr");
    exr::prelude::write_rgb_file(&path, 2, 1, |_, _| (1.0f32, 1.0f32, 1.0f32)).unwrap();
    let mut bytes = std::fs::read(&path).unwrap();
    // dataWindow: name, type, size (16), then xMin, yMin, xMax, yMax.
    let key = b"dataWindow\0box2i\0";
    let at = bytes.windows(key.len()).position(|w| w == key).unwrap() + key.len() + 4;
    for (i, v) in [0i32, 0, 99_999, 99_999].iter().enumerate() {
        bytes[at + 4 * i..at + 4 * i + 4].copy_from_slice(&v.to_le_bytes());
    }
    std::fs::write(&path, bytes).unwrap();
    let err = EnvironmentMap::load(&path).unwrap_err();
    std::fs::remove_dir_all(&dir).ok();
    assert!(err.contains("huge.exr"), "{err}");
    assert!(err.contains("declares 100000×100000"), "{err}");
}

/// A text file with an .exr name gives an error naming the file.
#[test]
fn load_reports_invalid_file() {
    let dir = std::env::temp_dir().join(format!("light_bad_exr_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("not_really.exr");
    std::fs::write(&path, "hello").unwrap();
    let err = EnvironmentMap::load(&path).unwrap_err();
    std::fs::remove_dir_all(&dir).ok();
    assert!(err.contains("not_really.exr"), "{err}");
}
