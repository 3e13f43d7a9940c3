//! Unit tests of `commands/bench/mitsuba.rs`.

use lesson11::commands::bench::mitsuba::*;
use std::path::Path;
use std::time::{Duration, Instant};

/// A peer that never ends is killed at its limit (0.3 s here; it sleeps
/// for 1000 s, so only the limit can end it this soon), with one line
/// saying so.
#[cfg(unix)]
#[test]
fn a_peer_that_hangs_is_killed_at_its_limit() {
    let start = Instant::now();
    let r = run_peer(Path::new("sleep"), &["1000"], Duration::from_millis(300));
    let seconds = start.elapsed().as_secs_f64();
    match r {
        Err(Unfinished::Failed(why)) => assert!(why.contains("did not finish within"), "{why}"),
        other => panic!("{other:?}"),
    }
    // Generous: the kill and the wait take milliseconds.
    assert!(seconds < 100.0, "{seconds} s");
    let ok = run_peer(Path::new("sh"), &["-c", "echo 1.5 M samples/s"], PEER_LIMIT).unwrap();
    assert_eq!(String::from_utf8_lossy(&ok.stdout), "1.5 M samples/s\n");
}
