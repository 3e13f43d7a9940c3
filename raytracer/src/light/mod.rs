//! Lights: where the emitted radiance `L_e` of the rendering equation comes from.
//!
//! Lecture topic: the `L_e` term of Kajiya's rendering equation, and the light
//! side of light tracing and bidirectional path tracing.
//!
//! Every light does three things (pbrt's and SmallVCM's interface):
//! - **illuminate** a point: [`Light::sample_li`] picks a point on the light
//!   as seen from a receiving point and returns a [`LightSample`] (direction,
//!   radiance, pdf per unit solid angle at the receiver, distance) — next event
//!   estimation;
//! - **report densities** for MIS: [`Light::pdf_li_w`] is the pdf per unit
//!   solid angle `sample_li` would have had for a direction that a BRDF
//!   sample happened to send into the light, and [`Light::pdf_le`] the
//!   densities of an emitted ray (a [`RayPdf`]);
//! - **emit** a ray: [`Light::sample_le`] starts a light path (an [`Emission`]
//!   with its position pdf per unit area and direction pdf per unit solid
//!   angle, kept apart for bidirectional MIS).
//!
//! Names of densities carry their measure, as in SmallVCM: `_w` per unit
//! solid angle, `_a` per unit area.

pub mod area;
pub mod environment;
pub mod point;

use crate::math::{Color, INV_4PI, Ray, RayPdf, Vec2, Vec3A};

pub use area::{AreaLight, AreaShape};
pub use environment::{EnvironmentLight, EnvironmentMap};
pub use point::PointLight;

/// A light sampled from a receiving point (next event estimation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightSample {
    /// Unit direction from the receiver towards the light point.
    pub wi: Vec3A,
    /// Radiance arriving at the receiver along `-wi` (unoccluded).
    pub li: Color,
    /// Density of `wi` per unit solid angle at the receiver (for a point
    /// light: 1, meaning "a delta with weight one").
    pub pdf_w: f32,
    /// Distance to the light point (`f32::INFINITY` for the environment).
    pub dist: f32,
    /// The point on the light (for a shadow ray).
    pub p: Vec3A,
    /// The light's surface normal at `p` (zero for a point light or the
    /// environment).
    pub n: Vec3A,
    /// Whether the light is a delta in position (a point light): MIS cannot
    /// hit it with a BRDF sample.
    pub is_delta: bool,
}

/// A ray leaving a light (the first vertex of a light path).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Emission {
    /// The point on the light: on its surface, where the path's vertex `y_0`
    /// lies (the ray's origin is pushed off the surface; the vertex is not).
    pub p: Vec3A,
    /// The ray that leaves `p`: its origin offset off an area light's
    /// surface (see [`crate::math::Ray::spawn`]).
    pub ray: Ray,
    /// Surface normal at the ray's origin (zero for a point light; the
    /// direction of travel for the environment).
    pub n: Vec3A,
    /// Emitted radiance along the ray (for a point light: its intensity).
    pub le: Color,
    /// Density of the origin per unit area (1 for a point light).
    pub pdf_a: f32,
    /// Density of the direction per unit solid angle.
    pub pdf_w: f32,
    /// Whether the origin is a delta in position (point light).
    pub is_delta_position: bool,
}

/// The lights of the course (an enum: a closed set, dispatched by `match`).
#[derive(Clone, Debug)]
pub enum Light {
    Area(AreaLight),
    Point(PointLight),
    Environment(EnvironmentLight),
}

impl Light {
    /// Next event estimation: samples a point (direction) on the light as
    /// seen from the receiving point `p`. `None` if the light sends nothing
    /// to `p` (behind a one-sided light) or the sample is degenerate.
    ///
    /// - quad, sphere seen from inside: a point uniform by area, its density
    ///   converted to one per unit solid angle at `p`;
    /// - sphere seen from outside: uniform in the subtended cone,
    ///   `p_ω = 1/(2π(1 − cos θ_max))`;
    /// - point: `L_i = I/r²`, `p_ω = 1`, `is_delta`;
    /// - environment: uniform sphere (constant) or by the map's brightness,
    ///   `dist = ∞`.
    #[inline]
    pub fn sample_li(&self, p: Vec3A, u: Vec2) -> Option<LightSample> {
        match self {
            Light::Area(l) => l.sample_li(p, u),
            Light::Point(l) => l.sample_li(p),
            Light::Environment(l) => l.sample_li(p, u),
        }
    }

