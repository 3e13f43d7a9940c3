//! `lesson11 lab`: the lecture live in the browser. A local web page with
//! a progressive render and the lecture's knobs (scene, integrator, max
//! depth D, samples, seed, exposure), a stereo pair composed live, the BRDF
//! lobes with their directional albedo, and the path inspector (a click on
//! the picture shows the paths the integrator traced for that pixel sample,
//! recorded by `raytracer`'s path recorder, see `lab/paths.rs`).
//!
//! The program serves one page and a small HTTP API on 127.0.0.1; the page
//! (HTML, CSS and script embedded in the program, no network beyond the
//! local server) drives it. The files:
//!
//! - `lab/server.rs`: the HTTP loop (tiny_http), the routes, and the rule
//!   that every request gets an answer — 400 with a one-line reason for bad
//!   parameters, 404 for unknown paths, never a panic;
//! - `lab/query.rs`: query strings, read and checked;
//! - `lab/settings.rs`: a render's settings as `lesson11 render` reads them
//!   (the same options, checked by the same code), so the lab's picture at N
//!   spp is that command's picture, bit for bit;
//! - `lab/job.rs` and `lab/pages.rs`: the progressive render of one page,
//!   its snapshots and its cancellation; one render at a time per page;
//! - `lab/stereo.rs`, `lab/brdf.rs`: the Stereo and BRDF tabs;
//! - `lab/race.rs`: the Race tab (an equal-time race, RMSE against time);
//! - `lab/student.rs`: the "Your code" tab (the student's integrator beside
//!   the renderer's, and the tile z-map between them);
//! - `lab/paths.rs`: the path inspector's data (a recorded pixel sample);
//! - `lab/preview.rs`: the coarse preview of an incomplete first pass;
//! - `lab/assets/`: the page.

pub mod brdf;
pub mod job;
pub mod pages;
pub mod paths;
pub mod preview;
pub mod query;
pub mod race;
pub mod server;
pub mod settings;
pub mod stereo;
pub mod student;

use std::net::{IpAddr, SocketAddr, ToSocketAddrs};
use std::path::PathBuf;
use std::time::Duration;

use anyhow::{Context, Result, bail};
use clap::Args;

pub use server::{Lab, LabConfig};

/// Serve the lab: a local web page with a progressive render and the lecture's knobs,
/// a live stereo pair, BRDF lobes with their albedo, and a path inspector (click a pixel:
/// the paths one of its samples traced). It prints the address to open; Ctrl-C stops it.
#[derive(Args, Debug)]
pub struct LabArgs {
    /// The address to listen on. Only 127.0.0.1 (this machine) by default; any other
    /// address lets every machine that reaches it use the lab (a warning says so).
    #[arg(long, default_value = "127.0.0.1")]
    pub host: String,
    /// The port (0 picks a free one).
    #[arg(long, default_value_t = 8011)]
    pub port: u16,
    /// Open the page in the default browser.
    #[arg(long)]
    pub open: bool,
    /// A folder of scene files (.toml) to offer beside the built-in scenes; it is read again
    /// whenever the page asks, so new files appear without a restart.
    #[arg(long)]
    pub scenes: Option<PathBuf>,
}

pub fn run(args: &LabArgs) -> Result<()> {
    let address = resolve(&args.host, args.port)?;
    if !address.ip().is_loopback() {
        eprintln!(
            "{}",
            lang::fill(
                lang::pick(
                    "warning: serving on {address}: every machine that can reach this address can \
                     use the lab and its processors (use --host 127.0.0.1 to keep it to this machine)",
                    "внимание: лабораторията слуша на {address}: всяка машина, която достига този \
                     адрес, може да ползва нея и процесорите ѝ (--host 127.0.0.1 я оставя само за \
                     тази машина)",
                ),
                &[("address", &address)]
            )
        );
    }
    if let Some(dir) = &args.scenes
        && !dir.is_dir()
    {
        bail!(
            "--scenes {}: {}",
            dir.display(),
            lang::pick(
                "no such folder (give a folder of .toml scene files)",
                "няма такава папка (дайте папка с файлове със сцени .toml)"
            )
        );
    }
    let lab = Lab::start(
        address,
        LabConfig {
            scenes: args.scenes.clone(),
        },
    )
    .map_err(|e| {
        let hint = if e.to_string().contains("in use") {
            lang::pick(
                " (another program uses it: pass --port N, or --port 0 for a free one)",
                " (друга програма го ползва: дайте --port N или --port 0 за свободен)",
            )
        } else {
            ""
        };
        anyhow::anyhow!(
            "{} {address}: {e}{hint}",
            lang::pick("cannot listen on", "не мога да слушам на")
        )
    })?;
    // The page opens in the lab's language (it is English without `?lang`).
    let url = match lang::current() {
        lang::Lang::En => lab.url(),
        lang::Lang::Bg => format!("{}?lang=bg", lab.url()),
    };
    crate::console::say!(
        "lesson11 lab: {} {url} {}",
        lang::pick("open", "отворете"),
        lang::pick("(Ctrl-C stops the lab)", "(Ctrl-C спира лабораторията)")
    );
    if args.open {
        open_browser(&url);
    }
    // The interrupt handler of `main` sets the flag; the renders stop with the lab.
    while !raytracer::render::interrupted() {
        std::thread::sleep(Duration::from_millis(100));
    }
    lab.stop();
    crate::console::say!("lesson11 lab: {}", lang::pick("stopped", "спряна"));
    Ok(())
}

/// `host:port` as one socket address; names (`localhost`) are resolved.
fn resolve(host: &str, port: u16) -> Result<SocketAddr> {
    if let Ok(ip) = host.parse::<IpAddr>() {
        return Ok(SocketAddr::new(ip, port));
    }
    let mut found = (host, port)
        .to_socket_addrs()
        .with_context(|| format!("--host {host}: not an address or a name this machine knows"))?;
    // Prefer IPv4 (a browser asked for `localhost` tries it first too).
    let all: Vec<SocketAddr> = found.by_ref().collect();
    all.iter()
        .find(|a| a.is_ipv4())
        .or(all.first())
        .copied()
        .with_context(|| format!("--host {host}: the name has no address"))
}

/// Asks the desktop to open `url`; says so if it cannot (the URL is printed anyway).
fn open_browser(url: &str) {
    let opener: &[&str] = if cfg!(target_os = "macos") {
        &["open"]
    } else if cfg!(windows) {
        &["cmd", "/C", "start", ""]
    } else {
        &["xdg-open"]
    };
    let started = std::process::Command::new(opener[0])
        .args(&opener[1..])
        .arg(url)
        .stdin(std::process::Stdio::null())
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn();
    if let Err(e) = started {
        eprintln!(
            "note: cannot open a browser with {} ({e}); open {url} yourself",
            opener[0]
        );
    }
}
