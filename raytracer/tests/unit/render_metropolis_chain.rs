//! Unit tests of `render/metropolis/chain.rs`.

use raytracer::render::metropolis::chain::*;

#[test]
fn acceptance_and_weights_follow_metropolis() {
    assert_eq!(acceptance(2.0, 1.0), 0.5);
    assert_eq!(acceptance(1.0, 3.0), 1.0);
    assert_eq!(acceptance(0.0, 3.0), 1.0);
    assert_eq!(acceptance(2.0, 0.0), 0.0);
    let w = expected_value_splat(2.0, 1.0);
    assert_eq!(
        w,
        SplatWeights {
            current: 0.25,
            proposed: 0.5
        }
    );
    // One unit of luminance per step, shared by the two states.
    for (fx, fy) in [(2.0f32, 1.0f32), (0.5, 4.0), (3.0, 0.0), (0.0, 2.0)] {
        let w = expected_value_splat(fx, fy);
        assert!((w.current * fx + w.proposed * fy - 1.0).abs() < 1e-6);
    }
    let none = expected_value_splat(0.0, 0.0);
    assert_eq!((none.current, none.proposed), (0.0, 0.0));
}
