//! The path recorder holds to DESIGN.md's contract "Paths can be recorded":
//! recording never changes the estimate (the recorded sample equals the
//! rendered one bit for bit, splats included), and the record adds up to
//! it — for direct lighting and the path tracer the vertices' emitter hits
//! and shadow rays, for
//! light tracing the connections to the lens (its splats, bit for bit), for
//! bidirectional tracing the weighted strategies, for naive recursion every
//! ray of its tree. Deterministic (fixed seeds, no tolerance on chance): the
//! only tolerance is float rounding, because the record sums in another
//! order than the integrator.

use raytracer::film::Splat;
use raytracer::integrator::record::{
    MAX_RECORDED_VERTICES, PathRecord, PathRole, SegmentKind, VertexKind, record_sample,
};
use raytracer::integrator::{Bdpt, Direct, Integrator, LightTracer, NaiveRecursive, PathTracer};
use raytracer::math::{Color, UVec2};
use raytracer::sampling::Sampler;
use raytracer::scene::Scene;

fn cornell(size: u32) -> Scene {
    let mut scene = Scene::builtin("cornell").unwrap();
    scene.set_resolution(size, size);
    scene
}

/// The sample as the render computes it (the same sampler).
fn rendered(
    integrator: &dyn Integrator,
    scene: &Scene,
    pixel: UVec2,
    seed: u64,
    k: u32,
) -> (Color, Vec<Splat>) {
    let index = pixel.y as u64 * scene.camera.width as u64 + pixel.x as u64;
    let mut sampler = Sampler::new(seed, index, k as u64);
    let mut splats = Vec::new();
    let c = integrator.sample(scene, pixel, &mut sampler, &mut splats);
    (c, splats)
}

fn bits(c: Color) -> [u32; 3] {
    c.to_array().map(f32::to_bits)
}

fn close(a: Color, b: Color) -> bool {
    (a - b).abs().max_element() <= 1e-5 * a.abs().max(b.abs()).max_element() + 1e-9
}

/// Every pixel sample of a small Cornell box (16×16, 2 samples each):
/// recorded = rendered, bit for bit, and the record's sum = the estimate.
fn check(integrator: &dyn Integrator, mut each: impl FnMut(&PathRecord)) -> usize {
    let scene = cornell(16);
    let mut contributing = 0;
    for y in 0..16 {
        for x in 0..16 {
            for k in 0..2 {
                let pixel = UVec2::new(x, y);
                let (record, splats) = record_sample(integrator, &scene, pixel, 7, k);
                let (c, rendered_splats) = rendered(integrator, &scene, pixel, 7, k);
                let estimate = Color::from_array(record.estimate);
                let what = format!("{} pixel ({x}, {y}) sample {k}", integrator.name());
                assert_eq!(
                    bits(estimate),
                    bits(c),
                    "{what}: recording changed the estimate"
                );
                assert_eq!(splats.len(), rendered_splats.len(), "{what}");
                for (a, b) in splats.iter().zip(&rendered_splats) {
                    assert_eq!(bits(a.value), bits(b.value), "{what}: a splat changed");
                }
                let sum = record.pixel_sum();
                assert!(
                    close(sum, estimate),
                    "{what}: record sums to {sum}, estimate {estimate}"
                );
                let recorded = record.splats();
                assert_eq!(recorded.len(), splats.len(), "{what}: every splat recorded");
                for (a, b) in recorded.iter().zip(&splats) {
                    assert_eq!(a.raster, b.raster, "{what}");
                    assert_eq!(bits(a.value), bits(b.value), "{what}: recorded splat");
                }
                assert!(record.truncated.is_none(), "{what}: {:?}", record.truncated);
                if estimate != Color::ZERO || !splats.is_empty() {
                    contributing += 1;
                }
                each(&record);
            }
        }
    }
    contributing
}

#[test]
fn the_path_tracers_record_sums_to_its_estimate() {
    let mut shadow_rays = 0;
    let pt = PathTracer {
        max_depth: Some(5),
        ..PathTracer::default()
    };
    let n = check(&pt, |r| {
        assert_eq!(r.paths.len(), 1);
        assert_eq!(r.paths[0].role, PathRole::Camera);
        assert_eq!(r.paths[0].vertices[0].kind, VertexKind::Camera);
        for s in &r.segments {
            assert_eq!(s.kind, SegmentKind::ShadowRay);
            assert!(s.from.vertex >= 1, "a shadow ray leaves a hit");
            shadow_rays += 1;
        }
    });
    assert!(
        n > 400 && shadow_rays > 400,
        "{n} contributing samples, {shadow_rays} shadow rays"
    );
}

