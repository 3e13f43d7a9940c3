//! Unit tests of `integrator/dimensions.rs`.

use raytracer::integrator::dimensions::*;
use raytracer::integrator::{
    AmbientOcclusion, Bdpt, Direct, DirectStrategy, Integrator, LightTracer, NaiveRecursive,
    PathTracer,
};
use raytracer::math::UVec2;
use raytracer::sampling::Sampler;
use raytracer::scene::Scene;

/// The number of dimensions one pixel sample of `integrator` uses.
fn dimensions_used(scene: &Scene, integrator: &dyn Integrator) -> u32 {
    let mut sampler = Sampler::new(1, 2, 3);
    let mut splats = Vec::new();
    let pixel = UVec2::new(scene.camera.width / 2, scene.camera.height / 2);
    integrator.sample(scene, pixel, &mut sampler, &mut splats);
    sampler.dimension()
}

/// The layouts of the module doc, counted on the furnace (every ray hits
/// its emitting Lambert sphere, every BRDF sample succeeds, the only
/// light is always chosen) with the depth small and no roulette.
#[test]
fn each_integrator_draws_its_documented_layout() {
    let scene = Scene::builtin("furnace").unwrap();
    let camera_ray = FILM.dimensions() + LENS.dimensions();
    let light_sample = LIGHT_CHOICE.dimensions() + LIGHT_POINT.dimensions();
    let continuation = BRDF_LOBE.dimensions() + BRDF_DIRECTION.dimensions();
    let light_start =
        LIGHT_CHOICE.dimensions() + EMISSION_POINT.dimensions() + EMISSION_DIRECTION.dimensions();
    let to_camera = LENS.dimensions();
    assert_eq!(
        dimensions_used(&scene, &Direct),
        camera_ray + light_sample + continuation,
        "direct"
    );
    assert_eq!(
        dimensions_used(&scene, &AmbientOcclusion::default()),
        camera_ray + AO_DIRECTION.dimensions(),
        "ao"
    );
    // Max depth 3: two bounces, each with a light sample (not for
    // path-brdf) and a continuation.
    for (strategy, per_bounce) in [
        (DirectStrategy::Mis, light_sample + continuation),
        (DirectStrategy::LightOnly, light_sample + continuation),
        (DirectStrategy::BrdfOnly, continuation),
    ] {
        let path = PathTracer {
            max_depth: Some(3),
            rr_depth: 100,
            strategy,
        };
        assert_eq!(
            dimensions_used(&scene, &path),
            camera_ray + 2 * per_bounce,
            "{strategy:?}"
        );
    }
    // Max depth 2, two branches: each branch continues once and stops.
    let naive = NaiveRecursive::new(vec![2], Some(2));
    assert_eq!(
        dimensions_used(&scene, &naive),
        camera_ray + 2 * continuation,
        "naive"
    );
    // Max depth 2: the light subpath keeps y_0 and y_1 (no bounce), both
    // joined to the camera.
    let light = LightTracer {
        max_depth: Some(2),
        rr_depth: 100,
    };
    assert_eq!(
        dimensions_used(&scene, &light),
        light_start + 2 * to_camera,
        "light"
    );
    // Max depth 2: camera subpath z_0 z_1 z_2 (one continuation, at
    // z_1), light subpath y_0 y_1; strategies (1,1) and (2,1) connect to
    // the camera, (1,2) samples a light, (0,2) and (0,3) draw nothing.
    let bdpt = Bdpt {
        max_depth: Some(2),
        rr_depth: 100,
        strategy_images: None,
    };
    assert_eq!(
        dimensions_used(&scene, &bdpt),
        camera_ray + continuation + light_start + 2 * to_camera + light_sample,
        "bdpt"
    );
    // The biased integrators: visible point, light sample; final
    // gathering adds a continuation per gather ray (the furnace has no
    // delta surfaces); a covered irradiance-cache point draws nothing more.
    let never = std::sync::atomic::AtomicBool::new(false);
    let d = Some(3);
    let photon = raytracer::integrator::PhotonMapping::build(
        &scene,
        raytracer::integrator::PhotonSettings {
            photons: 2000,
            max_depth: d,
            ..Default::default()
        },
        &never,
    )
    .unwrap();
    assert_eq!(
        dimensions_used(&scene, &photon),
        camera_ray + light_sample,
        "photon"
    );
    let gathering = raytracer::integrator::PhotonMapping::build(
        &scene,
        raytracer::integrator::PhotonSettings {
            photons: 2000,
            final_gather: 2,
            max_depth: d,
            ..Default::default()
        },
        &never,
    )
    .unwrap();
    assert_eq!(
        dimensions_used(&scene, &gathering),
        camera_ray + light_sample + 2 * continuation,
        "photon with final gathering"
    );
    let vpl = raytracer::integrator::InstantRadiosity::build(
        &scene,
        raytracer::integrator::VplSettings {
            paths: 16,
            max_depth: d,
            ..Default::default()
        },
        &never,
    )
    .unwrap();
    assert_eq!(
        dimensions_used(&scene, &vpl),
        camera_ray + light_sample,
        "vpl"
    );
    let mut tiny = scene.clone();
    tiny.set_resolution(4, 4);
    let ic = raytracer::integrator::IrradianceCache::build(
        &tiny,
        raytracer::integrator::IrradianceCacheSettings {
            rays: 4,
            error: 0.9,
            max_depth: d,
            ..Default::default()
        },
        &never,
    )
    .unwrap();
    assert_eq!(
        dimensions_used(&tiny, &ic),
        camera_ray + light_sample,
        "irradiance-cache"
    );
    let ic = raytracer::integrator::IrradianceCache::build(
        &tiny,
        raytracer::integrator::IrradianceCacheSettings {
            rays: 12,
            error: 0.9,
            max_depth: d,
            gradients: true,
            ..Default::default()
        },
        &never,
    )
    .unwrap();
    assert_eq!(
        dimensions_used(&tiny, &ic),
        camera_ray + light_sample,
        "irradiance-cache with gradients"
    );
    // Roulette adds its one number per bounce once it plays (from the
    // first bounce on here; the path may end after one or two).
    let path = PathTracer {
        max_depth: Some(3),
        rr_depth: 1,
        strategy: DirectStrategy::BrdfOnly,
    };
    let used = dimensions_used(&scene, &path);
    let bounce = continuation + ROULETTE.dimensions();
    assert!(
        used == camera_ray + bounce || used == camera_ray + 2 * bounce,
        "{used}"
    );
}

/// Every random number an integrator draws goes through a named `Draw`:
/// no `next_1d`/`next_2d` on a sampler in the code of `integrator/`
/// (comments aside, and this file, which names them).
#[test]
fn integrators_draw_only_through_named_dimensions() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src/integrator");
    let mut raw = Vec::new();
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.ends_with("dimensions.rs") {
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        for (i, line) in text.lines().enumerate() {
            let code = line.split("//").next().unwrap_or("");
            if code.contains(".next_1d()") || code.contains(".next_2d()") {
                let name = path.file_name().unwrap().to_string_lossy();
                raw.push(format!("integrator/{name}:{}: {}", i + 1, line.trim()));
            }
        }
    }
    assert!(
        raw.is_empty(),
        "draws without a name (use a Draw of integrator::dimensions):\n{}",
        raw.join("\n")
    );
}
