//! `lesson11 exercises --watch`: the rustlings loop. Each time a file of
//! `exercises/src/` is saved, the exercise it holds is graded again (by
//! `cargo test -p grading --test exercises -- NAME`, which rebuilds the
//! student's code), and its verdict is shown with the next hint command.
//!
//! Saves are found by polling the files' modification times every
//! [`POLL`]: fifteen small files cost nothing to poll, and a file-watching
//! crate (with its platform back-ends) would add to every student's cold
//! build for no gain here.

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, SystemTime};

use exercises::Exercise;

/// How often the files are polled.
pub const POLL: Duration = Duration::from_millis(300);

/// The files being watched and their last modification times.
#[derive(Debug)]
pub struct Watcher {
    files: Vec<(PathBuf, Option<SystemTime>)>,
}

fn mtime(p: &Path) -> Option<SystemTime> {
    std::fs::metadata(p).and_then(|m| m.modified()).ok()
}

impl Watcher {
    /// Starts watching `files` (their current times are the baseline).
    pub fn new(files: Vec<PathBuf>) -> Watcher {
        Watcher {
            files: files.into_iter().map(|f| (f.clone(), mtime(&f))).collect(),
        }
    }

    /// The files modified since the last call (or since [`Watcher::new`]).
    pub fn changed(&mut self) -> Vec<PathBuf> {
        let mut out = Vec::new();
        for (path, seen) in &mut self.files {
            let now = mtime(path);
            if now != *seen {
                *seen = now;
                out.push(path.clone());
            }
        }
        out
    }
}

/// The exercise whose student file is `path`.
pub fn exercise_of(path: &Path, registry: &[Exercise]) -> Option<Exercise> {
    let name = path.file_stem()?.to_str()?;
    registry.iter().find(|e| e.name == name).cloned()
}

/// The command that grades the exercises matching `filter` (all if empty)
/// in the workspace at `root`: the grading harness alone, quietly.
pub fn grade_command(root: &Path, filter: &str) -> Command {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let mut cmd = Command::new(cargo);
    // The harness speaks this program's language (`lesson11 --lang`).
    cmd.current_dir(root)
        .env(lang::ENV, lang::current().code())
        .args(["test", "-q", "-p", "grading", "--test", "exercises"]);
    if !filter.is_empty() {
        cmd.args(["--", filter]);
    }
    cmd
}

/// What to show for one grading run, from its standard output and error:
/// the harness's report, or — if the code did not compile and the harness
/// never ran — the compiler's errors.
pub fn verdict(stdout: &[u8], stderr: &[u8]) -> String {
    let stdout = String::from_utf8_lossy(stdout);
    // The report names an exercise (or all of them), in either language.
    if ["Exercise", "Задача"].iter().any(|w| stdout.contains(w)) {
        return stdout.trim_end().to_string();
    }
    let stderr = String::from_utf8_lossy(stderr);
    let lines: Vec<&str> = stderr.lines().collect();
    let first = lines
        .iter()
        .position(|l| l.starts_with("error") || l.starts_with("warning: unused"))
        .unwrap_or(0);
    let shown: Vec<&str> = lines[first..].iter().take(60).copied().collect();
    format!(
        "{}\n{}",
        crate::tr!("report.does_not_compile"),
        shown.join("\n")
    )
}

/// Runs `cmd` to its end and returns its output, or `None` as soon as
/// `stop()` says so (the command is then killed): a grading run can take
/// minutes when it rebuilds the student's code.
fn output_unless(mut cmd: Command, stop: &dyn Fn() -> bool) -> std::io::Result<Option<Output>> {
    let mut child = cmd
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()?;
    // Read both pipes all along, so that the command never blocks on them
    // (on threads of their own: a killed cargo's compilers may hold the
    // pipes open a while, and a stop does not wait for them).
    let read = |pipe: Option<Box<dyn std::io::Read + Send>>| {
        std::thread::spawn(move || {
            let mut bytes = Vec::new();
            if let Some(mut pipe) = pipe {
                let _ = pipe.read_to_end(&mut bytes);
            }
            bytes
        })
    };
    let stdout = read(child.stdout.take().map(|p| Box::new(p) as _));
    let stderr = read(child.stderr.take().map(|p| Box::new(p) as _));
    let status = loop {
        if stop() {
            let _ = child.kill();
            let _ = child.wait();
            return Ok(None);
        }
        if let Some(status) = child.try_wait()? {
            break status;
        }
        std::thread::sleep(STOP_POLL);
    };
    Ok(Some(Output {
        status,
        stdout: stdout.join().unwrap_or_default(),
        stderr: stderr.join().unwrap_or_default(),
    }))
}

/// How often a wait asks whether to stop.
const STOP_POLL: Duration = Duration::from_millis(20);

/// Watches `exercises/src/`: grades everything once, then the exercise of
/// each file saved, until `stop()` says so (it is asked every
/// [`STOP_POLL`], during a grading run too, which is then killed).
pub fn run(stop: &dyn Fn() -> bool) -> std::io::Result<()> {
    let root = crate::texts::repo_root();
    let registry = exercises::registry();
    let files: Vec<PathBuf> = registry
        .iter()
        .map(|e| exercises::crate_dir().join(&e.file))
        .collect();
    let mut watcher = Watcher::new(files);
    println!("{}", crate::tr!("report.grading_all"));
    let Some(out) = output_unless(grade_command(&root, ""), stop)? else {
        return Ok(());
    };
    println!("{}", verdict(&out.stdout, &out.stderr));
    loop {
        println!("\n{}", crate::tr!("report.watching"));
        let exercise = loop {
            for _ in 0..POLL.as_millis() / STOP_POLL.as_millis() {
                if stop() {
                    return Ok(());
                }
                std::thread::sleep(STOP_POLL);
            }
            if let Some(e) = watcher
                .changed()
                .iter()
                .rev()
                .find_map(|p| exercise_of(p, &registry))
            {
                break e;
            }
        };
        println!(
            "\n{}",
            crate::tr!(
                "report.saved",
                file = exercise.file,
                number = exercise.number().unwrap_or(0)
            )
        );
        let Some(out) = output_unless(grade_command(&root, &exercise.name), stop)? else {
            return Ok(());
        };
        println!("{}", verdict(&out.stdout, &out.stderr));
        // Saves made while grading belong to this run.
        watcher.changed();
    }
}
