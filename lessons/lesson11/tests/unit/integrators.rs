//! Unit tests of `integrators.rs`.

use anyhow::Result;
use lesson11::integrators::*;
use raytracer::integrator::Integrator;
use raytracer::render::RenderOptions;
use raytracer::scene::Scene;

fn build(
    kind: IntegratorKind,
    args: &IntegratorArgs,
    spp: u32,
) -> Result<Box<dyn Integrator + Send>> {
    let scene = Scene::builtin("cornell").unwrap();
    let options = RenderOptions {
        spp,
        ..RenderOptions::default()
    };
    kind.build(args, &scene, &options, false)
}

#[test]
fn unused_and_meaningless_options_are_refused() {
    use IntegratorKind::*;
    let with = |f: fn(&mut IntegratorArgs)| {
        let mut a = IntegratorArgs::default();
        f(&mut a);
        a
    };
    let cases: [(IntegratorKind, IntegratorArgs, &str); 9] = [
        (
            Direct,
            with(|a| a.max_depth = Some(5)),
            "D = 2 by definition",
        ),
        (
            Ao,
            with(|a| a.rr_depth = Some(5)),
            "--rr-depth does not apply",
        ),
        (
            Path,
            with(|a| a.branching = vec![4]),
            "--branching does not apply",
        ),
        (
            Path,
            with(|a| a.cutoff = Some(0.1)),
            "--cutoff does not apply",
        ),
        (
            Bdpt,
            with(|a| a.ao_distance = Some(1.0)),
            "--ao-distance does not apply",
        ),
        (
            Naive,
            with(|a| a.cutoff = Some(f32::NAN)),
            "--cutoff must be",
        ),
        (Naive, with(|a| a.cutoff = Some(-1.0)), "--cutoff must be"),
        (
            Ao,
            with(|a| a.ao_distance = Some(0.0)),
            "--ao-distance must be",
        ),
        (
            Path,
            with(|a| a.max_depth = Some(0)),
            "--max-depth must be -1",
        ),
    ];
    for (kind, args, expected) in cases {
        let e = build(kind, &args, 1).err().expect("refused").to_string();
        assert!(e.contains(expected), "{kind:?} {args:?}: {e}");
    }
}

#[test]
fn max_depth_follows_the_scene_files_rule() {
    use IntegratorKind::*;
    let scene = Scene::builtin("cornell").unwrap();
    let depth = |kind, d: Option<i64>, roulette| {
        let args = IntegratorArgs {
            max_depth: d,
            roulette,
            ..IntegratorArgs::default()
        };
        args.max_depth(kind, &scene).map_err(|e| e.to_string())
    };
    for bad in [0, -2, 65_536, 70_000] {
        let e = depth(Path, Some(bad), false).unwrap_err();
        assert!(e.starts_with("--max-depth must be -1 (unlimited)"), "{e}");
    }
    assert_eq!(depth(Path, Some(-1), false), Ok(None));
    assert_eq!(depth(Path, Some(65_535), false), Ok(Some(65_535)));
    // The Cornell box's own depth is unlimited.
    assert_eq!(depth(Path, None, false), Ok(None));
    assert_eq!(depth(Naive, None, false), Ok(Some(4)));
    assert!(
        depth(Naive, Some(-1), false)
            .unwrap_err()
            .contains("never ends")
    );
    assert_eq!(depth(Naive, Some(-1), true), Ok(None));
}

#[test]
fn naive_recursion_stays_within_its_ray_budget() {
    crate::english();
    let args = IntegratorArgs {
        branching: vec![1000],
        ..IntegratorArgs::default()
    };
    let e = build(IntegratorKind::Naive, &args, 4)
        .err()
        .unwrap()
        .to_string();
    assert!(
        e.contains("more than the budget") && e.contains("--force"),
        "{e}"
    );
    // N = 8, D = 4: 585 rays per sample, 3.8e7 for 256×256 at 1 spp.
    assert!(build(IntegratorKind::Naive, &IntegratorArgs::default(), 1).is_ok());
}
