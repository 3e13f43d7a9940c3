//! Unit tests of `commands/lab/query.rs`.

use lesson11::commands::lab::query::*;

#[test]
fn reads_checks_and_explains() {
    let q = Query::parse("spp=64&scene=my%20room.toml&x=+1", &["spp", "scene", "x"]).unwrap();
    assert_eq!(q.get("scene"), Some("my room.toml"));
    assert_eq!(q.number::<u32>("spp", 1), Ok(64));
    assert_eq!(q.number::<i32>("x", 0), Ok(1));
    assert_eq!(q.number::<u32>("missing", 7), Ok(7));
    let e = |q: &str| Query::parse(q, &["a", "page"]).unwrap_err();
    assert!(e("b=1").starts_with("unknown parameter `b`"));
    assert!(e("a=1&a=2").contains("twice"));
    assert!(e("a=%zz").contains("%-escape"));
    assert!(e("a=%ff").contains("UTF-8"));
    assert!(e(&"a".repeat(5000)).contains("more than"));
    let q = Query::parse("a=nan&page=x/y", &["a", "page"]).unwrap();
    assert!(
        q.in_range("a", 0.0, 0.0..=1.0)
            .unwrap_err()
            .contains("[0, 1]")
    );
    assert!(q.page().unwrap_err().contains("letters"));
    assert!(q.flag("a").is_err());
}
