//! Unit tests of `watch.rs`.

use grading::watch::*;
use std::path::Path;
use std::time::{Duration, SystemTime};

#[test]
fn a_save_is_seen_once_and_mapped_to_its_exercise() {
    let dir = std::env::temp_dir().join(format!("grading-watch-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("ex05_cone_lobe.rs");
    std::fs::write(&file, "a").unwrap();
    let mut w = Watcher::new(vec![file.clone(), dir.join("missing.rs")]);
    assert!(w.changed().is_empty());
    // Make sure the new time differs even on coarse file systems.
    let later = SystemTime::now() + Duration::from_secs(5);
    std::fs::File::options()
        .write(true)
        .open(&file)
        .and_then(|f| f.set_modified(later))
        .unwrap();
    assert_eq!(w.changed(), vec![file.clone()]);
    assert!(w.changed().is_empty());
    let reg = exercises::registry();
    assert_eq!(exercise_of(&file, &reg).map(|e| e.number()), Some(Some(5)));
    assert!(exercise_of(&dir.join("notes.rs"), &reg).is_none());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_verdict_is_the_report_or_the_compiler_errors() {
    let v = verdict(b"Exercise 5 - x\n  passed\n", b"   Compiling exercises\n");
    assert!(v.starts_with("Exercise 5"), "{v}");
    let v = verdict("Задача 5 — x\n".as_bytes(), b"");
    assert!(v.starts_with("Задача 5"), "{v}");
    let v = lang::with(lang::Lang::En, || {
        verdict(
            b"",
            b"   Compiling exercises\nerror[E0308]: mismatched types\n --> exercises/src/ex05_cone_lobe.rs:3:5\n",
        )
    });
    assert!(
        v.contains("does not compile") && v.contains("error[E0308]") && !v.contains("Compiling"),
        "{v}"
    );
    let cmd = lang::with(lang::Lang::Bg, || {
        grade_command(Path::new("/tmp"), "ex05_cone_lobe")
    });
    let language = cmd.get_envs().find(|(k, _)| *k == lang::ENV);
    assert_eq!(language.and_then(|(_, v)| v), Some("bg".as_ref()));
    let args: Vec<_> = cmd
        .get_args()
        .map(|a| a.to_string_lossy().into_owned())
        .collect();
    assert_eq!(
        args,
        [
            "test",
            "-q",
            "-p",
            "grading",
            "--test",
            "exercises",
            "--",
            "ex05_cone_lobe"
        ]
    );
}
