//! Grader of exercise 12 (next event estimation).
//!
//! 1. The change of measure exactly, including the light seen edge-on.
//! 2. Direct light at a point of a Lambertian floor under square area
//!    lights, whose exact value is `f_r · Σ L E`, with `E` the irradiance of
//!    each light's visible part by Lambert's polygon formula
//!    ([`crate::polygon`]): one light; the same with an occluder (its shadow,
//!    projected onto the light, is subtracted exactly); two lights (the
//!    light-choice probability); a light that turns its back (one-sided
//!    emission); and the floor seen from its back side (the cosine at the
//!    surface). A failing mean is compared with what the usual mistakes
//!    converge to — a missing cosine at the surface or at the light, `r`
//!    instead of `r²`, the area density left unconverted, no shadow ray, no
//!    pmf, two-sided emission, a signed cosine — computed by quadrature over
//!    the light, and the matching one is named.
//!    A sixth case: a two-sided light seen from its back (where a signed
//!    cosine at the light shows).
//! 3. Direct light in the Cornell box against the renderer, tile by tile.
//! 4. The path tracer with next event estimation: the emitting furnace
//!    (exact `L_e(1 + ρ + ρ²)` at max depth 3, and `L_e/(1 − ρ)` with
//!    roulette; direct light counted twice is named), the white furnace under
//!    a sky (the environment is a light too), a mirror that shows a light
//!    (exact `R·L_e`: emission after a delta bounce), then the Cornell box
//!    at max depth 5 against the renderer, tile by tile.
//!
//! Tolerances: |z| ≤ 5.5 per channel with the student's own variance in 6
//! direct-light cases and 3 furnace cases (false failure < 1e-6 in all);
//! the mirror case is exact (1e-4 relative, no noise); the image
//! comparisons at family-wise α = 1e-4 each ([`crate::compare`]).

use exercises::plug::{PathRadianceFn, StudentDirect, StudentPathTracer};
use glam::DVec3;
use raytracer::brdf::{Brdf, Lambert, Mirror, Texture};
use raytracer::camera::CameraParams;
use raytracer::frame::Frame;
use raytracer::geometry::{Quad, Shape};
use raytracer::math::{Color, INV_PI, Ray, Vec2, Vec3A};
use raytracer::sampling::Sampler;
use raytracer::scene::{
    Emitter, Interaction, LightSelection, RenderSettings, Scene, SceneObject, SceneParts,
};

use crate::compare::{EX12_CORNELL, EX12_CORNELL_DIRECT, compare};
use crate::ex10_naive_recursive::{LE, RHO, camera_estimates, series, small_scene};
use crate::polygon::{corners, integrate_over_quad, irradiance, project_from};
use crate::stats::{MeanVar, close, fmt3};

/// The signatures of exercise 12.
pub type AreaPdfFn = fn(f32, Vec3A, Vec3A, Vec3A) -> f32;
pub use exercises::plug::EstimateDirectFn as DirectFn;

/// Estimates per analytic case.
pub const ESTIMATES: u64 = 20_000;

/// The grader's conversion (0 for a light seen edge-on).
pub fn expected_pdf(pdf_a: f32, x: Vec3A, y: Vec3A, n_y: Vec3A) -> f32 {
    let d = x - y;
    let cos = n_y.dot(d.normalize()).abs();
    if cos == 0.0 {
        0.0
    } else {
        pdf_a * d.length_squared() / cos
    }
}

/// Paths per furnace case of the path tracer.
pub const PATHS: u64 = 4000;

pub fn check(
    to_solid_angle: AreaPdfFn,
    direct: DirectFn,
    path: PathRadianceFn,
) -> Result<(), String> {
    check_conversion(to_solid_angle)?;
    for case in cases() {
        case.check(direct)?;
    }
    compare(&EX12_CORNELL_DIRECT, &StudentDirect(direct))
        .map_err(|e| crate::tr!("ex12.direct_what", e))?;
    check_path(path)
}

