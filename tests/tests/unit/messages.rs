//! Unit tests of `messages.rs`.

use grading::messages::*;
use lang::{self, Lang};

#[test]
fn a_missing_key_or_placeholder_is_named() {
    let en = parse("[a]\nx = \"x {n}\"\ny = \"y\"\n").unwrap();
    let bg = parse("[a]\nx = \"х {m}\"\nz = \"з\"\n").unwrap();
    let m = mismatches(&en, &bg);
    assert_eq!(m.len(), 3, "{m:?}");
    assert!(m[0].starts_with("a.x: placeholders"), "{m:?}");
    assert!(
        m[1].starts_with("a.y: missing in tests/messages/bg.toml"),
        "{m:?}"
    );
    assert!(
        m[2].starts_with("a.z: missing in tests/messages/en.toml"),
        "{m:?}"
    );
    assert!(mismatches(&en, &en).is_empty());
}

#[test]
fn a_message_is_filled_in_the_language_asked() {
    let n = 3;
    let en = lang::with(Lang::En, || {
        grading::tr!(
            "report.progress",
            done = 1,
            total = n,
            failing = 0,
            todo = 2
        )
    });
    let bg = lang::with(Lang::Bg, || {
        grading::tr!(
            "report.progress",
            done = 1,
            total = n,
            failing = 0,
            todo = 2
        )
    });
    assert_eq!(en, "Progress: 1/3 done, 0 failing, 2 not started.");
    assert!(bg.starts_with("Напредък: 1/3 готови"), "{bg}");
    assert_eq!(
        keys_in_source("x tr!(\n \"a.b\", n) tr!(\"c.d\")"),
        ["a.b", "c.d"]
    );
    let ((), keys) = keys_used(|| {
        grading::tr!("report.last");
    });
    assert_eq!(keys, ["report.last"]);
}
