//! Environment light: radiance arriving from infinitely far away.
//!
//! Lecture topic: `L_e` at infinity. A ray that escapes the scene in the
//! direction `d` sees `L_env(d)`; next event estimation samples `d` in
//! proportion to the map's brightness, and light tracing starts rays on a
//! disk outside the scene (pbrt-v4's infinite lights are the model).
//!
//! # Lat-long convention
//!
//! `+y` is up. A unit direction `d` has the polar angle `θ = acos(d.y) ∈ [0, π]`
//! and the azimuth `φ = atan2(d.x, −d.z)` wrapped to `[0, 2π)`; its map
//! coordinates are `u = φ / 2π`, `v = θ / π`. So `u = 0` looks along `−z`,
//! `u = 1/4` along `+x`, `u = 1/2` along `+z`; the top row of the map
//! (`v = 0`) is straight up. Inversely
//! `d = (sin θ sin φ, cos θ, −sin θ cos φ)`.
//!
//! # Densities
//!
//! With `φ = 2πu`, `θ = πv`, the solid angle is `dω = sin θ dθ dφ =
//! 2π² sin θ du dv`, so a density `p(u, v)` on the unit square becomes
//! `p_ω = p(u, v) / (2π² sin θ)`. The map is sampled by the piecewise-constant
//! [`Distribution2D`] over its pixels with weights `luminance · sin θ` (the
//! `sin θ` makes a pixel's probability follow its solid angle, so the rows near
//! the poles, which cover little of the sphere, are rarely chosen).
//! The map is looked up by nearest pixel: the radiance is then constant where
//! the density is, so no pixel with light can have zero density.

use std::path::Path;
use std::sync::Arc;

use crate::frame::Frame;
use crate::light::{Emission, LightSample};
use crate::math::{Color, INV_2PI, INV_4PI, INV_PI, PI, Ray, RayPdf, Vec2, Vec3A, luminance};
use crate::sampling::Distribution2D;
use crate::sampling::warp::{concentric_disk, uniform_sphere};

/// Light from every direction: a constant radiance, optionally multiplied by
/// a lat-long map.
///
/// Build it with [`EnvironmentLight::new`] (which prepares the sampling
/// distribution of the map) and give it the scene's bounding sphere with
/// [`EnvironmentLight::set_scene_bounds`] before emitting rays.
#[derive(Clone, Debug)]
pub struct EnvironmentLight {
    /// Constant radiance, or the scale of the map.
    pub radiance: Color,
    /// The map (replacing it after `new` leaves a stale sampling distribution:
    /// build a new light instead).
    pub map: Option<Arc<EnvironmentMap>>,
    /// Centre and radius of a sphere bounding the scene (set by the scene;
    /// emission starts on a disk of this radius).
    pub scene_center: Vec3A,
    pub scene_radius: f32,
    /// Sampling distribution over the map's pixels (`None` without a map).
    distribution: Option<Distribution2D>,
    /// `∫_{S²} map(ω) dω` (4π without a map), for [`EnvironmentLight::power`].
    map_integral: Color,
}

/// A lat-long (equirectangular) radiance map.
#[derive(Clone, Debug)]
pub struct EnvironmentMap {
    pub width: u32,
    pub height: u32,
    /// Row-major, top row (up, +y) first.
    pub pixels: Vec<Color>,
}

/// Map coordinates `(u, v) ∈ [0,1)×[0,1]` of a unit direction (see the module doc).
#[inline]
pub fn direction_to_uv(d: Vec3A) -> Vec2 {
    // θ by atan2, not acos(d.y): acos loses all precision near the poles.
    let theta = Vec2::new(d.x, d.z).length().atan2(d.y);
    let mut phi = d.x.atan2(-d.z);
    if phi < 0.0 {
        phi += 2.0 * PI;
    }
    let u = phi * INV_2PI;
    Vec2::new(if u >= 1.0 { 0.0 } else { u }, theta * INV_PI)
}

/// The unit direction of map coordinates `(u, v)` (see the module doc).
#[inline]
pub fn uv_to_direction(uv: Vec2) -> Vec3A {
    let (sin_t, cos_t) = (PI * uv.y).sin_cos();
    let (sin_p, cos_p) = (2.0 * PI * uv.x).sin_cos();
    Vec3A::new(sin_t * sin_p, cos_t, -sin_t * cos_p)
}

