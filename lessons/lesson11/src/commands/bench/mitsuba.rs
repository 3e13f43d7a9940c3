//! The peer of the Cornell box figure: Mitsuba 3's path tracer on its own
//! Cornell box (`mitsuba.cornell_box()`, which our `cornell` scene equals),
//! with the settings of `lesson11 bench` (256×256, max depth 65, Russian
//! roulette from depth 5, box filter), timed by the repository's script
//! `raytracer/tests/data/time_mitsuba_cornell.py` right after our own
//! render, so the ratio compares the two in the same minute.
//!
//! Which Python: `--mitsuba PYTHON`, else the environment variable
//! `LESSON11_MITSUBA_PYTHON`, else `python3` if it can `import mitsuba`.

use std::path::PathBuf;
use std::process::Command;

/// The timing script, as the repository holds it (run with `python -c`).
const SCRIPT: &str = include_str!("../../../../../raytracer/tests/data/time_mitsuba_cornell.py");
/// The environment variable naming a Python with Mitsuba 3.
pub const ENV: &str = "LESSON11_MITSUBA_PYTHON";
/// Mitsuba's vectorized CPU variant, the one the README compares with.
const VARIANT: &str = "llvm_ad_rgb";

/// How to get a Mitsuba to compare with, in one paragraph.
pub const HOW_TO_GET: &str = "to compare with Mitsuba 3: `python3 -m venv .venv && \
.venv/bin/pip install mitsuba==3.9.1` (its llvm_ad_rgb variant needs LLVM 19: \
`apt-get install libllvm19`), then `lesson11 bench --mitsuba .venv/bin/python` \
(or set LESSON11_MITSUBA_PYTHON)";

/// The Python to run Mitsuba with: the one asked for (flag, then
/// environment), checked; else `python3` if it imports Mitsuba. `Err` says
/// what was tried.
pub fn find(asked: Option<&PathBuf>) -> Result<PathBuf, String> {
    let from_env = std::env::var_os(ENV).map(PathBuf::from);
    let (python, source) = match (asked, from_env) {
        (Some(p), _) => (p.clone(), "--mitsuba".to_string()),
        (None, Some(p)) => (p, ENV.to_string()),
        (None, None) => (PathBuf::from("python3"), "auto-detect".to_string()),
    };
    let ok = Command::new(&python)
        .args(["-c", "import mitsuba"])
        .output()
        .map(|o| o.status.success());
    match ok {
        Ok(true) => Ok(python),
        Ok(false) => Err(format!(
            "{} ({source}) cannot `import mitsuba`",
            python.display()
        )),
        Err(e) => Err(format!("cannot run {} ({source}): {e}", python.display())),
    }
}

/// Mitsuba's samples per second (best of three renders after a warm-up, as
/// the script measures) at `spp` samples per pixel, or why there is none.
pub fn samples_per_second(python: &PathBuf, spp: u32) -> Result<f64, String> {
    let out = Command::new(python)
        .args(["-c", SCRIPT, VARIANT, &spp.to_string()])
        .output()
        .map_err(|e| format!("cannot run {}: {e}", python.display()))?;
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
            Err(format!(
                "Mitsuba {VARIANT} failed ({}): {}",
                out.status,
                last.unwrap_or("no message")
            ))
        }
    }
}

/// The line `lesson11 bench` prints after its path tracing figures: Mitsuba's
/// rate and the ratio of each of our engines (`(name, samples per second)`)
/// to it.
pub fn compare(asked: Option<&PathBuf>, spp: u32, ours: &[(&str, f64)], threads: usize) -> String {
    let python = match find(asked) {
        Ok(p) => p,
        Err(why) => return format!("  Mitsuba 3: not found ({why}); {HOW_TO_GET}"),
    };
    match samples_per_second(&python, spp) {
        Ok(theirs) => {
            let ratios: Vec<String> = ours
                .iter()
                .map(|(name, rate)| format!("{name} {:.2}×", rate / theirs))
                .collect();
            format!(
                "  Mitsuba 3 {VARIANT} ({}), same scene and settings, all cores, just after: \
                 {:.3} M samples/s; ours on {threads} thread(s) / Mitsuba: {}",
                python.display(),
                theirs / 1e6,
                ratios.join(", ")
            )
        }
        Err(why) => format!("  Mitsuba 3: {why}; {HOW_TO_GET}"),
    }
}
