//! Unit tests of `outcome.rs`.

use grading::outcome::*;

#[test]
fn todo_is_not_started_and_other_panics_fail() {
    let o = grade(|| todo!());
    assert!(o.is_not_started(), "{o}");
    let o = grade(|| panic!("index out of bounds"));
    assert!(
        matches!(&o, Outcome::Failed(r) if r.contains("index out of bounds")),
        "{o}"
    );
    assert_eq!(grade(|| Ok(())), Outcome::Passed);
    assert_eq!(grade(|| Err("x".into())), Outcome::Failed("x".into()));
}
