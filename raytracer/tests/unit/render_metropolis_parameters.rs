//! Unit tests of `render/metropolis/parameters.rs`.

use raytracer::render::metropolis::parameters::*;

#[test]
fn bad_parameters_are_named() {
    let ok = Metropolis::default();
    assert_eq!(ok.check(1000), Ok(()));
    let with = |f: fn(&mut Metropolis)| {
        let mut m = ok.clone();
        f(&mut m);
        m
    };
    let cases = [
        (
            with(|m| m.large_step_probability = 1.5),
            "large_step_probability",
            "must be in [0, 1]",
        ),
        (
            with(|m| m.large_step_probability = f32::NAN),
            "large_step_probability",
            "got NaN",
        ),
        (
            with(|m| m.large_step_probability = -0.1),
            "large_step_probability",
            "got -0.1",
        ),
        (
            with(|m| m.mutation_size = -0.01),
            "mutation_size",
            "must be in (0, 1]",
        ),
        (with(|m| m.mutation_size = 0.0), "mutation_size", "got 0"),
        (with(|m| m.chains = 0), "chains", "at least 1"),
        (
            with(|m| m.chains = 2000),
            "chains",
            "only 1000 mutations in all",
        ),
        (
            with(|m| m.bootstrap = Some(0)),
            "bootstrap",
            "at least 1 path",
        ),
    ];
    for (m, field, reason) in cases {
        let e = m.check(1000).unwrap_err();
        assert_eq!(e.field, field, "{m:?}");
        assert!(e.reason.contains(reason), "{m:?}: {e}");
    }
}