/// Part 3: the path tracer with next event estimation.
pub fn check_path(path: PathRadianceFn) -> Result<(), String> {
    let what = "path_radiance_nee";
    check_furnaces(what, path, 120)?;
    check_mirror(what, path, |got, want| {
        if got == Color::ZERO {
            crate::tr!("ex12.mirror_missing")
        } else if got.element_sum() < want.element_sum() {
            crate::tr!("ex12.mirror_dark")
        } else {
            crate::tr!("ex12.mirror_bright")
        }
    })?;
    let student = StudentPathTracer {
        path_radiance: path,
        max_depth: Some(5),
        rr_depth: 3,
    };
    compare(&EX12_CORNELL, &student).map_err(|e| crate::tr!("ex12.cornell", what, e))
}

/// The furnaces of a path tracer with light sampling (exercises 12 and 13):
/// every vertex sees the light by a light sample too, so emission counted
/// at every hit as well counts the direct light twice.
pub fn check_furnaces(what: &str, path: PathRadianceFn, seed: u64) -> Result<(), String> {
    let furnace = small_scene("furnace")?;
    let d = 3;
    let stats = camera_estimates(&furnace, seed, PATHS, |ray, s| {
        path(&furnace, ray, Some(d), 1000, s)
    });
    // Counted twice: L_e + 2ρL_e + 2ρ²L_e (light sample and hit at each bounce).
    let twice = LE * (1.0 + 2.0 * RHO + 2.0 * RHO * RHO);
    let named = [
        (twice, crate::tr!("ex12.twice")),
        (LE, crate::tr!("ex12.le_only")),
        (LE * (1.0 + 2.0 * RHO), crate::tr!("ex12.no_beta")),
        (series(d + 1, RHO), crate::tr!("ex12.bounce_more")),
        (series(d - 1, RHO), crate::tr!("ex12.bounce_fewer")),
    ];
    let advice = named
        .iter()
        .find(|(v, _)| stats.matches(Color::splat(*v as f32)))
        .map(|(_, why)| why.to_string());
    stats.check(
        &crate::tr!("ex12.furnace", what, d),
        Color::splat(series(d, RHO) as f32),
        |r| {
            advice.clone().or_else(|| {
                Some(if r > 1.0 {
                    crate::tr!("ex12.furnace_bright")
                } else {
                    crate::tr!("ex12.furnace_dark")
                })
            })
        },
    )?;
    let stats = camera_estimates(&furnace, seed + 1, PATHS, |ray, s| {
        path(&furnace, ray, None, 1, s)
    });
    stats.check(
        &crate::tr!("ex12.furnace_roulette", what),
        Color::ONE,
        |r| {
            Some(
                if r < 1.0 {
                    crate::tr!("ex12.roulette_dark")
                } else {
                    crate::tr!("ex12.roulette_bright")
                }
                .to_string(),
            )
        },
    )?;
    let white = small_scene("white-furnace")?;
    let stats = camera_estimates(&white, seed + 2, PATHS, |ray, s| {
        path(&white, ray, None, 2, s)
    });
    stats.check(&crate::tr!("ex12.white", what), Color::ONE, |r| {
        Some(
            if r > 1.2 {
                crate::tr!("ex12.sky_twice")
            } else if r < 1.0 {
                crate::tr!("ex12.sky_missing")
            } else {
                crate::tr!("ex12.too_bright")
            }
            .to_string(),
        )
    })
}

/// A mirror floor (reflectance `MIRROR_R`) under a square light (facing
/// down): the camera ray `ray` hits the mirror and its reflection the light.
pub fn mirror_scene() -> (Scene, Ray, Color) {
    let le = Color::new(4.0, 3.0, 2.0);
    let light = TestLight {
        origin: Vec3A::new(-1.0, 2.0, -1.0),
        // e1 × e2 = −4 y: the light faces down, towards the mirror.
        e1: Vec3A::new(2.0, 0.0, 0.0),
        e2: Vec3A::new(0.0, 0.0, 2.0),
        radiance: le,
    };
    let (mut scene, _) = scene_with(&[light], None, 1.0, false);
    scene.brdfs[0] = Brdf::Mirror(Mirror {
        reflectance: MIRROR_R,
    });
    let d = Vec3A::new(0.3, -1.0, 0.1).normalize();
    (scene, Ray::new(-0.8 * d, d), MIRROR_R * le)
}

