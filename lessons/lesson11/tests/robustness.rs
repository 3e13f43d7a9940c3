//! The `lesson11` program against a hostile user: whatever the command line,
//! the scene file or the signal, no panic, no abort, no hang and no lost
//! file (issue 14). Every case spawns the real binary in a fresh folder that
//! already holds the files of an earlier, good render, and checks the exit
//! code, the one-line message, and that no file was created, changed or
//! truncated. Renders are tiny: the whole suite takes seconds.

use std::collections::BTreeMap;
use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

const EXE: &str = env!("CARGO_BIN_EXE_lesson11");

/// A fresh folder for one case, with a good earlier render in `out/` (the
/// files a refused command must leave as they are).
fn folder(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("lesson11-robust-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let o = run(
        &dir,
        &[
            "render", "--width", "6", "--height", "4", "--spp", "1", "--out", "out",
        ],
    );
    assert!(
        o.status.success(),
        "the earlier render failed: {}",
        text(&o.stderr)
    );
    dir
}

fn run(dir: &Path, args: &[&str]) -> Output {
    Command::new(EXE)
        .args(args)
        .current_dir(dir)
        .output()
        .expect("lesson11 runs")
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// Every file under `dir` with its bytes.
fn files(dir: &Path) -> BTreeMap<PathBuf, Vec<u8>> {
    let mut all = BTreeMap::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for entry in std::fs::read_dir(&d).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
            } else if path.is_file() {
                let bytes = std::fs::read(&path).unwrap();
                all.insert(path.strip_prefix(dir).unwrap().to_path_buf(), bytes);
            }
        }
    }
    all
}

