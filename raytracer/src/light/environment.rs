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
