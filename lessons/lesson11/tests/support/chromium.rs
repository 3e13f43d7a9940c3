//! Headless Chromium for the browser tests (the lab, the slides): where it is installed,
//! and the DOM or a screenshot of a page after its script ran. A test that
//! finds no Chromium prints that it was skipped and passes, so a student's
//! `cargo test` stays green with only Rust installed.

#![allow(dead_code)]

use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Chromium, where a student or CI installed it: on PATH, else /usr/bin/chromium.
pub fn chromium() -> Option<PathBuf> {
    std::env::var_os("PATH")
        .and_then(|paths| {
            std::env::split_paths(&paths)
                .map(|d| d.join("chromium"))
                .find(|p| p.is_file())
        })
        .or_else(|| Some(PathBuf::from("/usr/bin/chromium")).filter(|p| p.is_file()))
}

/// Runs headless Chromium on `url` with a fresh profile and the flags of
/// the guide, plus `extra` (`--dump-dom`, `--screenshot=…`,
/// `--virtual-time-budget=…`); returns what it printed on stdout. An error
/// after `limit`.
pub fn run(
    chromium: &Path,
    url: &str,
    extra: &[String],
    limit: Duration,
) -> Result<String, String> {
    static RUN: std::sync::atomic::AtomicU32 = std::sync::atomic::AtomicU32::new(0);
    let n = RUN.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let profile =
        std::env::temp_dir().join(format!("lesson11-chromium-{}-{n}", std::process::id()));
    let _ = std::fs::remove_dir_all(&profile);
    let mut child = Command::new(chromium)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-quic",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--hide-scrollbars",
        ])
        .arg(format!("--user-data-dir={}", profile.display()))
        .args(extra)
        .arg(url)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .map_err(|e| format!("cannot start {}: {e}", chromium.display()))?;
    let mut stdout = child.stdout.take().unwrap();
    let reader = std::thread::spawn(move || {
        let mut s = String::new();
        let _ = stdout.read_to_string(&mut s);
        s
    });
    let deadline = Instant::now() + limit;
    let status = loop {
        if let Some(status) = child.try_wait().map_err(|e| e.to_string())? {
            break status;
        }
        if Instant::now() > deadline {
            let _ = child.kill();
            let _ = child.wait();
            let _ = std::fs::remove_dir_all(&profile);
            return Err(format!("chromium did not finish {url} within {limit:?}"));
        }
        std::thread::sleep(Duration::from_millis(50));
    };
    let out = reader.join().unwrap_or_default();
    let _ = std::fs::remove_dir_all(&profile);
    if !status.success() {
        return Err(format!("chromium failed on {url}: {status}"));
    }
    Ok(out)
}

/// The text of the page's `<pre id="selftest">`, which the lab's `#selftest`
/// mode fills with JSON (HTML entities of the dump decoded).
pub fn selftest_report(dom: &str) -> Option<String> {
    let start = dom.find("<pre id=\"selftest\"")?;
    let open = start + dom[start..].find('>')? + 1;
    let close = open + dom[open..].find("</pre>")?;
    Some(
        dom[open..close]
            .replace("&lt;", "<")
            .replace("&gt;", ">")
            .replace("&quot;", "\"")
            .replace("&#39;", "'")
            .replace("&amp;", "&"),
    )
}
