//! Unit tests of `integrator/stop.rs`.

use raytracer::integrator::stop::*;
use std::sync::atomic::{AtomicBool, Ordering};

#[test]
fn the_flag_is_seen_only_inside_watch_and_marks_the_sample() {
    let flag = AtomicBool::new(false);
    assert!(!stop_requested());
    watch(&flag, || {
        assert!(!stop_requested());
        assert!(!take_abandoned());
        flag.store(true, Ordering::Relaxed);
        assert!(stop_requested());
        assert!(take_abandoned());
        assert!(!take_abandoned());
        // A nested render with its own flag, then back to ours.
        let other = AtomicBool::new(false);
        watch(&other, || assert!(!stop_requested()));
        assert!(stop_requested());
        take_abandoned();
    });
    assert!(!stop_requested());
    assert!(!take_abandoned());
}