#[test]
fn direct_lightings_record_sums_to_its_estimate() {
    let n = check(&Direct, |r| {
        assert!(
            r.paths[0].vertices.len() <= 3,
            "the lens, the hit, the BRDF ray's end"
        );
        assert!(r.segments.len() <= 1, "one shadow ray");
    });
    // 312 of the 512 samples carry light; the test can fail only if some do.
    assert!(n > 250, "{n}");
}

#[test]
fn light_tracings_record_is_its_splats() {
    let lt = LightTracer {
        max_depth: Some(5),
        ..LightTracer::default()
    };
    let mut occluded = 0;
    let n = check(&lt, |r| {
        assert_eq!(r.estimate, [0.0; 3]);
        assert_eq!(r.paths[0].role, PathRole::Light);
        assert_eq!(r.paths[0].vertices[0].kind, VertexKind::Light);
        for s in &r.segments {
            // Issue 27: blocked connections to the lens are shown too,
            // adding nothing and landing nowhere.
            if s.occluded {
                assert_eq!((s.splat, s.contribution), (None, [0.0; 3]));
                occluded += 1;
            }
            assert_eq!(
                s.strategy.unwrap()[1],
                1,
                "light tracing joins the lens: t = 1"
            );
            assert_eq!(s.from.vertex as u32 + 1, s.strategy.unwrap()[0]);
        }
    });
    assert!(n > 100, "{n} samples splatted");
    assert!(occluded > 5, "{occluded} blocked connections to the lens");
}

#[test]
fn bdpts_record_is_its_weighted_strategies() {
    let bdpt = Bdpt {
        max_depth: Some(5),
        ..Bdpt::default()
    };
    let mut strategies = std::collections::BTreeSet::new();
    let (mut occluded, mut occluded_lens, mut weighed) = (0, 0, 0);
    let n = check(&bdpt, |r| {
        for s in &r.segments {
            let [s_, t] = s.strategy.unwrap();
            strategies.insert((s_, t));
            if s.occluded {
                // Blocked: recorded, adds nothing, has no weight, lands nowhere.
                assert_eq!((s.mis_weight, s.contribution), (None, [0.0; 3]));
                assert_eq!((&s.strategy_weights, s.splat), (&None, None));
                occluded += 1;
                occluded_lens += usize::from(t == 1);
                continue;
            }
            let w = s.mis_weight.unwrap();
            assert!((0.0..=1.0).contains(&w), "MIS weight {w}");
            let all = s
                .strategy_weights
                .as_ref()
                .expect("every strategy's weight");
            strategy_weights_add_up(all, [s_, t], w);
            weighed += 1;
        }
        for v in r.paths.iter().flat_map(|p| &p.vertices) {
            if let (Some(w), Some(all)) = (v.mis_weight, &v.strategy_weights) {
                // A camera path that hit a light: strategy (0, t).
                strategy_weights_add_up(all, [0, all.len() as u32], w);
                weighed += 1;
            }
        }
    });
    assert!(n > 400, "{n}");
    assert!(
        weighed > 1000,
        "{weighed} contributions with every strategy's weight"
    );
    // Issue 27, bug 4: BDPT showed no blocked connection (0 of 70 segments
    // over 5 pixels) where the path tracer shows its blocked shadow rays;
    // and connections to the lens (t = 1) only when they contributed.
    assert!(occluded > 50, "{occluded} blocked connections recorded");
    assert!(
        occluded_lens > 5,
        "{occluded_lens} blocked connections to the lens"
    );
    for st in [(1, 2), (2, 2), (1, 3), (2, 1), (3, 1)] {
        assert!(
            strategies.contains(&st),
            "strategy {st:?} recorded: {strategies:?}"
        );
    }
}

