//! Unit tests of `commands/lab/settings.rs`.

use lesson11::commands::lab::query::Query;
use lesson11::commands::lab::settings::*;
use lesson11::integrators::IntegratorPlan;
use raytracer::render::RenderOptions;

/// Naive recursion over the command line's ray budget is refused with
/// its message (N = 8 at max depth 12: 8¹¹ rays per sample).
#[test]
fn the_lab_refuses_the_naive_renders_the_command_line_refuses() {
    crate::english();
    let Err(e) = setup("integrator=naive&width=64&height=64&spp=16&max-depth=12") else {
        panic!("accepted");
    };
    assert!(e.contains("more than the budget"), "{e}");
    assert!(setup("integrator=naive&width=64&height=64&spp=16&max-depth=3").is_ok());
}

/// A symbolic link in the scenes folder is neither listed nor loaded,
/// whether it leads out of the folder or not (`lab --scenes DIR`
/// followed one to a file outside DIR and sent its values to the page).
#[cfg(unix)]
#[test]
fn links_in_the_scenes_folder_are_not_followed() {
    crate::english();
    let root = std::env::temp_dir().join(format!("lab-links-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&root);
    let dir = root.join("scenes");
    std::fs::create_dir_all(&dir).unwrap();
    let outside = root.join("secret.toml");
    std::fs::write(&outside, "secret = \"do not show\"\n").unwrap();
    std::fs::write(dir.join("room.toml"), "# a scene\n").unwrap();
    std::os::unix::fs::symlink(&outside, dir.join("evil.toml")).unwrap();
    std::os::unix::fs::symlink(dir.join("room.toml"), dir.join("alias.toml")).unwrap();
    let folder = SceneFolder(Some(dir.clone()));
    let names: Vec<String> = folder.list().into_iter().map(|s| s.name).collect();
    assert!(names.contains(&"room.toml".to_string()), "{names:?}");
    assert!(
        !names.iter().any(|n| n == "evil.toml" || n == "alias.toml"),
        "{names:?}"
    );
    assert!(folder.resolve("room.toml").is_ok());
    for link in ["evil.toml", "alias.toml"] {
        let e = folder.resolve(link).unwrap_err();
        assert!(
            e.starts_with("unknown scene") && !e.contains("do not show"),
            "{e}"
        );
    }
    std::fs::remove_dir_all(&root).ok();
}

fn setup(query: &str) -> Result<RenderSetup, String> {
    let mut allowed = RENDER_PARAMS.to_vec();
    allowed.push("page");
    let q = Query::parse(query, &allowed)?;
    render_setup(&q, &SceneFolder::default(), "cornell", "path")
}

#[test]
fn the_query_is_read_as_lesson11_render_reads_its_options() {
    let s = setup("spp=8&seed=3&max-depth=-1&width=32&height=24").unwrap();
    assert_eq!((s.options.spp, s.options.seed), (8, 3));
    assert_eq!((s.scene.camera.width, s.scene.camera.height), (32, 24));
    let IntegratorPlan::Ready(integrator) = &s.plan else {
        panic!("path tracing is ready at once")
    };
    assert_eq!(integrator.name(), "path");
    assert_eq!(
        s.options_line,
        "--scene cornell --integrator path --height 24 --max-depth -1 --seed 3 --spp 8 --width 32"
    );
    assert_eq!(s.options.tile_size, RenderOptions::default().tile_size);
}

#[test]
fn bad_settings_get_the_commands_reasons_in_one_line() {
    crate::english();
    for (query, reason) in [
        (
            "spp=abc",
            "“Target spp”: \"abc\" is not valid (invalid digit",
        ),
        ("seed=-1", "“Seed”: \"-1\" is not valid"),
        ("spp=0", "“Target spp” must be at least 1"),
        ("spp=100000", "at most 65536"),
        ("integrator=magic", "“Integrator”: \"magic\" is not valid"),
        ("integrator=direct&max-depth=5", "D = 2 by definition"),
        ("max-depth=0", "“Max depth D” must be -1"),
        ("width=1000&height=1000", "more than the lab's"),
        ("width=100000&height=100000", "more than the cap"),
        ("scene=../../etc/passwd", "unknown scene"),
        ("scene=/etc/passwd.toml", "unknown scene"),
        ("roulette=maybe", "`roulette` must be 1 or 0"),
    ] {
        let e = setup(query)
            .err()
            .unwrap_or_else(|| panic!("{query} accepted"));
        assert!(e.contains(reason), "{query}: {e}");
        assert!(!e.contains('\n'), "{query}: {e}");
    }
}

/// Issue 27, bug 2: the advice for unlimited naive recursion named
/// `--roulette`, which the page did not have. Its words are now the
/// page's fields, and following it renders.
#[test]
fn the_advice_for_unlimited_naive_recursion_can_be_followed_on_the_page() {
    crate::english();
    let base = "integrator=naive&width=16&height=16&spp=1&max-depth=-1";
    let Err(e) = setup(&format!("{base}&branching=8,1")) else {
        panic!("accepted")
    };
    assert!(
        e.contains("“Russian roulette”") && e.contains("“Branching N”") && !e.contains("--"),
        "{e}"
    );
    assert!(setup(&format!("{base}&branching=8,1&roulette=1")).is_ok());
}

#[test]
fn a_folder_offers_its_toml_files_and_nothing_else() {
    let dir = std::env::temp_dir().join(format!("lab-scenes-{}", std::process::id()));
    std::fs::create_dir_all(dir.join("sub.toml")).unwrap();
    std::fs::write(
        dir.join("mine.toml"),
        raytracer::scene::builtin("furnace").unwrap().toml,
    )
    .unwrap();
    std::fs::write(dir.join("notes.txt"), "").unwrap();
    let folder = SceneFolder(Some(dir.clone()));
    let names: Vec<String> = folder.list().into_iter().map(|s| s.name).collect();
    assert!(names.ends_with(&["mine.toml".to_string()]), "{names:?}");
    assert!(names.contains(&"cornell".to_string()));
    assert!(folder.resolve("mine.toml").unwrap().ends_with("mine.toml"));
    for bad in ["notes.txt", "sub.toml", "../mine.toml", ".hidden.toml"] {
        assert!(folder.resolve(bad).is_err(), "{bad}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