/// The mirror's reflectance in [`mirror_scene`].
pub const MIRROR_R: Color = Color::new(0.9, 0.8, 0.7);

/// The mirror case at max depth 2: exactly `R·L_e`, no noise.
pub fn check_mirror(
    what: &str,
    path: PathRadianceFn,
    why: impl Fn(Color, Color) -> String,
) -> Result<(), String> {
    let (scene, ray, want) = mirror_scene();
    for i in 0..16 {
        let got = path(&scene, ray, Some(2), 1000, &mut Sampler::new(121, i, 0));
        if !(0..3).all(|k| close(got[k], want[k], 1e-4)) {
            return Err(crate::tr!(
                "ex12.mirror",
                r = fmt3(MIRROR_R),
                le = fmt3(Color::new(4.0, 3.0, 2.0)),
                got = fmt3(got),
                want = fmt3(want),
                why = why(got, want),
                what
            ));
        }
    }
    Ok(())
}

fn check_conversion(to_solid_angle: AreaPdfFn) -> Result<(), String> {
    let cases = [
        (0.25, Vec3A::ZERO, Vec3A::new(0.0, 2.0, 0.0), -Vec3A::Y),
        (0.25, Vec3A::ZERO, Vec3A::new(1.0, 2.0, 0.5), -Vec3A::Y),
        (
            1.0,
            Vec3A::new(0.3, -1.0, 0.2),
            Vec3A::new(-0.2, 0.99, 0.1),
            Vec3A::new(0.0, -1.0, 0.0),
        ),
        // The light's normal faces away: the density uses |cos θ_y|.
        (
            2.0,
            Vec3A::ZERO,
            Vec3A::new(0.5, 1.0, -1.0),
            Vec3A::new(0.0, 0.6, 0.8),
        ),
        // x behind the light (a two-sided light is seen from there): the
        // cosine between n_y and y → x is negative.
        (
            0.5,
            Vec3A::new(0.2, -0.5, 0.1),
            Vec3A::new(-0.3, 1.5, 0.4),
            Vec3A::new(0.0, 0.8, 0.6),
        ),
    ];
    for (pdf_a, x, y, n) in cases {
        let got = to_solid_angle(pdf_a, x, y, n);
        let want = expected_pdf(pdf_a, x, y, n);
        if close(got, want, 1e-4) {
            continue;
        }
        let d = x - y;
        let cos_y = n.dot(d.normalize()).abs();
        let why = if close(got, pdf_a, 1e-4) {
            crate::tr!("ex12.area")
        } else if close(got, -want, 1e-4) {
            crate::tr!("ex12.negative")
        } else if close(got, pdf_a * d.length() / cos_y, 1e-4) {
            crate::tr!("ex12.not_squared")
        } else if close(got, pdf_a * d.length_squared(), 1e-4) {
            crate::tr!("ex12.no_cos_light")
        } else if close(got, pdf_a * cos_y / d.length_squared(), 1e-4) {
            crate::tr!("ex12.upside_down")
        } else {
            crate::tr!("ex12.theta_y")
        };
        return Err(crate::tr!(
            "ex12.pdf",
            x = fmt3(x),
            y = fmt3(y),
            n = fmt3(n),
            pdf_a,
            got,
            why
        ));
    }
    // The light seen edge-on: no solid angle, density 0 (not ∞ or NaN).
    let (x, y, n) = (
        Vec3A::ZERO,
        Vec3A::new(1.0, 1.0, 0.0),
        Vec3A::new(0.0, 0.0, 1.0),
    );
    let got = to_solid_angle(0.5, x, y, n);
    if got != 0.0 {
        return Err(crate::tr!(
            "ex12.edge_on",
            x = fmt3(x),
            y = fmt3(y),
            n = fmt3(n),
            got
        ));
    }
    Ok(())
}

/// A square area light of the test: `origin + a·e1 + b·e2`, emitting
/// `radiance` on the side of `e1 × e2`.
#[derive(Clone, Copy, Debug)]
pub struct TestLight {
    pub origin: Vec3A,
    pub e1: Vec3A,
    pub e2: Vec3A,
    pub radiance: Color,
}