/// Every strategy's weight for the path of strategy `(s, t)` (issue 27: the
/// inspector shows them): one per strategy `(i, s + t − i)`, `i < s + t`,
/// each in [0, 1]; strategy `s`'s is the weight the integrator used, bit for
/// bit; and they add up to 1. Each is one f32 division of a term by the same
/// total (that total itself a sum of at most `s + t` rounded terms), so the
/// sum is 1 within `2 (s + t)` units of 2⁻²⁴: 4e-6 allows up to 30 vertices.
fn strategy_weights_add_up(all: &[f32], [s, t]: [u32; 2], w: f32) {
    assert_eq!(all.len() as u32, s + t, "({s}, {t}): {all:?}");
    assert_eq!(
        all[s as usize].to_bits(),
        w.to_bits(),
        "({s}, {t}): {all:?}"
    );
    assert!(all.iter().all(|w| (0.0..=1.0).contains(w)), "{all:?}");
    let sum: f64 = all.iter().map(|&w| w as f64).sum();
    assert!(
        (sum - 1.0).abs() <= 4e-6,
        "({s}, {t}): {all:?} sum to {sum}"
    );
}

/// Issue 27, bug 5: BDPT's subpaths labelled every density "per area": the
/// pinhole's lens point and vertices behind glass as "0 per area", a point
/// light's position as "1 per area". They are discrete, as the path tracer
/// says: probability 1 on the lens, the light's choice probability, the
/// delta lobe's probability (Fresnel's share for glass).
#[test]
fn bdpts_densities_have_the_measure_of_how_the_vertex_was_chosen() {
    use raytracer::integrator::record::Measure;
    let mut scene = Scene::builtin("caustic").unwrap();
    scene.set_resolution(32, 32);
    let bdpt = Bdpt {
        max_depth: Some(6),
        ..Bdpt::default()
    };
    let (mut behind_delta, mut point_lights) = (0, 0);
    for y in 0..32 {
        for x in 0..32 {
            let (r, _) = record_sample(&bdpt, &scene, UVec2::new(x, y), 3, 0);
            for path in &r.paths {
                for (i, v) in path.vertices.iter().enumerate() {
                    // The escaped ray's end is no sampled vertex.
                    let Some(pdf) = v.pdf else { continue };
                    match (path.role, i, v.kind) {
                        (PathRole::Camera, 0, _) => {
                            assert_eq!((pdf.value, pdf.measure), (1.0, Measure::Discrete))
                        }
                        (PathRole::Light, 0, _) => {
                            assert_eq!(pdf.measure, Measure::Discrete, "the point light");
                            assert!(pdf.value > 0.0 && pdf.value <= 1.0, "{pdf:?}");
                            point_lights += 1;
                        }
                        _ if pdf.measure == Measure::Discrete => {
                            assert!(pdf.value > 0.0 && pdf.value <= 1.0, "{pdf:?}");
                            behind_delta += 1;
                        }
                        _ => assert!(
                            pdf.measure == Measure::Area && pdf.value > 0.0,
                            "{:?} vertex {i}: {pdf:?}",
                            path.role
                        ),
                    }
                }
            }
        }
    }
    assert!(
        point_lights > 100 && behind_delta > 100,
        "{point_lights} {behind_delta}"
    );
}

#[test]
fn naive_recursions_record_is_its_tree() {
    let naive = NaiveRecursive::new(vec![3], Some(3));
    let scene = cornell(16);
    let before = naive.rays_traced();
    let (record, _) = record_sample(&naive, &scene, UVec2::new(8, 8), 1, 0);
    let rays = naive.rays_traced() - before;
    let vertices: usize = record.paths.iter().map(|p| p.vertices.len()).sum();
    assert_eq!(vertices as u64, rays + 1, "the lens and one vertex per ray");
    assert_eq!(rays, 1 + 3 + 9, "every ray of the middle pixel hits a wall");
    assert!(
        record.paths[1..]
            .iter()
            .all(|p| p.role == PathRole::Branch && p.parent.is_some())
    );
    check(&naive, |_| {});
    // A tree past the cap is cut, and says so.
    let big = NaiveRecursive::new(vec![8], Some(5));
    let (record, _) = record_sample(&big, &scene, UVec2::new(8, 8), 1, 0);
    let vertices: usize = record.paths.iter().map(|p| p.vertices.len()).sum();
    assert_eq!(vertices, MAX_RECORDED_VERTICES);
    let note = record.truncated.expect("a truncated tree says so");
    assert!(note.contains("left out"), "{note}");
}
