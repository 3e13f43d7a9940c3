//! Shading normals in light paths: a smooth mesh must look the same to
//! path tracing, light tracing and bidirectional tracing, and to the biased
//! integrators (instant radiosity, photon mapping, SPPM, irradiance
//! caching), whose light paths and gathers meet the same normals.
//!
//! A smooth mesh shades with interpolated normals `n_s` that differ from its
//! flat triangles' `n_g`. Path tracing takes the cosine with `n_s`; light
//! paths must then scatter with the adjoint BRDF, `f_r` times Veach's
//! correction `|ω_o·n_s| |ω_i·n_g| / (|ω_o·n_g| |ω_i·n_s|)` (see
//! `integrator::shading_normals`), or light tracing and the light-side
//! strategies of BDPT converge to another image of the mesh.
//!
//! Two scenes. A low-poly ball (20 flat faces, the sphere's normals at the
//! vertices: normals up to 37° apart), where the correction matters: without
//! it light tracing and BDPT missed the ball's path-traced image by |z| = 54
//! and 17 in the worst tile. And the torus of `stereo` (3072 faces), where
//! the normals differ by a few degrees and the correction changes the
//! torus's mean by 0.02 %, far below what a test can see; there path and
//! bidirectional tracing must agree tile by tile on the torus and on the
//! whole picture, which found BDPT skipping its next-event strategy
//! whenever no light path started, as when the sky was chosen for it: the
//! sun of `stereo` lost most of its direct light (|z| = 19.9 over the floor,
//! 4.7 on the torus).
//!
//! Tolerance: z-scores of 8×8 tiles restricted to the pixels that see the
//! mesh (tiles with at least 16 of them), with both films' variances;
//! threshold for a family-wise false-failure probability of 1e-4 over all
//! z-scores of each test (≈ 5σ). Light-path splats of one path landing in
//! the same tile are correlated, which the film's per-pixel variances
//! ignore; measured max |z| stays far below the threshold.

use std::sync::Arc;

use raytracer::brdf::{Brdf, Lambert, Texture};
use raytracer::camera::CameraParams;
use raytracer::film::{Film, Image};
use raytracer::geometry::{Mesh, Quad, Shape, Transform};
use raytracer::integrator::{Bdpt, Integrator, LightTracer, PathTracer};
use raytracer::math::{Color, Vec2, Vec3, Vec3A};
use raytracer::metrics::z_threshold;
use raytracer::render::{RenderOptions, render};
use raytracer::scene::{Emitter, RenderSettings, Scene, SceneObject, SceneParts};

const TILE: u32 = 8;

fn film(scene: &Scene, integrator: &dyn Integrator, spp: u32, seed: u64) -> Film {
    let options = RenderOptions {
        spp,
        seed,
        threads: None,
        progress: false,
        ..RenderOptions::default()
    };
    render(scene, integrator, &options).film
}

/// The low-poly smooth ball at 24 × 24, the size of its comparisons of the
/// light that exactly three segments carry.
fn small_low_poly_ball() -> Scene {
    let mut scene = low_poly_ball();
    scene.set_resolution(24, 24);
    scene
}

/// The light of exactly three segments on [`small_low_poly_ball`]: the path
/// tracer at max depth 3 minus max depth 2, 4096 spp — the reference of both
/// smooth-ball comparisons (instant radiosity's, and the biased
/// integrators'), rendered once for the test binary.
fn three_segment_reference() -> &'static Film {
    static REFERENCE: std::sync::OnceLock<Film> = std::sync::OnceLock::new();
    REFERENCE.get_or_init(|| {
        let depth = |d| PathTracer {
            max_depth: Some(d),
            ..PathTracer::default()
        };
        let (deep, shallow) = (depth(3), depth(2));
        let difference = DepthDifference {
            deep: &deep,
            shallow: &shallow,
        };
        film(&small_low_poly_ball(), &difference, 4096, 1)
    })
}