impl TestLight {
    /// A square of side `s` centred at `c` whose normal is
    /// `(−sin τ, −cos τ, 0)`: facing down (τ = 0), tilted towards −x by τ.
    pub fn tilted(c: Vec3A, tau: f32, s: f32, radiance: Color) -> TestLight {
        let e1 = s * Vec3A::new(tau.cos(), -tau.sin(), 0.0);
        let e2 = Vec3A::new(0.0, 0.0, s);
        TestLight {
            origin: c - 0.5 * (e1 + e2),
            e1,
            e2,
            radiance,
        }
    }

    pub fn normal(&self) -> Vec3A {
        self.e1.cross(self.e2).normalize()
    }

    pub fn corners(&self) -> [Vec3A; 4] {
        corners(self.origin, self.e1, self.e2)
    }

    /// `∫ g dA` over the light, `g` of (unit direction from x, r², cos θ_y)
    /// (see [`integrate_over_quad`]).
    pub fn integrate(&self, x: Vec3A, g: impl Fn(DVec3, f64, f64) -> f64) -> f64 {
        let n = self.normal();
        let n = DVec3::new(n.x as f64, n.y as f64, n.z as f64);
        let x = DVec3::new(x.x as f64, x.y as f64, x.z as f64);
        integrate_over_quad(self.origin, self.e1, self.e2, 400, |y| {
            let v = y - x;
            let r2 = v.length_squared();
            let w = v / r2.sqrt();
            g(w, r2, w.dot(n).abs())
        })
    }
}

/// One analytic case.
pub struct NeeCase {
    pub what: String,
    pub scene: Scene,
    pub it: Interaction,
    pub exact: Color,
    /// What the usual mistakes converge to here, and what to say.
    pub named: Vec<(Color, String)>,
}

impl NeeCase {
    /// z-tests the student's mean; on failure names a mistake if its value matches.
    pub fn check(&self, direct: DirectFn) -> Result<(), String> {
        let mut stats = MeanVar::default();
        for i in 0..ESTIMATES {
            let mut sampler = Sampler::new(12, i, 0);
            stats.add(direct(&self.scene, &self.it, &mut sampler));
        }
        let advice = self
            .named
            .iter()
            .find(|(value, _)| stats.matches(*value))
            .map(|(_, why)| why.clone());
        stats.check(&self.what, self.exact, |_| {
            Some(advice.clone().unwrap_or_else(|| crate::tr!("ex12.compare")))
        })
    }
}

/// The albedo of the floor, and the BRDF value `ρ/π` of every case.
pub const FLOOR_ALBEDO: Color = Color::new(0.8, 0.6, 0.4);

/// The lights: A, tilted so that the cosines at x and at the light, `1/r`
/// and `r` all differ (a missing cosine at x changes the answer by ×1.13,
/// one at the light by ×1.72, `r` for `r²` by ×2.31, the area density by
/// ×9.4); B, a second light facing down; D, a light above x facing up.
pub fn light_a() -> TestLight {
    TestLight::tilted(
        Vec3A::new(1.0, 2.1, 0.2),
        1.4,
        0.8,
        Color::new(4.0, 3.0, 2.0),
    )
}
pub fn light_b() -> TestLight {
    TestLight::tilted(
        Vec3A::new(-1.2, 1.8, -0.3),
        0.0,
        0.6,
        Color::new(2.0, 2.5, 3.0),
    )
}
pub fn light_d() -> TestLight {
    let s = 0.7;
    TestLight {
        origin: Vec3A::new(-0.8 - s / 2.0, 1.5, 0.4 - s / 2.0),
        e1: Vec3A::new(0.0, 0.0, s),
        e2: Vec3A::new(s, 0.0, 0.0),
        radiance: Color::splat(3.0),
    }
}

/// The receiving point: the origin, on the floor.
pub const X: Vec3A = Vec3A::ZERO;