    /// The solid-angle density `sample_li(p, ·)` has for the direction `wi`
    /// that left `p` and hit the light at `p_light` with normal `n_light`
    /// (the environment ignores both; a point light returns 0: no direction
    /// hits it).
    #[inline]
    pub fn pdf_li_w(&self, p: Vec3A, p_light: Vec3A, n_light: Vec3A, wi: Vec3A) -> f32 {
        match self {
            Light::Area(l) => l.pdf_li_w(p, p_light, n_light, wi),
            Light::Point(_) => 0.0,
            Light::Environment(l) => l.pdf_li_w(wi),
        }
    }

    /// `L_e` leaving an area light's surface point with normal `n_light` in
    /// direction `w` (pointing away from the light, towards the viewer).
    /// Zero for a point light (no ray hits it) and for the environment (use
    /// [`Light::environment_radiance`] for escaping rays).
    #[inline]
    pub fn le(&self, n_light: Vec3A, w: Vec3A) -> Color {
        match self {
            Light::Area(l) => l.le(n_light, w),
            Light::Point(_) | Light::Environment(_) => Color::ZERO,
        }
    }

    /// Radiance a ray escaping with direction `d` sees from this light: the
    /// environment's [`EnvironmentLight::environment_radiance`], zero for
    /// the others.
    #[inline]
    pub fn environment_radiance(&self, d: Vec3A) -> Color {
        match self {
            Light::Environment(l) => l.environment_radiance(d),
            _ => Color::ZERO,
        }
    }

    /// Emits a ray (the first vertex of a light path), with its position
    /// density per unit area and direction density per unit solid angle:
    /// - area: uniform point (`1/A`), cosine-weighted direction on the
    ///   emitting side (`cos θ/π`, halved and either side if two-sided);
    /// - point: `p_A = 1`, uniform direction `1/(4π)`;
    /// - environment: direction as in `sample_li`, origin on a disk of the
    ///   scene's bounding radius `r` (`1/(π r²)`) beyond the scene.
    #[inline]
    pub fn sample_le(&self, u_pos: Vec2, u_dir: Vec2) -> Option<Emission> {
        match self {
            Light::Area(l) => l.sample_le(u_pos, u_dir),
            Light::Point(l) => Some(l.sample_le(u_dir)),
            Light::Environment(l) => l.sample_le(u_pos, u_dir),
        }
    }

    /// The densities `p_A` (origin) and `p_ω` (direction) with which
    /// `sample_le` emits from `p` (normal `n`) in direction `w` (direction of
    /// travel). Point light: `p_A = 1, p_ω = 1/(4π)`; environment: `p` and
    /// `n` are ignored.
    #[inline]
    pub fn pdf_le(&self, p: Vec3A, n: Vec3A, w: Vec3A) -> RayPdf {
        match self {
            Light::Area(l) => l.pdf_le(p, n, w),
            Light::Point(_) => RayPdf {
                pdf_a: 1.0,
                pdf_w: INV_4PI,
            },
            Light::Environment(l) => l.pdf_le(w),
        }
    }

    /// Emitted flux `Φ` (W): `π A L` per emitting side of an area light,
    /// `4π I` for a point light, `π r² ∫ L dω` for the environment (the flux
    /// through the scene's bounding disk; depends on the scene bounds).
    /// Lights are chosen in proportion to it (`Scene::choose_light`, unless
    /// `Scene::set_light_selection` asks for a uniform choice).
    #[inline]
    pub fn power(&self) -> Color {
        match self {
            Light::Area(l) => l.power(),
            Light::Point(l) => l.power(),
            Light::Environment(l) => l.power(),
        }
    }

    /// Whether the light is a delta in position (a point light).
    #[inline]
    pub fn is_delta(&self) -> bool {
        matches!(self, Light::Point(_))
    }

    /// Whether the light lies at infinity (rays that escape see it).
    #[inline]
    pub fn is_environment(&self) -> bool {
        matches!(self, Light::Environment(_))
    }
}