/// Runs `args` in a folder with an earlier render (plus `setup`'s files)
/// and checks that it is refused: exit code 1 (not a panic's 101, not a
/// signal), exactly one line on stderr, `error: …` containing `expected`,
/// and every file as it was. Returns stdout.
fn refused_with_setup(name: &str, args: &[&str], expected: &str, setup: impl Fn(&Path)) -> String {
    let dir = folder(name);
    setup(&dir);
    let before = files(&dir);
    let start = Instant::now();
    let o = run(&dir, args);
    let seconds = start.elapsed().as_secs_f64();
    let err = text(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{args:?}: {err}");
    assert!(
        err.starts_with("error: ") && err.trim_end().lines().count() == 1,
        "{args:?}: not one line: {err}"
    );
    assert!(
        err.contains(expected),
        "{args:?}: {err}\nexpected: {expected}"
    );
    assert!(!err.contains("panicked"), "{args:?}: {err}");
    assert!(
        files(&dir) == before,
        "{args:?} changed the files of {}",
        dir.display()
    );
    // Refused before any work: no render took place.
    assert!(seconds < 5.0, "{args:?} took {seconds} s");
    std::fs::remove_dir_all(&dir).ok();
    text(&o.stdout)
}

fn refused(name: &str, args: &[&str], expected: &str) -> String {
    refused_with_setup(name, args, expected, |_| {})
}

/// A scene file `s.toml`: a lit sphere, with `extra` appended.
fn scene_file(extra: &'static str) -> impl Fn(&Path) {
    move |dir: &Path| {
        let text = format!(
            "[camera]\nposition = [0, 0, 5]\nlook_at = [0, 0, 0]\nfov = 40\n\n\
             [materials.m]\ntype = \"lambert\"\nalbedo = 0.5\n\n\
             [[shapes]]\ntype = \"sphere\"\ncenter = [0, 0, 0]\nradius = 1\nmaterial = \"m\"\n\n\
             [environment]\nradiance = 1\n{extra}"
        );
        std::fs::write(dir.join("s.toml"), text).unwrap();
    }
}

const TINY: [&str; 6] = ["--width", "8", "--height", "6", "--spp", "1"];

fn tiny(args: &[&'static str]) -> Vec<&'static str> {
    let mut all = args.to_vec();
    all.extend(TINY);
    all.extend(["--out", "out"]);
    all
}

// ---- Crashes: memory is estimated before it is allocated. ----

#[test]
fn images_too_big_for_memory_are_refused() {
    let args = [
        "render", "--width", "100000", "--height", "100000", "--spp", "4", "--out", "out",
    ];
    refused(
        "huge",
        &args,
        "a 100000×100000 render needs about 1332 GiB of memory",
    );
    let args = [
        "render",
        "--width",
        "4294967295",
        "--height",
        "4294967295",
        "--spp",
        "1",
    ];
    refused("overflow", &args, "needs more than 2^64 bytes");
    refused_with_setup(
        "huge-file",
        &["render", "--scene", "s.toml", "--spp", "1", "--out", "out"],
        "a 100000×100000 render needs about",
        scene_file("[render]\nwidth = 100000\nheight = 100000\n"),
    );
    let args = [
        "stereo",
        "--width",
        "32",
        "--height",
        "32",
        "--spp",
        "4",
        "--lf-views",
        "100000",
    ];
    refused(
        "light-field",
        &args,
        "a light field of 100000×100000 views of 16×16 needs about",
    );
}

#[test]
fn mesh_files_are_read_only_if_they_are_small_regular_files() {
    let mesh = |file: &'static str| {
        let shape: &'static str = Box::leak(
            format!("[[shapes]]\ntype = \"mesh\"\nfile = \"{file}\"\nmaterial = \"m\"\n")
                .into_boxed_str(),
        );
        scene_file(shape)
    };
    let args = tiny(&["render", "--scene", "s.toml"]);
    // 300 MiB without a newline (a sparse file: nothing is written to disk).
    refused_with_setup(
        "mesh-huge",
        &args,
        "more than the 256 MiB a mesh file may have",
        |d| {
            mesh("huge.obj")(d);
            std::fs::File::create(d.join("huge.obj"))
                .unwrap()
                .set_len(300 << 20)
                .unwrap();
        },
    );
    refused_with_setup(
        "mesh-dir",
        &args,
        "s.toml:20:8: shapes[1].file: the mesh file",
        |d| {
            mesh("folder.obj")(d);
            std::fs::create_dir(d.join("folder.obj")).unwrap();
        },
    );
    refused_with_setup(
        "mesh-dir2",
        &args,
        "folder.obj is a folder, not a file",
        |d| {
            mesh("folder.obj")(d);
            std::fs::create_dir(d.join("folder.obj")).unwrap();
        },
    );
    if Path::new("/dev/zero").exists() {
        refused_with_setup(
            "mesh-dev",
            &args,
            "/dev/zero is not a regular file",
            mesh("/dev/zero"),
        );
    }
}

#[test]
fn scene_files_are_read_only_if_they_are_small_regular_files() {
    if Path::new("/dev/zero").exists() {
        let args = tiny(&["render", "--scene", "/dev/zero"]);
        refused("scene-dev", &args, "/dev/zero: is not a regular file");
    }
    refused_with_setup(
        "scene-dir",
        &tiny(&["render", "--scene", "./folder"]),
        "./folder: is a folder, not a scene file",
        |d| std::fs::create_dir(d.join("folder")).unwrap(),
    );
    refused_with_setup(
        "scene-huge",
        &tiny(&["render", "--scene", "huge.toml"]),
        "huge.toml: has 300 MiB; a scene file may have at most 16 MiB",
        |d| {
            let f = std::fs::File::create(d.join("huge.toml")).unwrap();
            f.set_len(300 << 20).unwrap();
        },
    );
}

/// A folder where a picture should go is found before the render, and the
/// picture's other files are left as they were.
#[test]
fn a_folder_in_the_way_of_a_picture_is_found_before_rendering() {
    refused_with_setup(
        "folder-in-the-way",
        &tiny(&["render"]),
        "cannot write out/cornell-direct-variance.exr: a folder has that name",
        |d| {
            let variance = d.join("out/cornell-direct-variance.exr");
            std::fs::remove_file(&variance).unwrap();
            std::fs::create_dir(&variance).unwrap();
        },
    );
}

// ---- Hangs and runaway resources. ----

#[test]
fn naive_recursion_states_its_rays_and_keeps_to_its_budget() {
    let args = [
        "render",
        "--integrator",
        "naive",
        "--branching",
        "1000",
        "--width",
        "32",
        "--height",
        "32",
        "--spp",
        "4",
        "--out",
        "out",
    ];
    let stdout = refused("naive-budget", &args, "more than the budget of 1e10");
    assert!(
        stdout.contains("at most 1001001001 rays per sample"),
        "{stdout}"
    );
    refused(
        "threads",
        &tiny(&["render", "--threads", "100000"]),
        "--threads 100000 is more than",
    );
}

/// Starts `args` in `dir`, waits for `ready` on stdout, sends `signal`, and
/// returns the output and the seconds from the signal to the exit.
#[cfg(unix)]
fn signalled(dir: &Path, args: &[&str], ready: &str, signal: &str) -> (Output, f64) {
    let mut child = Command::new(EXE)
        .args(args)
        .current_dir(dir)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut stdout = BufReader::new(child.stdout.take().unwrap());
    let mut seen = String::new();
    while !seen.contains(ready) {
        let mut line = String::new();
        assert!(
            stdout.read_line(&mut line).unwrap() > 0,
            "no `{ready}` in {seen}"
        );
        seen += &line;
    }
    // Let the render start its samples.
    std::thread::sleep(Duration::from_millis(300));
    let start = Instant::now();
    let kill = Command::new("kill")
        .args([signal, &child.id().to_string()])
        .status()
        .unwrap();
    assert!(kill.success());
    let mut o = child.wait_with_output().unwrap();
    let seconds = start.elapsed().as_secs_f64();
    std::io::Read::read_to_end(&mut stdout, &mut o.stdout).unwrap();
    seen.push_str(&text(&o.stdout));
    o.stdout = seen.into_bytes();
    (o, seconds)
}

/// Naive recursion with 10⁹ rays per sample: Ctrl-C ends it within a second
/// (inside the sample), and no black picture replaces the earlier one.
#[cfg(unix)]
#[test]
fn ctrl_c_stops_even_inside_a_huge_sample() {
    let dir = folder("ctrl-c");
    let before = files(&dir);
    let args = [
        "render",
        "--integrator",
        "naive",
        "--branching",
        "1000",
        "--force",
        "--width",
        "4",
        "--height",
        "4",
        "--spp",
        "1",
        "--out",
        "out",
    ];
    let (o, seconds) = signalled(&dir, &args, "rays per sample", "-INT");
    assert!(seconds < 1.0, "took {seconds} s to stop");
    assert_eq!(o.status.code(), Some(1));
    let out = text(&o.stdout);
    assert!(
        out.contains("interrupted before any sample was computed; nothing written"),
        "{out}"
    );
    assert!(files(&dir) == before);
    std::fs::remove_dir_all(&dir).ok();
}

/// SIGTERM and SIGHUP stop a render as Ctrl-C does: what was computed is
/// written, and stdout says how much that is.
#[cfg(unix)]
#[test]
fn sigterm_and_sighup_keep_what_was_computed() {
    for signal in ["-TERM", "-HUP", "-INT"] {
        let dir = folder(&format!("signal{signal}"));
        let args = [
            "render",
            "--integrator",
            "bdpt",
            "--width",
            "16",
            "--height",
            "16",
            "--spp",
            "1000000",
            "--out",
            "out",
        ];
        let (o, seconds) = signalled(&dir, &args, "", signal);
        assert!(seconds < 2.0, "{signal}: took {seconds} s to stop");
        assert_eq!(o.status.code(), Some(1), "{signal}: {}", text(&o.stderr));
        let out = text(&o.stdout);
        assert!(
            out.contains("INTERRUPTED after ")
                && out.contains(" of 256000000 samples")
                && out.contains("have no sample"),
            "{signal}: {out}"
        );
        assert!(!out.contains("1000000 spp,"), "{signal}: {out}");
        let err = text(&o.stderr);
        assert!(
            err.trim_end()
                .ends_with("what was rendered so far is in out/cornell-bdpt.exr"),
            "{err}"
        );
        let png = image_size(&dir.join("out/cornell-bdpt.png"));
        assert_eq!(png, (16, 16));
        std::fs::remove_dir_all(&dir).ok();
    }
}

fn image_size(png: &Path) -> (u32, u32) {
    let bytes = std::fs::read(png).unwrap();
    assert_eq!(&bytes[1..4], b"PNG");
    let be = |i: usize| u32::from_be_bytes(bytes[i..i + 4].try_into().unwrap());
    (be(16), be(20))
}

// ---- Lost or corrupt files. ----

/// kill -9 while the files of a render are being replaced: the previous
/// files stay whole. The rerun has the same seed, so its files have the
/// same bytes (PNG and EXR are deterministic): any other content would be a
/// truncated or half-written file. The kill lands as soon as the first,
/// second or third new file appears (or, if the files were written in
/// place, as soon as one of them changes).
#[test]
fn kill_9_during_a_rewrite_leaves_the_previous_files_whole() {
    let dir = folder("kill-9");
    let args = [
        "render",
        "--integrator",
        "ao",
        "--width",
        "512",
        "--height",
        "512",
        "--spp",
        "1",
        "--seed",
        "5",
        "--out",
        "big",
    ];
    assert!(run(&dir, &args).status.success());
    let big = dir.join("big");
    let good = files(&big);
    assert_eq!(good.len(), 3);
    let stat = |p: &Path| {
        std::fs::metadata(p)
            .ok()
            .map(|m| (m.len(), m.modified().ok()))
    };
    let targets: Vec<_> = good.keys().map(|k| big.join(k)).collect();
    let states: Vec<_> = targets.iter().map(|p| stat(p)).collect();
    let mut killed_while_writing = 0;
    for nth in 1..=3 {
        let mut child = Command::new(EXE)
            .args(args)
            .current_dir(&dir)
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        let start = Instant::now();
        let mut temps_seen = std::collections::BTreeSet::new();
        loop {
            for entry in std::fs::read_dir(&big).unwrap().flatten() {
                let name = entry.file_name().to_string_lossy().into_owned();
                if name.starts_with(".cornell-ao") && name.ends_with(".tmp") {
                    temps_seen.insert(name);
                }
            }
            let changed = targets.iter().zip(&states).any(|(p, s)| stat(p) != *s);
            if temps_seen.len() >= nth || changed {
                child.kill().unwrap();
                killed_while_writing += 1;
                break;
            }
            if child.try_wait().unwrap().is_some() || start.elapsed() > Duration::from_secs(20) {
                break;
            }
        }
        let _ = child.wait();
        let now = files(&big);
        for (name, bytes) in &good {
            assert!(
                now.get(name) == Some(bytes),
                "kill -9 at new file {nth}: {} is not the previous file any more",
                name.display()
            );
        }
    }
    assert!(
        killed_while_writing >= 2,
        "the kills never landed while the files were written"
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// A full disk, simulated by a file size limit (`ulimit -f`, with SIGXFSZ
/// ignored, so that writes fail with "File too large" as on a full disk):
/// one clear error, and the previous PNG, EXR and variance EXR all stay.
#[cfg(unix)]
#[test]
fn a_full_disk_leaves_the_previous_render_whole() {
    let dir = folder("full-disk");
    let render = format!(
        "trap '' XFSZ; ulimit -f 20; exec '{EXE}' render --width 64 --height 64 --spp 1 --out out"
    );
    let before = files(&dir);
    let o = Command::new("sh")
        .args(["-c", &render])
        .current_dir(&dir)
        .output()
        .unwrap();
    let err = text(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    // The render's summary, then the error.
    let last = err.trim_end().lines().last().unwrap_or_default();
    assert!(
        last.starts_with("error: cannot write EXR out/cornell-direct.exr: ")
            && err.matches("error: ").count() == 1,
        "{err}"
    );
    assert!(files(&dir) == before, "the previous files changed");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn an_unwritable_output_folder_is_found_before_rendering() {
    let dir = folder("unwritable-setup");
    let locked = dir.join("locked");
    std::fs::create_dir(&locked).unwrap();
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        std::fs::set_permissions(&locked, std::fs::Permissions::from_mode(0o555)).unwrap();
    }
    // Root may write anywhere: then use a folder the kernel refuses.
    let writable = std::fs::write(locked.join("probe"), "").is_ok();
    let out = if !writable {
        locked.to_str().unwrap().to_string()
    } else if Path::new("/sys/kernel").is_dir() {
        "/sys/kernel".to_string()
    } else {
        println!("skipped: no unwritable folder (running as root without /sys)");
        return;
    };
    let args = [
        "render", "--width", "64", "--height", "64", "--spp", "64", "--out", &out,
    ];
    let stdout = refused("unwritable", &args, "cannot write into the output folder");
    assert!(stdout.is_empty(), "{stdout}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn scenes_write_keeps_a_users_edits() {
    let dir = folder("scenes");
    let write = ["scenes", "--write", "cornell", "--to", "my"];
    assert!(run(&dir, &write).status.success());
    // The same file again is fine: nothing would be lost.
    assert!(run(&dir, &write).status.success());
    let file = dir.join("my/cornell.toml");
    let edited = std::fs::read_to_string(&file).unwrap() + "# mine\n";
    std::fs::write(&file, &edited).unwrap();
    let o = run(&dir, &write);
    let err = text(&o.stderr);
    assert_eq!(o.status.code(), Some(1));
    assert!(
        err.contains("my/cornell.toml already exists and differs") && err.contains("--force"),
        "{err}"
    );
    assert_eq!(std::fs::read_to_string(&file).unwrap(), edited);
    assert!(
        run(&dir, &[&write[..], &["--force"]].concat())
            .status
            .success()
    );
    assert!(std::fs::read_to_string(&file).unwrap() != edited);
    // A file where the folder should be: the message names --to.
    let o = run(
        &dir,
        &["scenes", "--write", "cornell", "--to", "my/cornell.toml"],
    );
    let err = text(&o.stderr);
    assert!(
        err.contains("is a file, not a folder: choose another with --to"),
        "{err}"
    );
    assert!(!err.contains("--out"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

// ---- Silent success with wrong output is now an error. ----

#[test]
fn meaningless_numbers_are_refused() {
    for value in ["--exposure=NaN", "--exposure=inf", "--exposure=-inf"] {
        let args = tiny(&["render", value]);
        refused(
            "exposure",
            &args,
            "--exposure must be a number of stops in [-64, 64]",
        );
    }
    for value in ["NaN", "0", "-1"] {
        let args = tiny(&["render", "--integrator", "ao", "--ao-distance", value]);
        refused("ao", &args, "--ao-distance must be a positive distance");
    }
    for value in ["NaN", "-1"] {
        let args = tiny(&["render", "--integrator", "naive", "--cutoff", value]);
        refused("cutoff", &args, "--cutoff must be a number ≥ 0");
    }
    refused(
        "bench-spp",
        &["bench", "--spp", "0"],
        "--spp must be at least 1",
    );
    refused(
        "bench-threads",
        &["bench", "--threads", "0"],
        "--threads must be at least 1",
    );
    refused(
        "bench-time",
        &["bench", "--equal-time", "NaN"],
        "--equal-time must be a number",
    );
}

/// Metropolis light transport's options (issue 16): each out-of-range value
/// is named by its flag before anything is rendered, and an option of
/// `--integrator mlt` given to another integrator is refused.
#[test]
fn metropolis_options_are_checked_before_rendering() {
    let mlt = |flag: &'static str, value: &'static str| {
        tiny(&[
            "render",
            "--integrator",
            "mlt",
            "--scene",
            "door",
            flag,
            value,
        ])
    };
    let cases = [
        (
            "--large-step-probability",
            "1.5",
            "--large-step-probability must be in [0, 1]",
        ),
        ("--large-step-probability", "-0.1", "got -0.1"),
        ("--large-step-probability", "NaN", "got NaN"),
        (
            "--mutation-size",
            "-0.01",
            "--mutation-size must be in (0, 1]",
        ),
        ("--mutation-size", "0", "--mutation-size must be in (0, 1]"),
        ("--mutation-size", "NaN", "got NaN"),
        ("--chains", "0", "--chains must be at least 1, got 0"),
        ("--chains", "-3", "--chains must be at least 1, got -3"),
        ("--chains", "1000", "there are only 48 mutations in all"),
        ("--bootstrap", "0", "--bootstrap must be at least 1 path"),
        (
            "--bootstrap",
            "-1",
            "--bootstrap must be at least 1, got -1",
        ),
    ];
    for (flag, value, expected) in cases {
        refused("mlt", &mlt(flag, value), expected);
    }
    // 2³² − 1 bootstrap paths would keep 64 GiB of f and its distribution.
    refused(
        "mlt-memory",
        &mlt("--bootstrap", "4294967295"),
        "Metropolis light transport at 8×6 on",
    );
    refused(
        "mlt-unused",
        &tiny(&["render", "--integrator", "bdpt", "--chains", "4"]),
        "--chains does not apply to --integrator bdpt",
    );
}

/// One rule for max depth D, on the command line and in a scene file.
#[test]
fn max_depth_has_one_rule_everywhere() {
    let rule = "must be -1 (unlimited) or in [1, 65535]";
    for depth in ["0", "-2", "70000"] {
        let flag = format!("--max-depth={depth}");
        let flag: &'static str = Box::leak(flag.into_boxed_str());
        refused(
            "depth-cli",
            &tiny(&["render", "--integrator", "path", flag]),
            rule,
        );
        let setup: &'static str =
            Box::leak(format!("[render]\nmax_depth = {depth}\n").into_boxed_str());
        let e = format!("s.toml:19:13: render.max_depth: {rule}");
        refused_with_setup(
            "depth-file",
            &tiny(&["render", "--scene", "s.toml"]),
            &e,
            scene_file(setup),
        );
    }
    refused(
        "depth-direct",
        &tiny(&["render", "--integrator", "direct", "--max-depth", "3"]),
        "--max-depth does not apply to --integrator direct: direct lighting is D = 2 by definition",
    );
    refused(
        "depth-naive",
        &tiny(&["render", "--integrator", "naive", "--max-depth=-1"]),
        "naive recursion with --max-depth -1 (unlimited) never ends: add --roulette",
    );
}

#[test]
fn a_scene_without_light_is_warned_about() {
    let dir = folder("unlit");
    std::fs::write(
        dir.join("dark.toml"),
        "[camera]\nposition = [0, 0, 5]\nlook_at = [0, 0, 0]\nfov = 40\n\
         [materials.m]\ntype = \"lambert\"\nalbedo = 0.5\n\
         [[shapes]]\ntype = \"sphere\"\ncenter = [0, 0, 0]\nradius = 1\nmaterial = \"m\"\n",
    )
    .unwrap();
    let o = run(&dir, &tiny(&["render", "--scene", "dark.toml"]));
    assert!(o.status.success());
    let err = text(&o.stderr);
    assert!(
        err.contains("warning: scene `dark` has no light, no emitting shape and no environment"),
        "{err}"
    );
    // Ambient occlusion needs no light.
    let o = run(
        &dir,
        &tiny(&["render", "--scene", "dark.toml", "--integrator", "ao"]),
    );
    assert!(o.status.success() && !text(&o.stderr).contains("warning"));
    std::fs::remove_dir_all(&dir).ok();
}

// ---- Clear messages. ----

#[test]
fn scene_file_mistakes_are_named_where_they_are() {
    let args = tiny(&["render", "--scene", "s.toml"]);
    refused_with_setup(
        "dup",
        &args,
        "s.toml:18:1: duplicate key `radiance`: each key may appear only once in a table",
        scene_file("radiance = 2\n"),
    );
    refused_with_setup(
        "dup-table",
        &args,
        "duplicate table `[materials.m]`",
        scene_file("[materials.m]\ntype = \"lambert\"\n"),
    );
    refused_with_setup("deep", &args, "s.toml:18:", |d| {
        let deep = format!("x = {}{}\n", "[".repeat(100_000), "]".repeat(100_000));
        scene_file(Box::leak(deep.into_boxed_str()))(d)
    });
    refused_with_setup("deep2", &args, "nested too deeply", |d| {
        let deep = format!("x = {}{}\n", "[".repeat(100_000), "]".repeat(100_000));
        scene_file(Box::leak(deep.into_boxed_str()))(d)
    });
    refused_with_setup(
        "tiny-radius",
        &args,
        "s.toml:21:10: shapes[1].radius: 1e-50 is too close to 0 for a 32-bit float",
        scene_file(
            "[[shapes]]\ntype = \"sphere\"\ncenter = [0, 0, 0]\nradius = 1e-50\nmaterial = \"m\"\n",
        ),
    );
}

/// `--scene cornell` beside a file named `cornell`: the built-in scene, and
/// a note that says so and how to load the file.
#[test]
fn a_builtin_name_wins_over_a_file_and_says_so() {
    let dir = folder("name");
    std::fs::write(dir.join("cornell"), "not a scene").unwrap();
    let o = run(&dir, &tiny(&["render", "--scene", "cornell"]));
    let err = text(&o.stderr);
    assert!(o.status.success(), "{err}");
    assert!(err.contains("note: `cornell` is the built-in scene; to load the file cornell of this folder, pass --scene ./cornell"), "{err}");
    let o = run(&dir, &tiny(&["render", "--scene", "./cornell"]));
    assert!(!o.status.success() && text(&o.stderr).contains("./cornell"));
    std::fs::remove_dir_all(&dir).ok();
}

/// The biased integrators' options (issue 15): zero photons, a negative or
/// NaN radius, α outside (0, 1), NaN bounds and thresholds, an option of
/// another integrator — one line each, before anything is traced, nothing
/// written.
#[test]
fn the_biased_integrators_refuse_meaningless_options() {
    let cases: [(&[&'static str], &str); 16] = [
        (
            &["--integrator", "photon", "--photons", "0"],
            "--photons must be at least 1",
        ),
        (
            &["--integrator", "sppm", "--photons", "0"],
            "--photons must be at least 1",
        ),
        (
            &["--integrator", "photon", "--radius=-1"],
            "--radius must be a positive distance, got -1",
        ),
        (
            &["--integrator", "sppm", "--radius=NaN"],
            "--radius must be a positive distance, got NaN",
        ),
        (
            &["--integrator", "photon", "--k", "0"],
            "--k must be at least 1",
        ),
        (
            &["--integrator", "photon", "--k", "5", "--radius", "0.1"],
            "--k and --radius exclude each other",
        ),
        (
            &["--integrator", "sppm", "--alpha", "1"],
            "--alpha must lie strictly between 0 and 1",
        ),
        (
            &["--integrator", "sppm", "--alpha=0"],
            "--alpha must lie strictly between 0 and 1",
        ),
        (
            &["--integrator", "sppm", "--alpha=NaN"],
            "--alpha must lie strictly between 0 and 1",
        ),
        (
            &["--integrator", "vpl", "--clamp=NaN"],
            "--clamp must be a bound ≥ 0 on the geometry term",
        ),
        (
            &["--integrator", "vpl", "--clamp=-1"],
            "--clamp must be a bound ≥ 0 on the geometry term",
        ),
        (
            &["--integrator", "vpl", "--vpl-paths", "0"],
            "--vpl-paths must be at least 1",
        ),
        (
            &["--integrator", "irradiance-cache", "--ic-error=NaN"],
            "--ic-error must be a positive threshold a",
        ),
        (
            &["--integrator", "irradiance-cache", "--ic-rays", "0"],
            "--ic-rays must be at least 1",
        ),
        (
            &["--integrator", "path", "--alpha", "0.5"],
            "--alpha does not apply to --integrator path: it is an option of --integrator sppm",
        ),
        (
            &["--integrator", "vpl", "--photons", "10"],
            "--photons does not apply to --integrator vpl",
        ),
    ];
    for (options, expected) in cases {
        let mut args = vec!["render"];
        args.extend(options);
        refused("biased", &tiny(&args), expected);
    }
}