/// Which pixels see the object `name` through their centre.
fn mask(scene: &Scene, name: &str) -> Vec<bool> {
    let object = scene.objects.iter().position(|o| o.name == name).unwrap() as u32;
    let (w, h) = (scene.camera.width, scene.camera.height);
    (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .map(|(x, y)| {
            let ray = scene
                .camera
                .generate_ray(Vec2::new(x as f32 + 0.5, y as f32 + 0.5), Vec2::ZERO);
            scene.intersect(&ray).is_some_and(|it| it.shape == object)
        })
        .collect()
}

/// z-scores of the masked pixels of each tile: (tile, z per channel).
fn masked_tiles(mask: &[bool], a: &Film, b: &Film) -> Vec<((u32, u32), Color)> {
    let (ia, va, ib, vb): (Image, Image, Image, Image) =
        (a.image(), a.variance_image(), b.image(), b.variance_image());
    let (w, h) = (ia.width, ia.height);
    let mut out = Vec::new();
    for ty in 0..h / TILE {
        for tx in 0..w / TILE {
            let (mut d, mut v, mut n) = (Color::ZERO, Color::ZERO, 0);
            for y in ty * TILE..(ty + 1) * TILE {
                for x in tx * TILE..(tx + 1) * TILE {
                    if mask[(y * w + x) as usize] {
                        d += ia.get(x, y) - ib.get(x, y);
                        v += va.get(x, y) + vb.get(x, y);
                        n += 1;
                    }
                }
            }
            if n >= 16 {
                out.push(((tx, ty), d / v.powf(0.5)));
            }
        }
    }
    out
}

/// The tile with the largest |z| (printed with `what`).
fn worst(what: &str, tiles: &[((u32, u32), Color)], threshold: f32) -> ((u32, u32), f32) {
    let (tile, z) = tiles
        .iter()
        .map(|(t, z)| (*t, z.abs().max_element()))
        .fold(((0, 0), 0.0f32), |a, b| if b.1 > a.1 { b } else { a });
    eprintln!(
        "{what}: {} tiles, max |z| = {z:.2} in tile {tile:?} (threshold {threshold:.2})",
        tiles.len()
    );
    (tile, z)
}

/// A low-poly ball shaded smooth: an icosahedron (20 flat faces) with the
/// sphere's normals at its vertices, so shading and geometric normals
/// differ by up to 37°, on a grey floor under a quad lamp.
fn low_poly_ball() -> Scene {
    let quad = |origin: Vec3A, e1: Vec3A, e2: Vec3A| Shape::Quad(Quad { origin, e1, e2 });
    let ball = Mesh::icosphere(0).transformed(
        &(Transform::translate(Vec3::new(0.0, 0.5, 0.0)) * Transform::scale(Vec3::splat(0.5))),
    );
    let lambert = |c: f32| {
        Brdf::Lambert(Lambert {
            albedo: Texture::Constant(Color::splat(c)),
        })
    };
    let object = |name: &str, shape, brdf, emission: Option<Color>| SceneObject {
        name: name.into(),
        shape,
        brdf,
        emitter: emission.map(|radiance| Emitter {
            radiance,
            two_sided: false,
        }),
    };
    let mut scene = Scene::build(
        "low-poly ball",
        SceneParts {
            camera: CameraParams {
                position: Vec3A::new(0.0, 1.0, 2.6),
                look_at: Vec3A::new(0.0, 0.5, 0.0),
                up: Vec3A::Y,
                vfov_deg: 30.0,
                aperture_radius: 0.0,
                focus_distance: 2.6,
                shift: Vec2::ZERO,
            },
            settings: RenderSettings::default(),
            brdf_names: vec!["floor".into(), "ball".into()],
            brdfs: vec![lambert(0.5), lambert(0.8)],
            objects: vec![
                object(
                    "floor",
                    quad(Vec3A::new(-3.0, 0.0, 3.0), 6.0 * Vec3A::X, -6.0 * Vec3A::Z),
                    0,
                    None,
                ),
                object("ball", Shape::Mesh(Arc::new(ball)), 1, None),
                // Facing down and left, towards the ball: e1 × e2 ∥ (−1, −1, 0).
                object(
                    "lamp",
                    quad(
                        Vec3A::new(0.99, 1.81, 0.0),
                        Vec3A::new(0.42, -0.42, 0.0),
                        0.6 * Vec3A::Z,
                    ),
                    0,
                    Some(Color::splat(6.0)),
                ),
            ],
            lights: Vec::new(),
        },
    );
    scene.set_resolution(48, 48);
    scene
}

#[test]
fn light_paths_see_a_low_poly_smooth_ball_as_camera_paths_do() {
    let scene = low_poly_ball();
    let ball = mask(&scene, "ball");
    let depth = Some(3);
    let pt = PathTracer {
        max_depth: depth,
        ..PathTracer::default()
    };
    let lt = LightTracer {
        max_depth: depth,
        rr_depth: 5,
    };
    let bdpt = Bdpt {
        max_depth: depth,
        ..Bdpt::default()
    };
    let reference = film(&scene, &pt, 256, 1);
    let lt_vs_pt = masked_tiles(&ball, &reference, &film(&scene, &lt, 256, 2));
    let bd_vs_pt = masked_tiles(&ball, &reference, &film(&scene, &bdpt, 64, 3));
    let threshold = z_threshold(3 * (lt_vs_pt.len() + bd_vs_pt.len()), 1e-4) as f32;
    let lt = worst("light and path tracing on the ball", &lt_vs_pt, threshold);
    let bd = worst(
        "bidirectional and path tracing on the ball",
        &bd_vs_pt,
        threshold,
    );
    assert!(
        lt.1 < threshold,
        "light and path tracing disagree on the ball, tile {:?}: |z| = {:.1}",
        lt.0,
        lt.1
    );
    assert!(
        bd.1 < threshold,
        "bidirectional and path tracing disagree on the ball, tile {:?}: |z| = {:.1}",
        bd.0,
        bd.1
    );
}

#[test]
fn path_and_bidirectional_tracing_agree_on_the_torus_of_stereo() {
    let mut scene = Scene::builtin("stereo").unwrap();
    scene.set_resolution(96, 72);
    let depth = Some(3);
    let pt = PathTracer {
        max_depth: depth,
        ..PathTracer::default()
    };
    let bdpt = Bdpt {
        max_depth: depth,
        ..Bdpt::default()
    };
    let (a, b) = (film(&scene, &pt, 128, 1), film(&scene, &bdpt, 64, 2));
    let on_torus = masked_tiles(&mask(&scene, "torus"), &a, &b);
    let everywhere = masked_tiles(&vec![true; 96 * 72], &a, &b);
    let threshold = z_threshold(3 * (on_torus.len() + everywhere.len()), 1e-4) as f32;
    for (what, tiles) in [
        ("on the torus", on_torus),
        ("in the whole picture", everywhere),
    ] {
        let (tile, z) = worst(
            &format!("bidirectional and path tracing {what}"),
            &tiles,
            threshold,
        );
        assert!(
            z < threshold,
            "bidirectional and path tracing disagree {what}, tile {tile:?}: |z| = {z:.1}"
        );
    }
}

/// The light that `deep` adds to `shallow` in the same sample (the same
/// random numbers): with max depths D and D − 1, the paths of exactly D
/// segments, without the noise of the shorter ones.
struct DepthDifference<'a> {
    deep: &'a dyn Integrator,
    shallow: &'a dyn Integrator,
}

