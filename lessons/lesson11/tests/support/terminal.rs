//! `lesson11` with its stderr on a terminal, stopped by a signal once it
//! shows that its render is under way.
//!
//! The render's progress bar is drawn only on a terminal, so the program runs
//! under util-linux `script` (a pseudo-terminal for stderr; stdout goes to a
//! file). The test waits for a real sign that the render has started — the
//! bar counting finished work, or a line on stdout followed by CPU time that
//! only the render can be burning — never for a fixed time. Linux only (the
//! `script` options and `/proc`); elsewhere [`available`] is false and the
//! tests say they were skipped.

#![allow(dead_code)]

use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, ExitStatus, Stdio};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// What shows that the render has started.
#[derive(Clone, Copy, Debug)]
pub enum Ready<'a> {
    /// The progress bar counts at least `at_least` finished `unit`s
    /// ("samples", "SPPM passes", "paths and mutations"): work is being done
    /// and some of it is already in the film.
    Progress { unit: &'a str, at_least: u64 },
    /// `line` appeared on stdout, and since then the process has used `cpu`
    /// seconds of CPU time: the render that follows the line is computing
    /// (for a sample that never finishes, so the bar never moves).
    StdoutThenCpu { line: &'a str, cpu: f64 },
}

/// The end of a signalled run.
#[derive(Debug)]
pub struct Signalled {
    pub status: ExitStatus,
    pub stdout: String,
    /// What the program wrote to its terminal, one line per line, without
    /// the progress bar's redraws and escape codes.
    pub stderr: String,
    /// Seconds from the signal to the exit.
    pub seconds: f64,
}

/// Whether runs on a pseudo-terminal work here (util-linux `script`, `/proc`).
pub fn available() -> bool {
    Path::new("/proc/self/stat").exists()
        && Command::new("script")
            .arg("--version")
            .output()
            .is_ok_and(|o| String::from_utf8_lossy(&o.stdout).contains("util-linux"))
}

/// `'text'` for `sh`.
fn quoted(text: &str) -> String {
    format!("'{}'", text.replace('\'', r"'\''"))
}

/// The terminal's text as lines: for each line the last redraw of it (the
/// text after its last carriage return), escape sequences removed.
pub fn clean(bytes: &[u8]) -> String {
    let text = String::from_utf8_lossy(bytes);
    let mut plain = String::new();
    let mut chars = text.chars();
    while let Some(c) = chars.next() {
        if c == '\x1b' {
            // CSI: ESC [ parameters, ended by a letter.
            if chars.next() == Some('[') {
                for c in chars.by_ref() {
                    if c.is_ascii_alphabetic() {
                        break;
                    }
                }
            }
            continue;
        }
        plain.push(c);
    }
    plain
        .split('\n')
        .map(|line| {
            let line = line.trim_end_matches('\r');
            line.rsplit('\r').next().unwrap_or_default()
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// The largest count of finished `unit`s the progress bar showed
/// (`… 4,096/409,600,000 samples, …`).
pub fn progress(text: &str, unit: &str) -> Option<u64> {
    let pattern = format!(" {unit}");
    text.match_indices(&pattern)
        .filter_map(|(i, _)| {
            let before = text[..i].split_whitespace().last()?;
            let (done, _total) = before.split_once('/')?;
            done.replace(',', "").parse::<u64>().ok()
        })
        .max()
}

/// CPU seconds (user and system, all threads) of process `pid` so far:
/// fields 14 and 15 of `/proc/PID/stat`, in the kernel's USER_HZ = 100 ticks
/// per second (fixed by the kernel's ABI for /proc on every architecture).
pub fn cpu_seconds(pid: u32) -> Option<f64> {
    let stat = std::fs::read_to_string(format!("/proc/{pid}/stat")).ok()?;
    // The command name may hold spaces: the fields follow its ')'.
    let fields: Vec<&str> = stat.rsplit_once(')')?.1.split_whitespace().collect();
    let ticks: u64 = fields.get(11)?.parse::<u64>().ok()? + fields.get(12)?.parse::<u64>().ok()?;
    Some(ticks as f64 / 100.0)
}

/// The child of process `parent` (the program `script` started).
fn child_of(parent: u32) -> Option<u32> {
    std::fs::read_dir("/proc")
        .ok()?
        .flatten()
        .find_map(|entry| {
            let pid: u32 = entry.file_name().to_str()?.parse().ok()?;
            let stat = std::fs::read_to_string(entry.path().join("stat")).ok()?;
            let ppid: u32 = stat
                .rsplit_once(')')?
                .1
                .split_whitespace()
                .nth(1)?
                .parse()
                .ok()?;
            (ppid == parent).then_some(pid)
        })
}

/// Runs `exe args` in `dir` with stderr on a pseudo-terminal, waits until
/// `ready` (at most `patience`), sends `signal` (`-INT`, `-TERM`, …) to it
/// and waits for its exit. Panics, with what the program printed, if it
/// never gets ready.
pub fn signalled(
    exe: &str,
    dir: &Path,
    args: &[&str],
    ready: Ready,
    signal: &str,
    patience: Duration,
) -> Signalled {
    let stdout_file: PathBuf = dir.with_extension("stdout");
    let mut command = format!("exec {}", quoted(exe));
    for a in args {
        command.push(' ');
        command.push_str(&quoted(a));
    }
    command.push_str(&format!(" > {}", quoted(stdout_file.to_str().unwrap())));
    let mut script = Command::new("script")
        .args(["-qfec", &command, "/dev/null"])
        // `script` runs the command with $SHELL: make it one that knows `exec`
        // and these quotes.
        .env("SHELL", "/bin/sh")
        // The tests match the program's English.
        .env("LESSON11_LANG", "en")
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("script runs");
    // Read the terminal all along, so that the program never blocks on it.
    let terminal = Arc::new(Mutex::new(Vec::new()));
    let reader = {
        let terminal = Arc::clone(&terminal);
        let mut out = script.stdout.take().unwrap();
        std::thread::spawn(move || {
            let mut buf = [0u8; 4096];
            while let Ok(n) = out.read(&mut buf) {
                if n == 0 {
                    break;
                }
                terminal.lock().unwrap().extend_from_slice(&buf[..n]);
            }
        })
    };
    let stdout = || std::fs::read_to_string(&stdout_file).unwrap_or_default();
    let start = Instant::now();
    let mut pid = None;
    let mut cpu_at_line = None;
    loop {
        if pid.is_none() {
            pid = child_of(script.id());
        }
        let is_ready = match (ready, pid) {
            (Ready::Progress { unit, at_least }, Some(_)) => {
                progress(&clean(&terminal.lock().unwrap()), unit).is_some_and(|n| n >= at_least)
            }
            (Ready::StdoutThenCpu { line, cpu }, Some(p)) => {
                if cpu_at_line.is_none() && stdout().contains(line) {
                    cpu_at_line = cpu_seconds(p);
                }
                cpu_at_line.is_some_and(|c0| cpu_seconds(p).is_some_and(|c| c - c0 >= cpu))
            }
            (_, None) => false,
        };
        if is_ready {
            break;
        }
        let exited = script.try_wait().unwrap().is_some();
        if exited || start.elapsed() > patience {
            if let Some(p) = pid {
                let _ = Command::new("kill")
                    .args(["-KILL", &p.to_string()])
                    .status();
            }
            let _ = script.kill();
            let _ = script.wait();
            let _ = reader.join();
            panic!(
                "{args:?}: not ready ({ready:?}) after {:.1} s{}\nstdout: {}\nterminal: {}",
                start.elapsed().as_secs_f64(),
                if exited { ", it exited" } else { "" },
                stdout(),
                clean(&terminal.lock().unwrap())
            );
        }
        std::thread::sleep(Duration::from_millis(2));
    }
    let pid = pid.unwrap().to_string();
    let signalled_at = Instant::now();
    let kill = Command::new("kill").args([signal, &pid]).status().unwrap();
    assert!(kill.success(), "kill {signal} {pid}");
    let status = script.wait().unwrap();
    let seconds = signalled_at.elapsed().as_secs_f64();
    reader.join().unwrap();
    let stderr = clean(&terminal.lock().unwrap());
    let out = stdout();
    let _ = std::fs::remove_file(&stdout_file);
    Signalled {
        status,
        stdout: out,
        stderr,
        seconds,
    }
}