/// A scene of the floor (normal `floor_normal`), the lights, and optionally
/// an occluder, with the interaction at [`X`] seen from above.
fn scene(
    lights: &[TestLight],
    occluder: Option<TestLight>,
    floor_normal: f32,
) -> (Scene, Interaction) {
    scene_with(lights, occluder, floor_normal, false)
}

/// [`scene`] with the lights one- or two-sided.
pub fn scene_with(
    lights: &[TestLight],
    occluder: Option<TestLight>,
    floor_normal: f32,
    two_sided: bool,
) -> (Scene, Interaction) {
    let floor = if floor_normal > 0.0 {
        // e1 × e2 = +y.
        Quad {
            origin: Vec3A::new(-3.0, 0.0, 3.0),
            e1: Vec3A::new(6.0, 0.0, 0.0),
            e2: Vec3A::new(0.0, 0.0, -6.0),
        }
    } else {
        Quad {
            origin: Vec3A::new(-3.0, 0.0, 3.0),
            e1: Vec3A::new(0.0, 0.0, -6.0),
            e2: Vec3A::new(6.0, 0.0, 0.0),
        }
    };
    let mut objects = vec![SceneObject {
        name: "floor".into(),
        shape: Shape::Quad(floor),
        brdf: 0,
        emitter: None,
    }];
    for (i, l) in lights.iter().enumerate() {
        objects.push(SceneObject {
            name: format!("light{i}"),
            shape: Shape::Quad(Quad {
                origin: l.origin,
                e1: l.e1,
                e2: l.e2,
            }),
            brdf: 1,
            emitter: Some(Emitter {
                radiance: l.radiance,
                two_sided,
            }),
        });
    }
    if let Some(o) = occluder {
        objects.push(SceneObject {
            name: "occluder".into(),
            shape: Shape::Quad(Quad {
                origin: o.origin,
                e1: o.e1,
                e2: o.e2,
            }),
            brdf: 1,
            emitter: None,
        });
    }
    let lambert = |c: Color| {
        Brdf::Lambert(Lambert {
            albedo: Texture::Constant(c),
        })
    };
    let parts = SceneParts {
        camera: CameraParams {
            position: Vec3A::new(0.0, 1.0, 5.0),
            look_at: Vec3A::ZERO,
            up: Vec3A::Y,
            vfov_deg: 40.0,
            aperture_radius: 0.0,
            focus_distance: 5.0,
            shift: Vec2::ZERO,
        },
        settings: RenderSettings {
            width: 8,
            height: 8,
            ..RenderSettings::default()
        },
        brdf_names: vec!["floor".into(), "grey".into()],
        brdfs: vec![lambert(FLOOR_ALBEDO), lambert(Color::splat(0.5))],
        objects,
        lights: Vec::new(),
    };
    let mut scene = Scene::build("grader-nee", parts);
    // The cases say "each chosen with probability 1/2": uniform choice (the
    // renderer's default is by power, which would give light A 0.68 here).
    scene.set_light_selection(LightSelection::Uniform);
    let ng = Vec3A::new(0.0, floor_normal, 0.0);
    let it = Interaction {
        p: X,
        ng,
        frame: Frame::from_normal(ng),
        uv: Vec2::splat(0.5),
        wo: Vec3A::new(0.3, 1.0, 0.2).normalize(),
        t: 1.0,
        shape: 0,
        p_error: Vec3A::ZERO,
    };
    (scene, it)
}

/// `f_r L E` at [`X`] (normal +y) for the lights, by Lambert's formula.
pub fn exact(lights: &[TestLight]) -> Color {
    lights
        .iter()
        .map(|l| {
            FLOOR_ALBEDO * INV_PI * l.radiance * irradiance(X, Vec3A::Y, &l.corners(), 1.0) as f32
        })
        .sum()
}