/// The most pixels an environment map may have: 2²⁷ (134 million, e.g.
/// 16384 × 8192), 1.6 GB as RGB floats plus its sampling tables.
pub const MAX_MAP_PIXELS: u64 = 1 << 27;

impl EnvironmentMap {
    /// Loads a lat-long map from an EXR file (linear RGB, the first RGB
    /// layer; alpha is ignored) or a Radiance HDR file (`.hdr`, linear RGBE),
    /// chosen by the file's extension. Every pixel must be finite and
    /// non-negative: radiance is never negative, so such a map is refused
    /// with the pixel named, not clamped.
    ///
    /// The size the file's header declares is checked before any pixel
    /// memory is taken: at most [`MAX_MAP_PIXELS`].
    pub fn load(path: &Path) -> Result<EnvironmentMap, String> {
        let is_hdr = path
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("hdr"));
        let (width, mut pixels) = if is_hdr {
            Self::read_hdr(path)?
        } else {
            Self::read_exr(path)?
        };
        if width == 0 || pixels.is_empty() {
            return Err(format!("environment map {} is empty", path.display()));
        }
        for (i, c) in pixels.iter_mut().enumerate() {
            if !c.is_finite() || c.min_element() < 0.0 {
                return Err(format!(
                    "environment map {}: pixel ({}, {}) is {}: {c} (radiance is finite and never negative)",
                    path.display(),
                    i % width,
                    i / width,
                    if c.is_finite() {
                        "negative"
                    } else {
                        "not finite"
                    }
                ));
            }
            // −0 to +0, so that sampling weights are never negative zero.
            *c = c.max(Color::ZERO);
        }
        Ok(EnvironmentMap {
            width: width as u32,
            height: (pixels.len() / width) as u32,
            pixels,
        })
    }

    /// The refusal of a map whose header declares more than [`MAX_MAP_PIXELS`].
    fn too_big(path: &Path, width: u64, height: u64) -> Option<String> {
        (width.saturating_mul(height) > MAX_MAP_PIXELS).then(|| {
            format!(
                "environment map {} declares {width}×{height} pixels, more than the {} million a map may have",
                path.display(),
                MAX_MAP_PIXELS / 1_000_000
            )
        })
    }

    /// An EXR file's first RGB layer: its width and its pixels, row by row.
    fn read_exr(path: &Path) -> Result<(usize, Vec<Color>), String> {
        let unreadable = |e: &dyn std::fmt::Display| {
            format!(
                "cannot read environment map {}: {e} (an RGB EXR file is expected)",
                path.display()
            )
        };
        let meta = exr::meta::MetaData::read_from_file(path, false).map_err(|e| unreadable(&e))?;
        for h in &meta.headers {
            let (w, hh) = (h.layer_size.width() as u64, h.layer_size.height() as u64);
            if let Some(e) = Self::too_big(path, w, hh) {
                return Err(e);
            }
        }
        let image = exr::prelude::read_first_rgba_layer_from_file(
            path,
            |size, _| {
                (
                    size.width(),
                    vec![Color::ZERO; size.width() * size.height()],
                )
            },
            |(w, pixels): &mut (usize, Vec<Color>), pos, (r, g, b, _a): (f32, f32, f32, f32)| {
                pixels[pos.y() * *w + pos.x()] = Color::new(r, g, b);
            },
        )
        .map_err(|e| unreadable(&e))?;
        let width = image.layer_data.size.width();
        Ok((width, image.layer_data.channel_data.pixels.1))
    }

    /// A Radiance HDR file: its width and its pixels, row by row.
    fn read_hdr(path: &Path) -> Result<(usize, Vec<Color>), String> {
        use image::ImageDecoder;
        let unreadable = |e: &dyn std::fmt::Display| {
            format!(
                "cannot read environment map {}: {} (a Radiance HDR file is expected)",
                path.display(),
                crate::film::output::one_line(&e.to_string())
            )
        };
        let file = std::fs::File::open(path).map_err(|e| unreadable(&e))?;
        // The header alone: no pixel is read before the size is checked.
        let decoder = image::codecs::hdr::HdrDecoder::new(std::io::BufReader::new(file))
            .map_err(|e| unreadable(&e))?;
        let (w, h) = decoder.dimensions();
        if let Some(e) = Self::too_big(path, w as u64, h as u64) {
            return Err(e);
        }
        if decoder.color_type() != image::ColorType::Rgb32F {
            return Err(unreadable(&"its decoder gives no RGB floats"));
        }
        let mut bytes = vec![0u8; decoder.total_bytes() as usize];
        decoder.read_image(&mut bytes).map_err(|e| unreadable(&e))?;
        // Rgb32F: three native-endian f32 a pixel.
        let float = |b: &[u8]| f32::from_ne_bytes([b[0], b[1], b[2], b[3]]);
        let pixels = bytes
            .chunks_exact(12)
            .map(|p| Color::new(float(&p[0..4]), float(&p[4..8]), float(&p[8..12])))
            .collect();
        Ok((w as usize, pixels))
    }

    /// The pixel containing `(u, v)` (nearest lookup; `u` wraps around, `v`
    /// is clamped). Pixel `(i, j)` covers `[i/W, (i+1)/W) × [j/H, (j+1)/H)`.
    #[inline]
    pub fn lookup(&self, u: f32, v: f32) -> Color {
        let (w, h) = (self.width as usize, self.height as usize);
        let x = ((u - u.floor()) * w as f32) as usize;
        let y = ((v * h as f32).max(0.0) as usize).min(h - 1);
        self.pixels[y * w + x.min(w - 1)]
    }
}

