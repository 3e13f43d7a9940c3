//! The `lesson11` program as a student meets it: the tour writes what its
//! page links, and bad input gets a one-line error that says what to do.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn lesson11(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_lesson11"))
        .args(args)
        .output()
        .expect("lesson11 runs")
}

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("lesson11-cli-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Every `src="…"` and `href="…"` of the page names a file that exists.
fn assert_links_exist(page: &Path) {
    let html = std::fs::read_to_string(page).unwrap();
    let root = page.parent().unwrap();
    let mut links = 0;
    for attr in ["src=\"", "href=\""] {
        for part in html.split(attr).skip(1) {
            let link = &part[..part.find('"').unwrap()];
            assert!(
                root.join(link).is_file(),
                "{} links to missing {link}",
                page.display()
            );
            links += 1;
        }
    }
    assert!(
        links >= 10,
        "the page should show the pictures, found {links} links"
    );
}

#[test]
fn the_tour_writes_every_picture_its_page_shows() {
    let out = temp_dir("tour");
    let o = lesson11(&["tour", "--quality", "tiny", "--out", out.to_str().unwrap()]);
    assert!(o.status.success(), "tour failed: {}", stderr(&o));
    assert_links_exist(&out.join("index.html"));
    let csv = std::fs::read_to_string(out.join("04-rendering-equation/naive-rays.csv")).unwrap();
    assert!(csv.starts_with("N (branching),max depth D,"), "{csv}");
    assert_eq!(csv.lines().count(), 10, "a header and 9 rows");
    let compare = std::fs::read_to_string(out.join("08-compare/equal-time.csv")).unwrap();
    assert!(
        compare.starts_with("scene,algorithm,spp,seconds,RMSE\n"),
        "{compare}"
    );
    for algorithm in [
        "naive",
        "path (MIS)",
        "path (BRDF only)",
        "light",
        "bidirectional",
        "Metropolis (over bidirectional)",
    ] {
        assert!(
            compare.contains(algorithm),
            "the comparison misses {algorithm}"
        );
    }
    std::fs::remove_dir_all(&out).ok();
}

#[test]
fn render_writes_png_exr_and_variance() {
    let out = temp_dir("render");
    let o = lesson11(&[
        "render",
        "--scene",
        "cornell",
        "--integrator",
        "path",
        "--width",
        "8",
        "--height",
        "6",
        "--spp",
        "2",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    for f in [
        "cornell-path.png",
        "cornell-path.exr",
        "cornell-path-variance.exr",
    ] {
        assert!(out.join(f).is_file(), "{f} missing");
    }
    std::fs::remove_dir_all(&out).ok();
}

/// Metropolis light transport writes the same three files; a render this
/// small (48 mutations) runs with one chain per mutation.
#[test]
fn render_mlt_writes_png_exr_and_the_chains_variance() {
    let out = temp_dir("render-mlt");
    let o = lesson11(&[
        "render",
        "--scene",
        "door",
        "--integrator",
        "mlt",
        "--width",
        "8",
        "--height",
        "6",
        "--spp",
        "1",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(
        said.contains("Metropolis: b = ") && said.contains("48 chains"),
        "{said}"
    );
    for f in ["door-mlt.png", "door-mlt.exr", "door-mlt-variance.exr"] {
        assert!(out.join(f).is_file(), "{f} missing");
    }
    std::fs::remove_dir_all(&out).ok();
}

#[test]
fn an_unknown_scene_lists_the_available_ones() {
    let o = lesson11(&["render", "--scene", "cornel", "--spp", "1"]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains("cornel") && e.contains("cornell") && e.contains("furnace"),
        "{e}"
    );
    assert!(!e.contains("panicked"), "{e}");
}

#[test]
fn bad_sizes_and_counts_are_one_line_errors() {
    for args in [["--width", "0"], ["--spp", "0"], ["--threads", "0"]] {
        let mut all = vec!["render", "--scene", "cornell"];
        all.extend(args);
        let o = lesson11(&all);
        assert!(!o.status.success(), "{args:?} was accepted");
        let e = stderr(&o);
        assert!(
            e.starts_with("error:") && e.trim().lines().count() == 1 && e.contains(args[0]),
            "{args:?}: {e}"
        );
    }
}

#[test]
fn a_broken_scene_file_names_file_line_and_field() {
    let dir = temp_dir("broken");
    let path = dir.join("broken.toml");
    std::fs::write(
        &path,
        "[camera]\nposition = [0, 0, 5]\nlook_at = [0, 0, 0]\nfov = \"wide\"\n",
    )
    .unwrap();
    let o = lesson11(&["render", "--scene", path.to_str().unwrap(), "--spp", "1"]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(e.contains("broken.toml:4:") && e.contains("fov"), "{e}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_written_builtin_scene_renders_from_its_file() {
    let dir = temp_dir("scenes");
    let o = lesson11(&["scenes", "--write", "stereo", "--to", dir.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let file = dir.join("stereo.toml");
    assert!(file.is_file() && dir.join("torus.obj").is_file());
    let o = lesson11(&[
        "render",
        "--scene",
        file.to_str().unwrap(),
        "--width",
        "8",
        "--height",
        "8",
        "--spp",
        "1",
        "--out",
        dir.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(dir.join("stereo-direct.png").is_file());
    let o = lesson11(&["scenes"]);
    let listing = String::from_utf8_lossy(&o.stdout);
    for name in [
        "cornell",
        "furnace",
        "white-furnace",
        "caustic",
        "door",
        "stereo",
        "brdf-gallery",
    ] {
        assert!(
            listing.contains(name),
            "`lesson11 scenes` does not list {name}"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn every_chapter_is_a_subcommand_and_runs_alone() {
    let chapters = [
        "stereo",
        "gi-effects",
        "brdf",
        "rendering-equation",
        "path",
        "light",
        "bdpt",
        "compare",
    ];
    for chapter in chapters {
        let o = lesson11(&[chapter, "--help"]);
        assert!(
            o.status.success(),
            "`lesson11 {chapter} --help` failed: {}",
            stderr(&o)
        );
    }
    let out = temp_dir("chapter");
    let o = lesson11(&[
        "rendering-equation",
        "--quality",
        "tiny",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_links_exist_at_least(&out.join("rendering-equation.html"), 2);
    std::fs::remove_dir_all(&out).ok();
}

fn assert_links_exist_at_least(page: &Path, minimum: usize) {
    let html = std::fs::read_to_string(page).unwrap();
    let links: Vec<&str> = html
        .split("src=\"")
        .skip(1)
        .map(|p| &p[..p.find('"').unwrap()])
        .collect();
    assert!(
        links.len() >= minimum,
        "{} shows {} pictures",
        page.display(),
        links.len()
    );
    for link in links {
        assert!(
            page.parent().unwrap().join(link).is_file(),
            "missing {link}"
        );
    }
}