/// The cases, in the order they are graded (each adds one difficulty).
pub fn cases() -> Vec<NeeCase> {
    let a = light_a();
    let f = FLOOR_ALBEDO * INV_PI;
    let value = |l: &TestLight, g: &dyn Fn(DVec3, f64, f64) -> f64| {
        f * l.radiance * l.integrate(X, g) as f32
    };
    let exact_a = exact(&[a]);
    let mut out = Vec::new();

    // 1. One light.
    let (scene1, it1) = scene(&[a], None, 1.0);
    out.push(NeeCase {
        what: crate::tr!("ex12.one_light"),
        scene: scene1,
        it: it1,
        exact: exact_a,
        named: vec![
            (
                value(&a, &|_, r2, cy| cy / r2),
                crate::tr!("ex12.no_cos_surface"),
            ),
            (
                value(&a, &|w, r2, cy| w.y * cy / r2.sqrt()),
                crate::tr!("ex12.r_not_r2"),
            ),
            (
                value(&a, &|w, r2, _| w.y / r2),
                crate::tr!("ex12.no_cos_light2"),
            ),
            (value(&a, &|w, _, _| w.y), crate::tr!("ex12.area_density")),
            (exact_a / f, crate::tr!("ex12.no_brdf")),
        ],
    });

    // 2. The same light behind an occluder half way, parallel to it, whose
    // shadow projected from x onto the light lies inside the light.
    let c = a.origin + 0.5 * (a.e1 + a.e2);
    let occluder = TestLight {
        origin: 0.5 * c - 0.25 * (a.e1 + a.e2) * 0.5,
        e1: 0.25 * a.e1,
        e2: 0.25 * a.e2,
        radiance: Color::ZERO,
    };
    let shadow: Vec<Vec3A> = corners(occluder.origin, occluder.e1, occluder.e2)
        .iter()
        .map(|&p| project_from(X, p, a.origin, a.normal()))
        .collect();
    let blocked = f * a.radiance * irradiance(X, Vec3A::Y, &shadow, 1.0) as f32;
    let (scene2, it2) = scene(&[a], Some(occluder), 1.0);
    out.push(NeeCase {
        what: crate::tr!("ex12.occluded"),
        scene: scene2,
        it: it2,
        exact: exact_a - blocked,
        named: vec![(exact_a, crate::tr!("ex12.no_shadow"))],
    });

    // 3. Two lights: each chosen with probability 1/2.
    let b = light_b();
    let both = exact(&[a, b]);
    let (scene3, it3) = scene(&[a, b], None, 1.0);
    out.push(NeeCase {
        what: crate::tr!("ex12.two_lights"),
        scene: scene3,
        it: it3,
        exact: both,
        named: vec![
            (both * 0.5, crate::tr!("ex12.half")),
            (both * 0.25, crate::tr!("ex12.quarter")),
            (both * 2.0, crate::tr!("ex12.double")),
        ],
    });

    // 4. A light above x that faces up, away from it: one-sided, it sends x nothing.
    let d = light_d();
    let (scene4, it4) = scene(&[a, d], None, 1.0);
    let d_two_sided = f * d.radiance * irradiance(X, Vec3A::Y, &d.corners(), 1.0) as f32;
    out.push(NeeCase {
        what: crate::tr!("ex12.back_light"),
        scene: scene4,
        it: it4,
        exact: exact_a,
        named: vec![(exact_a + d_two_sided, crate::tr!("ex12.back_lights"))],
    });

    // 5. The floor seen from its back side: its normal points down, the
    // viewer and the light are above (wo.z < 0 and wi.z < 0 in the local frame).
    let (scene5, it5) = scene(&[a], None, -1.0);
    out.push(NeeCase {
        what: crate::tr!("ex12.back_floor"),
        scene: scene5,
        it: it5,
        exact: exact_a,
        named: vec![
            (-exact_a, crate::tr!("ex12.back_negative")),
            (Color::ZERO, crate::tr!("ex12.back_zero")),
        ],
    });

    // 6. A two-sided light above x that faces up: x sees its back, which emits too.
    let (scene6, it6) = scene_with(&[d], None, 1.0, true);
    out.push(NeeCase {
        what: crate::tr!("ex12.two_sided"),
        scene: scene6,
        it: it6,
        exact: d_two_sided,
        named: vec![
            (-d_two_sided, crate::tr!("ex12.two_sided_negative")),
            (Color::ZERO, crate::tr!("ex12.two_sided_zero")),
        ],
    });
    out
}