impl EnvironmentLight {
    /// A light of constant `radiance`, or of `radiance × map`. Builds the
    /// map's sampling distribution and its integral over the sphere once.
    /// The scene bounds default to the unit sphere at the origin.
    pub fn new(radiance: Color, map: Option<Arc<EnvironmentMap>>) -> Self {
        let (distribution, map_integral) = match &map {
            None => (None, Color::splat(4.0 * PI)),
            Some(m) => {
                let (w, h) = (m.width as usize, m.height as usize);
                assert!(
                    w > 0 && h > 0 && m.pixels.len() == w * h,
                    "environment map of {w} × {h} pixels holds {} values",
                    m.pixels.len()
                );
                let mut weights = Vec::with_capacity(w * h);
                let mut integral = Color::ZERO;
                for j in 0..h {
                    // Row j spans θ ∈ [πj/H, π(j+1)/H]; the weight uses sin θ
                    // at its centre, the exact integral uses the row's solid
                    // angle per pixel (2π/W)(cos θ_j − cos θ_{j+1}).
                    let (t0, t1) = (PI * j as f32 / h as f32, PI * (j + 1) as f32 / h as f32);
                    let sin_c = (0.5 * (t0 + t1)).sin();
                    let d_omega = 2.0 * PI / w as f32 * (t0.cos() - t1.cos());
                    for i in 0..w {
                        let c = m.pixels[j * w + i];
                        weights.push(luminance(c) * sin_c);
                        integral += c * d_omega;
                    }
                }
                (Some(Distribution2D::new(&weights, w, h)), integral)
            }
        };
        EnvironmentLight {
            radiance,
            map,
            scene_center: Vec3A::ZERO,
            scene_radius: 1.0,
            distribution,
            map_integral,
        }
    }

    /// Sets the sphere bounding the scene (emitted rays start on a disk of
    /// this radius, and [`Self::power`] depends on it).
    pub fn set_scene_bounds(&mut self, center: Vec3A, radius: f32) {
        self.scene_center = center;
        self.scene_radius = radius;
    }

    /// Radiance arriving from direction `d` (pointing from the scene out to
    /// the sky): what a ray escaping with direction `d` sees.
    #[inline]
    pub fn environment_radiance(&self, d: Vec3A) -> Color {
        match &self.map {
            None => self.radiance,
            Some(m) => {
                let uv = direction_to_uv(d);
                self.radiance * m.lookup(uv.x, uv.y)
            }
        }
    }

