//! The peer of the Cornell box figure: Mitsuba 3's path tracer on its own
//! Cornell box (`mitsuba.cornell_box()`, which our `cornell` scene equals),
//! with the settings of `lesson11 bench` (256×256, max depth 65, Russian
//! roulette from depth 5, box filter), timed by the repository's script
//! `raytracer/tests/data/time_mitsuba_cornell.py` right after our own
//! render, so the ratio compares the two in the same minute.
//!
//! Which Python: `--mitsuba PYTHON`, else the environment variable
//! `LESSON11_MITSUBA_PYTHON`, else `python3` if it can `import mitsuba`.
//!
//! The peer is another program: it may hang. Each run of it has a time
//! limit ([`PEER_LIMIT`]) and ends at once on Ctrl-C (it is killed).

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

/// The timing script, as the repository holds it (run with `python -c`).
const SCRIPT: &str = include_str!("../../../../../raytracer/tests/data/time_mitsuba_cornell.py");
/// The environment variable naming a Python with Mitsuba 3.
pub const ENV: &str = "LESSON11_MITSUBA_PYTHON";
/// Mitsuba's vectorized CPU variant, the one the README compares with.
const VARIANT: &str = "llvm_ad_rgb";

/// The longest a run of the peer may take: the timing script's warm-up
/// (Mitsuba's JIT compiles its kernels) and four renders of 256×256 at the
/// benchmark's spp take 10–40 s on two cores.
pub const PEER_LIMIT: Duration = Duration::from_secs(300);

/// How often a wait for the peer asks whether to stop.
const POLL: Duration = Duration::from_millis(20);

/// Why a run of the peer has no output.
#[derive(Debug, PartialEq)]
pub enum Unfinished {
    /// Ctrl-C: the benchmark stops.
    Interrupted,
    /// It did not start, or took longer than its limit (and was killed).
    Failed(String),
}

/// Runs `python args` to its end within `limit`; killed on Ctrl-C or when
/// the limit is over.
pub fn run_peer(python: &Path, args: &[&str], limit: Duration) -> Result<Output, Unfinished> {
    let start = Instant::now();
    let mut child = Command::new(python)
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| Unfinished::Failed(format!("cannot run {}: {e}", python.display())))?;
    // Read both pipes all along (the peer never blocks on them), on threads
    // of their own: a killed peer's children may hold them open.
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
        let why = if raytracer::render::interrupted() {
            Some(Unfinished::Interrupted)
        } else if start.elapsed() > limit {
            Some(Unfinished::Failed(format!(
                "{} did not finish within {} s (killed)",
                python.display(),
                limit.as_secs()
            )))
        } else {
            None
        };
        if let Some(why) = why {
            let _ = child.kill();
            let _ = child.wait();
            return Err(why);
        }
        match child.try_wait() {
            Ok(Some(status)) => break status,
            Ok(None) => std::thread::sleep(POLL),
            Err(e) => {
                return Err(Unfinished::Failed(format!(
                    "waiting for {}: {e}",
                    python.display()
                )));
            }
        }
    };
    Ok(Output {
        status,
        stdout: stdout.join().unwrap_or_default(),
        stderr: stderr.join().unwrap_or_default(),
    })
}

/// How to get a Mitsuba to compare with, in one paragraph.
pub const HOW_TO_GET: &str = "to compare with Mitsuba 3: `python3 -m venv .venv && \
.venv/bin/pip install mitsuba==3.9.1` (its llvm_ad_rgb variant needs LLVM 19: \
`apt-get install libllvm19`), then `lesson11 bench --mitsuba .venv/bin/python` \
(or set LESSON11_MITSUBA_PYTHON)";

/// The Python to run Mitsuba with: the one asked for (flag, then
/// environment), checked; else `python3` if it imports Mitsuba.
/// `Failed` says what was tried.
pub fn find(asked: Option<&PathBuf>) -> Result<PathBuf, Unfinished> {
    let from_env = std::env::var_os(ENV).map(PathBuf::from);
    let (python, source) = match (asked, from_env) {
        (Some(p), _) => (p.clone(), "--mitsuba".to_string()),
        (None, Some(p)) => (p, ENV.to_string()),
        (None, None) => (PathBuf::from("python3"), "auto-detect".to_string()),
    };
    let out =
        run_peer(&python, &["-c", "import mitsuba"], PEER_LIMIT).map_err(|why| match why {
            Unfinished::Failed(e) => Unfinished::Failed(format!("{e} ({source})")),
            interrupted => interrupted,
        })?;
    if out.status.success() {
        Ok(python)
    } else {
        Err(Unfinished::Failed(format!(
            "{} ({source}) cannot `import mitsuba`",
            python.display()
        )))
    }
}

/// Mitsuba's samples per second (best of three renders after a warm-up, as
/// the script measures) at `spp` samples per pixel, or why there is none.
pub fn samples_per_second(python: &Path, spp: u32) -> Result<f64, Unfinished> {
    let out = run_peer(
        python,
        &["-c", SCRIPT, VARIANT, &spp.to_string()],
        PEER_LIMIT,
    )?;
    let stdout = String::from_utf8_lossy(&out.stdout);
    // The script's last line: "... = 3.61 M samples/s".
    let figure = stdout.lines().rev().find_map(|l| {
        l.strip_suffix(" M samples/s")?
            .rsplit(' ')
            .next()?
            .parse::<f64>()
            .ok()
    });
    match figure {
        Some(m) if out.status.success() => Ok(m * 1e6),
        _ => {
            let stderr = String::from_utf8_lossy(&out.stderr);
            let last = stderr.lines().rev().find(|l| !l.trim().is_empty());
            Err(Unfinished::Failed(format!(
                "Mitsuba {VARIANT} failed ({}): {}",
                out.status,
                last.unwrap_or("no message")
            )))
        }
    }
}

/// The line `lesson11 bench` prints after its path tracing figures: Mitsuba's
/// rate and the ratio of each of our engines (`(name, samples per second)`)
/// to it; `None` if Ctrl-C stopped the peer.
pub fn compare(
    asked: Option<&PathBuf>,
    spp: u32,
    ours: &[(&str, f64)],
    threads: usize,
) -> Option<String> {
    let figure = find(asked).and_then(|python| Ok((samples_per_second(&python, spp)?, python)));
    match figure {
        Ok((theirs, python)) => {
            let ratios: Vec<String> = ours
                .iter()
                .map(|(name, rate)| format!("{name} {:.2}×", rate / theirs))
                .collect();
            Some(format!(
                "  Mitsuba 3 {VARIANT} ({}), same scene and settings, all cores, just after: \
                 {:.3} M samples/s; ours on {threads} thread(s) / Mitsuba: {}",
                python.display(),
                theirs / 1e6,
                ratios.join(", ")
            ))
        }
        Err(Unfinished::Interrupted) => None,
        Err(Unfinished::Failed(why)) => Some(format!("  Mitsuba 3: {why}; {HOW_TO_GET}")),
    }
}