impl Integrator for DepthDifference<'_> {
    fn name(&self) -> &'static str {
        "depth-difference"
    }

    fn sample(
        &self,
        scene: &Scene,
        pixel: raytracer::math::UVec2,
        sampler: &mut raytracer::sampling::Sampler,
        splats: &mut Vec<raytracer::film::Splat>,
    ) -> Color {
        let deep = self.deep.sample(scene, pixel, &mut sampler.clone(), splats);
        deep - self.shallow.sample(scene, pixel, sampler, splats)
    }
}

/// Mean of the pixels of `image` that `mask` selects, channel x (the scene
/// is grey).
fn masked_mean(image: &Image, mask: &[bool]) -> f64 {
    let (mut sum, mut n) = (0.0, 0);
    for y in 0..image.height {
        for x in 0..image.width {
            if mask[(y * image.width + x) as usize] {
                sum += image.get(x, y).x as f64;
                n += 1;
            }
        }
    }
    sum / n.max(1) as f64
}

/// Instant radiosity's VPLs are light-path vertices, so a VPL on the smooth
/// ball must scatter towards `x` with the adjoint BRDF (Veach's correction
/// at the VPL's end, as BDPT's connection applies it). The light of exactly
/// three segments (D = 3 minus D = 2 in the same sample: the VPL term alone,
/// a VPL on the ball lighting the floor or one on the floor lighting the
/// ball) of 384 independent VPL sets (256 light paths each) is compared
/// with a 4096-spp path tracer's, over the floor, over the ball and in each
/// 6×6 tile of a 24×24 image.
///
/// Error to catch: without the correction the floor's share of that light
/// came out 13–18 % low and the floor tile beside the ball's lit side
/// 25–31 % low; with 384 sets that tile's standard error is about 4 % of
/// its mean, so the missing factor shows there as |z| ≈ 6, above the
/// threshold of about 4.6 (a smaller test would let it through).
/// Tolerance: the runs' spread gives the VPL side's standard error (the
/// pixels of one run share their VPLs, so the film's per-pixel variance
/// would not), the film's variances the path tracer's; the threshold holds a
/// family-wise false-failure probability of 1e-4 over every z-score (≈ 5σ).
/// The unclamped VPL estimate near the ball's contact with the floor is
/// heavy-tailed, which a Gaussian threshold understates; the tiles there
/// are few. Cost: about 10 s on two cores.
#[test]
fn vpl_sees_the_low_poly_smooth_ball_as_the_path_tracer_does() {
    use raytracer::integrator::{InstantRadiosity, VplSettings};
    use raytracer::metrics::{tile_means, tile_variances};
    let scene = small_low_poly_ball();
    let tile = 6;
    let reference = three_segment_reference();
    let (ref_image, ref_var) = (reference.image(), reference.variance_image());
    let masks = [mask(&scene, "floor"), mask(&scene, "ball")];
    // The path tracer's mean and variance of the mean, per region then per tile.
    let mut expected: Vec<(String, f64, f64)> = ["floor", "ball"]
        .iter()
        .zip(&masks)
        .map(|(name, m)| {
            let n = m.iter().filter(|&&b| b).count() as f64;
            (
                name.to_string(),
                masked_mean(&ref_image, m),
                masked_mean(&ref_var, m) / n,
            )
        })
        .collect();
    let tiles = tile_means(&ref_image, tile);
    let tile_var = tile_variances(&ref_var, tile);
    for (t, (m, v)) in tiles.iter().zip(&tile_var).enumerate() {
        expected.push((format!("tile {t}"), m.x as f64, v.x as f64));
    }
    let never = std::sync::atomic::AtomicBool::new(false);
    let runs: Vec<Vec<f64>> = (0..384u64)
        .map(|s| {
            let vpl = |d| {
                let settings = VplSettings {
                    paths: 256,
                    max_depth: Some(d),
                    seed: 100 + s,
                    ..VplSettings::default()
                };
                InstantRadiosity::build(&scene, settings, &never).unwrap()
            };
            let (deep, shallow) = (vpl(3), vpl(2));
            let image = film(
                &scene,
                &DepthDifference {
                    deep: &deep,
                    shallow: &shallow,
                },
                2,
                10 + s,
            )
            .image();
            let mut values: Vec<f64> = masks.iter().map(|m| masked_mean(&image, m)).collect();
            values.extend(tile_means(&image, tile).iter().map(|c| c.x as f64));
            values
        })
        .collect();
    let threshold = z_threshold(expected.len(), 1e-4);
    let n = runs.len() as f64;
    let mut worst = (String::new(), 0.0f64);
    for (i, (what, reference, ref_var)) in expected.iter().enumerate() {
        let mean = runs.iter().map(|r| r[i]).sum::<f64>() / n;
        let var = runs.iter().map(|r| (r[i] - mean).powi(2)).sum::<f64>() / (n - 1.0) / n;
        if var + ref_var == 0.0 {
            continue; // No three-segment light there (the sky).
        }
        let z = (mean - reference) / (var + ref_var).sqrt();
        eprintln!(
            "vpl vs path, {what}: {:+.1} % (z = {z:+.1})",
            100.0 * (mean / reference - 1.0)
        );
        if z.abs() > worst.1 {
            worst = (what.clone(), z.abs());
        }
    }
    eprintln!(
        "vpl vs path on the ball's scene: max |z| = {:.2} in {} (threshold {threshold:.2})",
        worst.1, worst.0
    );
    assert!(
        worst.1 < threshold,
        "instant radiosity and path tracing disagree on the smooth ball's scene, {}: |z| = {:.1}",
        worst.0,
        worst.1
    );
}