/// Statistics shared by the Monte Carlo tests of this module.
#[cfg(test)]
pub(crate) mod test_stats {
    /// Mean and standard error of the mean of `values`.
    pub fn mean_and_stderr(values: &[f64]) -> (f64, f64) {
        let n = values.len() as f64;
        let mean = values.iter().sum::<f64>() / n;
        let var = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0);
        (mean, (var / n).sqrt())
    }

    /// Asserts that a Monte Carlo mean matches `exact` within 5 standard
    /// errors (a false failure has probability < 1e-6 under the normal
    /// approximation), and that the estimate is precise enough for the test
    /// to mean something (standard error below `max_rel_se` of `exact`).
    /// A zero standard error (a constant estimator) leaves a relative
    /// rounding slack of 1e-4.
    pub fn assert_matches(what: &str, values: &[f64], exact: f64, max_rel_se: f64) {
        let (mean, se) = mean_and_stderr(values);
        assert!(
            se <= max_rel_se * exact.abs(),
            "{what}: standard error {se} too large for {exact}"
        );
        eprintln!("{what}: {mean:.6} ± {se:.6} (exact {exact:.6})");
        let tol = 5.0 * se + 1e-4 * exact.abs();
        assert!(
            (mean - exact).abs() <= tol,
            "{what}: estimate {mean} ± {se} vs exact {exact}"
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::{Quad, Sphere};
    use crate::sampling::Sampler;
    use std::sync::Arc;

    fn all_lights() -> Vec<Light> {
        let quad = Quad {
            origin: Vec3A::new(-0.5, 2.0, -0.5),
            e1: Vec3A::X,
            e2: Vec3A::Z,
        };
        let sphere = Sphere {
            center: Vec3A::new(1.0, 1.0, 0.0),
            radius: 0.25,
        };
        let mut pixels = vec![Color::splat(0.5); 16 * 8];
        pixels[3 * 16 + 2] = Color::splat(100.0);
        let map = EnvironmentMap {
            width: 16,
            height: 8,
            pixels,
        };
        vec![
            Light::Area(AreaLight {
                shape: AreaShape::Quad(quad),
                radiance: Color::ONE,
                two_sided: false,
            }),
            Light::Area(AreaLight {
                shape: AreaShape::Sphere(sphere),
                radiance: Color::ONE,
                two_sided: true,
            }),
            Light::Point(PointLight {
                position: Vec3A::new(0.0, 1.5, 0.5),
                intensity: Color::ONE,
            }),
            Light::Environment(EnvironmentLight::new(Color::ONE, None)),
            Light::Environment(EnvironmentLight::new(Color::ONE, Some(Arc::new(map)))),
        ]
    }

    /// Through the enum, for every light type and several receivers:
    /// `pdf_li_w` of each sample's direction equals the sample's `pdf_w`
    /// (relative 1e-3; point lights report 0, no BRDF sample hits them), and
    /// `pdf_le` agrees with each emission.
    #[test]
    fn every_light_reports_the_density_it_samples() {
        let receivers = [
            Vec3A::ZERO,
            Vec3A::new(0.9, 1.1, 0.1),
            Vec3A::new(-2.0, 0.5, 3.0),
        ];
        for (k, light) in all_lights().iter().enumerate() {
            assert_eq!(light.is_delta(), matches!(light, Light::Point(_)));
            assert_eq!(
                light.is_environment(),
                matches!(light, Light::Environment(_))
            );
            for p in receivers {
                let mut got = 0;
                for i in 0..4096 {
                    let Some(s) = light.sample_li(p, Sampler::new(90 + k as u64, i, 0).next_2d())
                    else {
                        continue;
                    };
                    got += 1;
                    let pdf = light.pdf_li_w(p, s.p, s.n, s.wi);
                    if light.is_delta() {
                        assert!(s.is_delta && s.pdf_w == 1.0 && pdf == 0.0);
                    } else {
                        assert!(
                            (pdf - s.pdf_w).abs() <= 1e-3 * s.pdf_w,
                            "light {k} from {p}: {pdf} vs {}",
                            s.pdf_w
                        );
                    }
                }
                assert!(got > 0, "light {k} lights {p}");
            }
            for i in 0..4096 {
                let mut smp = Sampler::new(99, i, k as u64);
                let Some(e) = light.sample_le(smp.next_2d(), smp.next_2d()) else {
                    continue;
                };
                let RayPdf { pdf_a, pdf_w } = light.pdf_le(e.p, e.n, e.ray.d);
                assert!((pdf_a - e.pdf_a).abs() <= 1e-4 * e.pdf_a, "light {k}");
                assert!((pdf_w - e.pdf_w).abs() <= 1e-3 * e.pdf_w, "light {k}");
                assert_eq!(e.is_delta_position, light.is_delta());
            }
            assert!(light.power().min_element() > 0.0);
        }
    }
}
