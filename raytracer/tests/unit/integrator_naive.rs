//! Unit tests of `integrator/naive.rs`.

use raytracer::integrator::naive::*;

/// A recursion that nothing ends is refused by the library, not only by
/// the command line: unlimited depth without roulette or cutoff (it
/// never returned, `NaiveRecursive::new(_, None)` was accepted), roulette
/// alone over a repeating split (a tree that never stops growing), the
/// cutoff alone without one (a white wall keeps the product at 1).
#[test]
fn a_recursion_without_end_is_refused() {
    for (branching, roulette, cutoff) in [
        (vec![4], None, None),
        (vec![1], None, None),
        (vec![16, 4, 2], Some(1), None),
        (vec![8], Some(5), None),
        (vec![4, 1], None, Some(0.01)),
    ] {
        let e = NaiveRecursive::try_new(branching.clone(), None, roulette, cutoff).unwrap_err();
        assert!(
            e.contains("never ends"),
            "{branching:?} {roulette:?} {cutoff:?}: {e}"
        );
    }
    assert!(std::panic::catch_unwind(|| NaiveRecursive::new(vec![4], None)).is_err());
    for (branching, roulette, cutoff) in [
        (vec![16, 4, 1], Some(1), None),
        (vec![1], Some(5), None),
        (vec![4, 2], None, Some(0.01)),
        (vec![8], Some(3), Some(0.1)),
    ] {
        NaiveRecursive::try_new(branching.clone(), None, roulette, cutoff)
            .unwrap_or_else(|e| panic!("{branching:?} {roulette:?} {cutoff:?}: {e}"));
    }
    // A finite depth always ends.
    NaiveRecursive::try_new(vec![8], Some(4), None, None).unwrap();
    for bad in [vec![], vec![2, 0]] {
        assert!(NaiveRecursive::try_new(bad, Some(3), None, None).is_err());
    }
    for bad in [-1.0, f32::NAN, f32::INFINITY] {
        assert!(NaiveRecursive::try_new(vec![2], Some(3), None, Some(bad)).is_err());
    }
}