    /// A direction `d` to the sky, its radiance and its solid-angle density.
    #[inline]
    fn sample_direction(&self, u: Vec2) -> Option<(Vec3A, Color, f32)> {
        match (&self.map, &self.distribution) {
            (Some(m), Some(dist)) => {
                let (uv, pdf_uv) = dist.sample(u);
                let sin_t = (PI * uv.y).sin();
                if pdf_uv <= 0.0 || sin_t <= 0.0 {
                    return None;
                }
                let d = uv_to_direction(uv);
                let li = self.radiance * m.lookup(uv.x, uv.y);
                Some((d, li, pdf_uv / (2.0 * PI * PI * sin_t)))
            }
            _ => Some((uniform_sphere(u), self.radiance, INV_4PI)),
        }
    }

    /// Solid-angle density of [`Self::sample_direction`] for `d`.
    #[inline]
    fn pdf_direction(&self, d: Vec3A) -> f32 {
        match &self.distribution {
            Some(dist) => {
                let uv = direction_to_uv(d);
                let sin_t = Vec2::new(d.x, d.z).length();
                if sin_t <= 0.0 {
                    return 0.0;
                }
                dist.pdf(uv) / (2.0 * PI * PI * sin_t)
            }
            None => INV_4PI,
        }
    }

    /// Next event estimation: a direction by the map's brightness (uniform
    /// on the sphere without a map). `dist` is infinite; `p` is a point in
    /// direction `wi` beyond the scene's bounding sphere (a shadow ray should
    /// rather be an unbounded ray along `wi`).
    pub fn sample_li(&self, p: Vec3A, u: Vec2) -> Option<LightSample> {
        let (wi, li, pdf_w) = self.sample_direction(u)?;
        let far = 2.0 * (self.scene_radius + (p - self.scene_center).length());
        Some(LightSample {
            wi,
            li,
            pdf_w,
            dist: f32::INFINITY,
            p: p + far * wi,
            n: Vec3A::ZERO,
            is_delta: false,
        })
    }

    /// Solid-angle density of `sample_li` for the direction `wi` (to the sky).
    #[inline]
    pub fn pdf_li_w(&self, wi: Vec3A) -> f32 {
        self.pdf_direction(wi)
    }

    /// Emits a ray into the scene: a direction `d` to the sky drawn as in
    /// `sample_li` (`p_ω`), then a point uniform on the disk of radius `r`
    /// (the scene's bounding radius) perpendicular to `d`, centred at
    /// `scene_center + r·d` (`p_A = 1/(π r²)`); the ray travels along `−d`,
    /// so every ray that can reach the scene is possible.
    pub fn sample_le(&self, u_pos: Vec2, u_dir: Vec2) -> Option<Emission> {
        let (d, le, pdf_w) = self.sample_direction(u_dir)?;
        let r = self.scene_radius;
        let frame = Frame::from_normal(-d);
        let disk = concentric_disk(u_pos);
        let o = self.scene_center + r * (d + frame.s * disk.x + frame.t * disk.y);
        Some(Emission {
            p: o,
            ray: Ray::new(o, -d),
            n: -d,
            le,
            pdf_a: 1.0 / (PI * r * r),
            pdf_w,
            is_delta_position: false,
        })
    }

    /// `p_A` and `p_ω` of emitting a ray travelling in direction `w` (into
    /// the scene).
    #[inline]
    pub fn pdf_le(&self, w: Vec3A) -> RayPdf {
        let r = self.scene_radius;
        RayPdf {
            pdf_a: 1.0 / (PI * r * r),
            pdf_w: self.pdf_direction(-w),
        }
    }

    /// Flux entering the scene's bounding disk: `Φ = π r² ∫_{S²} L(ω) dω`
    /// (`π r² · 4π L` for a constant environment), as pbrt-v4 defines it:
    /// the radiance through a disk of area `π r²` facing each direction.
    pub fn power(&self) -> Color {
        let r = self.scene_radius;
        PI * r * r * self.radiance * self.map_integral
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::light::test_stats::assert_matches;
    use crate::sampling::Sampler;
    use std::f64::consts::PI as PI64;

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
            let light = crate::light::Light::Environment(env.clone());
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
}