/// Photon mapping, SPPM and irradiance caching see the low-poly smooth
/// ball as the path tracer does: the light of exactly three segments
/// (D = 3 minus D = 2 in the same sample, as for instant radiosity above),
/// averaged over the ball's pixels and over the floor's, from independent
/// runs (8 photon maps of 200 000 paths, 8 caches of 128 rays per record,
/// 16 SPPM renders of 32 passes of 50 000 photons), against a 4096-spp
/// path tracer (standard error 0.2 % on the ball, 1 % on the floor).
///
/// These estimators are consistent, not unbiased: the bound is a band of
/// 6 % around the path tracer, not a z-score, on the ball for all three
/// and on the floor for SPPM. The floor's three-segment light is the
/// ball's light scattered onto it, carried by photons that leave the
/// smooth ball with the adjoint BRDF: without Veach's correction on the
/// photons' walk SPPM's floor came out 10–12 % low, and this test failed.
/// The band holds the kernel's and the interpolation's bias on the ball
/// (measured below 2.5 %) and, on the SPPM floor (measured 1–2.5 % low),
/// about 3.5 standard errors of the runs' spread (4 % per run, 1 % for the
/// mean of 16): a change of random numbers fails it with probability about
/// 2e-4; the ball's spread is a quarter of the floor's.
/// Left out: photon mapping's floor (±9 % per run) and the cache's (its
/// interpolation overshoots beside the ball, by about 30 %): at this cost
/// they could not see a 10 % error. Cost: about 6 s on two loaded cores.
#[test]
fn biased_integrators_see_the_low_poly_smooth_ball_as_the_path_tracer_does() {
    use raytracer::integrator::{
        IrradianceCache, IrradianceCacheSettings, PhotonMapping, PhotonSettings,
    };
    use raytracer::render::render_sppm;
    use raytracer::render::sppm::SppmSettings;
    let start = std::time::Instant::now();
    let scene = small_low_poly_ball();
    let reference = three_segment_reference().image();
    let masks = [mask(&scene, "floor"), mask(&scene, "ball")];
    let never = std::sync::atomic::AtomicBool::new(false);
    let runs = 0..8u64;
    let difference = |deep: &dyn Integrator, shallow: &dyn Integrator, seed| {
        film(&scene, &DepthDifference { deep, shallow }, 4, seed).image()
    };
    let photon: Vec<Image> = runs
        .clone()
        .map(|s| {
            let map = |d| {
                let settings = PhotonSettings {
                    max_depth: Some(d),
                    seed: s,
                    ..PhotonSettings::default()
                };
                PhotonMapping::build(&scene, settings, &never).unwrap()
            };
            difference(&map(3), &map(2), 2 + s)
        })
        .collect();
    let cache: Vec<Image> = runs
        .clone()
        .map(|s| {
            let cache = |d| {
                let settings = IrradianceCacheSettings {
                    max_depth: Some(d),
                    seed: s,
                    ..IrradianceCacheSettings::default()
                };
                IrradianceCache::build(&scene, settings, &never).unwrap()
            };
            difference(&cache(3), &cache(2), 2 + s)
        })
        .collect();
    let sppm: Vec<Image> = (0..16u64)
        .map(|s| {
            let options = RenderOptions {
                spp: 32,
                seed: 4 + s,
                threads: None,
                progress: false,
                ..RenderOptions::default()
            };
            let render = |d| {
                let settings = SppmSettings {
                    max_depth: Some(d),
                    ..SppmSettings::default()
                };
                render_sppm(&scene, &settings, &options).image
            };
            let (deep, shallow) = (render(3), render(2));
            Image::from_fn(24, 24, |x, y| deep.get(x, y) - shallow.get(x, y))
        })
        .collect();
    let mut wrong = Vec::new();
    for (what, images, regions) in [
        ("photon mapping", &photon, &["ball"][..]),
        ("irradiance caching", &cache, &["ball"][..]),
        ("sppm", &sppm, &["floor", "ball"][..]),
    ] {
        for (region, m) in ["floor", "ball"].iter().zip(&masks) {
            let mean = images.iter().map(|i| masked_mean(i, m)).sum::<f64>() / images.len() as f64;
            let off = mean / masked_mean(&reference, m) - 1.0;
            let checked = regions.contains(region);
            eprintln!(
                "{what} vs path, {region}: {:+.1} %{}",
                100.0 * off,
                if checked { "" } else { " (not checked)" }
            );
            if checked && off.abs() > 0.06 {
                wrong.push(format!("{what} on the {region}: {:+.1} %", 100.0 * off));
            }
        }
    }
    eprintln!(
        "smooth ball, biased integrators: {:.1} s",
        start.elapsed().as_secs_f64()
    );
    assert!(
        wrong.is_empty(),
        "the three-segment light on the smooth ball's scene differs from the path tracer's by more than 6 %: {}",
        wrong.join("; ")
    );
}
