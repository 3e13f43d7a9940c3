//! The lab's HTTP server: tiny_http accepts the connections, a few worker
//! threads answer the requests, and [`route`] maps each request to its
//! answer. Every request gets one: 400 with a one-line reason for bad
//! parameters, 404 for an unknown path, 405 for a wrong method, and 500
//! (the lab keeps running) if a handler should ever panic.
//!
//! The API (every answer is JSON, PNG, EXR or one line of text):
//!
//! | request | answer |
//! |---|---|
//! | `GET /` (`?lang=bg`: in Bulgarian), `/lab.css`, `/lab.js`, `/i18n.js`, `/favicon.svg` | the page |
//! | `GET /api/scenes` | scenes, integrators, composites, limits |
//! | `POST /api/render?page=P&scene=…&integrator=…&max-depth=…&spp=…&seed=…` | starts the page's render (options of `lesson11 render`) |
//! | `POST /api/stereo?page=P&…&separation=…&convergence=…&toe-in=1` | starts both eyes |
//! | `POST /api/brdf-sphere?page=P&model=…&spp=…` | starts a ball of that BRDF |
//! | `POST /api/student?page=P&integrator=…&…` | starts the student's integrator beside the renderer's (options of `lesson11 render --student`) |
//! | `POST /api/race?page=P&racers=path,light,bdpt&seconds=S&scene=…` | an equal-time race, RMSE against time in the status |
//! | `GET /api/zmap.png?page=P` | the tile z-map between them (headers: the verdict) |
//! | `POST /api/stop?page=P` | stops the page's render |
//! | `GET /api/status?page=P&after=V` | the render's phase (building, rendering, done) and progress, once a change newer than V is out (at most 2 s) |
//! | `GET /api/image.png?page=P&exposure=E` / `image.exr?page=P&eye=0` | the picture so far |
//! | `GET /api/stereo.png?page=P&mode=…&desaturate=…&exposure=E` | the pair, composed |
//! | `GET /api/brdf?model=…&albedo=…&exponent=…&theta=…` | lobe, albedo, verdict |
//! | `GET /api/paths?page=P&x=…&y=…&sample=…` | the paths the integrator traced for one pixel sample, recorded (JSON) |

use std::net::SocketAddr;
use std::path::PathBuf;
use std::sync::Arc;
use std::thread::JoinHandle;
use std::time::Duration;

use clap::ValueEnum;
use serde::Serialize;
use tiny_http::{Header, Method, Request, Response, Server};

use super::brdf::{self, BRDF_PARAMS};
use super::job::Job;
use super::pages::{IDLE, Pages};
use super::query::Query;
use super::race::{self, RACE_PARAMS};
use super::settings::{MAX_PIXELS, MAX_SPP, RENDER_PARAMS, SceneFolder, render_setup};
use super::stereo::{self, COMPOSITE_PARAMS, RIG_PARAMS};
use super::student::{self, ZMap};
use crate::integrators::IntegratorKind;

/// Threads that answer requests (a long poll holds one for up to 2 s).
const WORKERS: usize = 8;

/// The longest a status request waits for a newer snapshot.
const LONGEST_POLL: Duration = Duration::from_secs(2);

const INDEX_HTML: &str = include_str!("assets/index.html");
const LAB_CSS: &str = include_str!("assets/lab.css");
const LAB_JS: &str = include_str!("assets/lab.js");
const FAVICON: &str = include_str!("assets/favicon.svg");
const I18N_JS: &str = include_str!("assets/i18n.js");

/// What the lab is started with.
#[derive(Clone, Default)]
pub struct LabConfig {
    /// A folder of scene files offered beside the built-in scenes.
    pub scenes: Option<PathBuf>,
}

struct State {
    folder: SceneFolder,
    pages: Pages,
}

/// A running lab.
pub struct Lab {
    server: Arc<Server>,
    state: Arc<State>,
    workers: Vec<JoinHandle<()>>,
    address: SocketAddr,
}

impl Lab {
    /// Listens on `address` (port 0: a free one) and starts answering.
    pub fn start(address: SocketAddr, config: LabConfig) -> Result<Lab, String> {
        let server = Arc::new(Server::http(address).map_err(|e| e.to_string())?);
        let address = server
            .server_addr()
            .to_ip()
            .ok_or("the server has no IP address")?;
        let state = Arc::new(State {
            folder: SceneFolder(config.scenes),
            pages: Pages::default(),
        });
        let workers = (0..WORKERS)
            .map(|i| {
                let (server, state) = (server.clone(), state.clone());
                std::thread::Builder::new()
                    .name(format!("lab-http-{i}"))
                    .spawn(move || {
                        while let Ok(request) = server.recv() {
                            answer(&state, request);
                        }
                    })
                    .map_err(|e| format!("cannot start the lab's threads: {e}"))
            })
            .collect::<Result<Vec<_>, _>>()?;
        // Closed pages: their renders stop after a while without a request.
        let watched = Arc::downgrade(&state);
        std::thread::Builder::new()
            .name("lab-idle".into())
            .spawn(move || {
                while let Some(state) = watched.upgrade() {
                    state.pages.stop_idle(IDLE);
                    drop(state);
                    std::thread::sleep(Duration::from_secs(1));
                }
            })
            .map_err(|e| format!("cannot start the lab's threads: {e}"))?;
        Ok(Lab {
            server,
            state,
            workers,
            address,
        })
    }

    /// The page's address, e.g. `http://127.0.0.1:8011/` (see [`page_url`]).
    pub fn url(&self) -> String {
        page_url(self.address)
    }

    /// The pages and their renders (for the tests).
    pub fn pages(&self) -> &Pages {
        &self.state.pages
    }

    /// Stops the renders and the server.
    pub fn stop(self) {
        self.state.pages.stop_all();
        self.server.unblock();
        for _ in 1..WORKERS {
            self.server.unblock();
        }
        for w in self.workers {
            let _ = w.join();
        }
    }
}

/// An answer: status, content type, body and extra headers.
struct Reply {
    status: u16,
    content_type: &'static str,
    body: Vec<u8>,
    headers: Vec<(&'static str, String)>,
}

impl Reply {
    fn ok(content_type: &'static str, body: impl Into<Vec<u8>>) -> Reply {
        Reply {
            status: 200,
            content_type,
            body: body.into(),
            headers: Vec::new(),
        }
    }

    fn json(value: &impl Serialize) -> Reply {
        match serde_json::to_vec(value) {
            Ok(body) => Reply::ok("application/json", body),
            Err(e) => Reply::text(500, format!("cannot write JSON: {e}")),
        }
    }

    /// One line of text (an error's reason).
    fn text(status: u16, line: impl Into<String>) -> Reply {
        let mut line: String = line.into();
        line.retain(|c| c != '\n' && c != '\r');
        line.push('\n');
        Reply {
            status,
            content_type: "text/plain; charset=utf-8",
            body: line.into_bytes(),
            headers: Vec::new(),
        }
    }

    fn bad(reason: String) -> Reply {
        Reply::text(400, reason)
    }

    fn header(mut self, name: &'static str, value: impl ToString) -> Reply {
        self.headers.push((name, value.to_string()));
        self
    }
}

/// Answers one request; a panic in a handler becomes a 500 and the lab goes on.
/// The answer speaks the page's language: the page sends it as
/// `Accept-Language` (`bg` or `en`), the lab's own language otherwise; a
/// render started by the request keeps it for its notes and errors.
fn answer(state: &State, request: Request) {
    let method = request.method().clone();
    let url = request.url().to_string();
    let language = request
        .headers()
        .iter()
        .find(|h| h.field.equiv("Accept-Language"))
        .and_then(|h| lang::Lang::parse(h.value.as_str()))
        .unwrap_or_else(lang::current);
    let reply = lang::with(language, || {
        std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| route(state, &method, &url)))
            .unwrap_or_else(|_| {
                Reply::text(
                    500,
                    lang::pick(
                        "internal error (the lab goes on; please report it)",
                        "вътрешна грешка (лабораторията продължава; моля, съобщете за нея)",
                    ),
                )
            })
    });
    // Always a Content-Length (the body is in memory), never chunks.
    let mut response = Response::from_data(reply.body)
        .with_status_code(reply.status)
        .with_chunked_threshold(usize::MAX);
    let headers = [
        ("Content-Type", reply.content_type.to_string()),
        ("Cache-Control", "no-store".to_string()),
        ("X-Content-Type-Options", "nosniff".to_string()),
    ];
    for (name, value) in headers.into_iter().chain(reply.headers) {
        if let Ok(h) = Header::from_bytes(name.as_bytes(), value.as_bytes()) {
            response.add_header(h);
        }
    }
    // The client may have gone; nothing to do then.
    let _ = request.respond(response);
}

/// The answer to `method url`.
fn route(state: &State, method: &Method, url: &str) -> Reply {
    let (path, query) = url.split_once('?').unwrap_or((url, ""));
    let post = |allowed: &[&str], handler: &dyn Fn(&Query) -> Result<Reply, String>| {
        if *method != Method::Post {
            return Reply::text(405, format!("{path} takes POST")).header("Allow", "POST");
        }
        Query::parse(query, allowed)
            .and_then(|q| handler(&q))
            .unwrap_or_else(Reply::bad)
    };
    let get = |allowed: &[&str], handler: &dyn Fn(&Query) -> Result<Reply, String>| {
        if *method != Method::Get {
            return Reply::text(405, format!("{path} takes GET")).header("Allow", "GET");
        }
        Query::parse(query, allowed)
            .and_then(|q| handler(&q))
            .unwrap_or_else(Reply::bad)
    };
    match path {
        // `?lang=bg` opens the page in Bulgarian.
        "/" | "/index.html" => get(&["lang"], &|_| {
            Ok(Reply::ok("text/html; charset=utf-8", INDEX_HTML))
        }),
        "/lab.css" => get(&[], &|_| Ok(Reply::ok("text/css; charset=utf-8", LAB_CSS))),
        "/lab.js" => get(&[], &|_| {
            Ok(Reply::ok("text/javascript; charset=utf-8", LAB_JS))
        }),
        "/i18n.js" => get(&[], &|_| {
            Ok(Reply::ok("text/javascript; charset=utf-8", I18N_JS))
        }),
        "/favicon.svg" | "/favicon.ico" => get(&[], &|_| Ok(Reply::ok("image/svg+xml", FAVICON))),
        "/api/scenes" => get(&[], &|_| Ok(Reply::json(&catalogue(state)))),
        "/api/render" => post(&with(&[RENDER_PARAMS]), &|q| {
            let setup = render_setup(q, &state.folder, "cornell", "direct")?;
            let spec = super::job::JobSpec {
                kind: "render",
                command: format!(
                    "cargo run --release -p lesson11 -- render {}",
                    setup.options_line
                ),
                eyes: vec![setup.scene],
                build_for: None,
                plan: setup.plan,
                options: setup.options,
                student: None,
                race: None,
                wavefront: setup.wavefront,
            };
            started(state.pages.start(q.page()?, spec)?)
        }),
        "/api/stereo" => post(&with(&[RENDER_PARAMS, RIG_PARAMS]), &|q| {
            let spec = stereo::stereo_job(q, &state.folder)?;
            started(state.pages.start(q.page()?, spec)?)
        }),
        "/api/race" => post(&with(&[RENDER_PARAMS, RACE_PARAMS]), &|q| {
            let spec = race::race_job(q, &state.folder)?;
            started(state.pages.start(q.page()?, spec)?)
        }),
        "/api/student" => post(&with(&[RENDER_PARAMS]), &|q| {
            let spec = student::student_job(q, &state.folder)?;
            started(state.pages.start(q.page()?, spec)?)
        }),
        "/api/zmap.png" => get(&["page", "job", "v"], &|q| {
            let job = page_job(state, q)?;
            let map = ZMap::of(&job).ok_or(lang::pick(
                "no z-map: the page's render is not of the \"Your code\" tab, or has no picture yet",
                "няма z-карта: рендерът на страницата не е от раздела „Вашият код“ или още няма картина",
            ))?;
            let image = map.image(job.width, job.height);
            Ok(png(&image, 0.0, &job)?
                .header("X-Lab-Verdict", map.verdict())
                .header(
                    "X-Lab-Verdict-Numbers",
                    map.verdict_numbers().map(|v| v.to_string()).join(","),
                )
                .header("X-Lab-Consistent", map.consistent()))
        }),
        "/api/brdf-sphere" => post(&with(&[BRDF_PARAMS, &["spp", "seed"]]), &|q| {
            let choice = brdf::choose(q)?;
            let spec = brdf::sphere_job(q, &choice)?;
            started(state.pages.start(q.page()?, spec)?)
        }),
        "/api/stop" => post(&["page"], &|q| {
            state.pages.stop(q.page()?);
            Ok(Reply::text(200, "stopped"))
        }),
        "/api/status" => get(&["page", "after"], &|q| {
            let page = q.page()?;
            let job = state.pages.job(page);
            if let (Some(job), Some(after)) = (&job, q.get("after")) {
                let after: u64 = after
                    .parse()
                    .map_err(|_| format!("`after` must be a snapshot number, got {after:?}"))?;
                job.wait_newer(after, LONGEST_POLL);
            }
            Ok(Reply::json(&PageStatus {
                job: job.map(|j| j.status()),
                previous: state.pages.previous(page).map(|j| j.status()),
                running_renders: state
                    .pages
                    .running
                    .load(std::sync::atomic::Ordering::SeqCst),
            }))
        }),
        "/api/image.png" => get(&["page", "job", "exposure", "eye", "v"], &|q| {
            let exposure = q.in_range("exposure", 0.0, -64.0..=64.0)?;
            let (job, image) = eye_image(state, q, Job::shown_images)?;
            png(&image, exposure, &job)
        }),
        "/api/image.exr" => get(&["page", "job", "eye", "v"], &|q| {
            let (job, image) = eye_image(state, q, Job::images)?;
            let bytes = image.exr_bytes().map_err(|e| e.to_string())?;
            Ok(with_progress(Reply::ok("image/x-exr", bytes), &job))
        }),
        "/api/stereo.png" => get(
            &with(&[COMPOSITE_PARAMS, &["job", "exposure", "v"]]),
            &|q| {
                let exposure = q.in_range("exposure", 0.0, -64.0..=64.0)?;
                let job = page_job(state, q)?;
                let images = job.shown_images();
                let (Some(Some(left)), Some(Some(right))) = (images.first(), images.get(1)) else {
                    return Err(lang::pick(
                        "the page's render is not a stereo pair (start one with /api/stereo), or has no picture yet",
                        "рендерът на страницата не е стереодвойка (започнете я с /api/stereo) или още няма картина",
                    )
                    .into());
                };
                png(&stereo::compose(q, left, right)?, exposure, &job)
            },
        ),
        "/api/brdf" => get(BRDF_PARAMS, &|q| {
            let choice = brdf::choose(q)?;
            let theta = q.in_range("theta", 30.0, 0.0..=89.0)?;
            Ok(Reply::json(&brdf::analyse(&choice, theta)))
        }),
        "/api/paths" => get(&["page", "x", "y", "sample"], &|q| paths(state, q)),
        _ => Reply::text(
            404,
            lang::pick(
                format!("no such page: {path}"),
                format!("няма такава страница: {path}"),
            ),
        ),
    }
}

/// `page` and the parameters of `extra`.
fn with(extra: &[&[&'static str]]) -> Vec<&'static str> {
    let mut all = vec!["page"];
    extra.iter().for_each(|e| all.extend_from_slice(e));
    all
}

/// The page's render, or a reason why there is none; with `job=ID`, only
/// that render (a picture asked for just before a new render started must
/// not show the new render's picture under the old one's numbers).
fn page_job(state: &State, q: &Query) -> Result<Arc<Job>, String> {
    let job = state.pages.job(q.page()?).ok_or_else(|| {
        lang::pick(
            "this page has no render yet: start one first",
            "тази страница още няма рендер: започнете един",
        )
        .to_string()
    })?;
    match q.get("job") {
        Some(id) if id != job.id.to_string() => Err(lang::pick(
            format!("render {id} of this page was replaced by render {}", job.id),
            format!("рендер {id} на тази страница е заменен с рендер {}", job.id),
        )),
        _ => Ok(job),
    }
}

/// One eye's latest picture (`eye`, 0 unless given) of those `which` gives
/// (the film's, or what the page shows).
fn eye_image(
    state: &State,
    q: &Query,
    which: fn(&Job) -> Vec<Option<Arc<raytracer::film::Image>>>,
) -> Result<(Arc<Job>, Arc<raytracer::film::Image>), String> {
    let job = page_job(state, q)?;
    let eye: usize = q.number("eye", 0)?;
    let images = which(&job);
    let image = images
        .get(eye)
        .ok_or_else(|| format!("`eye` must be below {}, got {eye}", images.len()))?
        .clone()
        .ok_or(lang::pick(
            "no picture yet: the first snapshot comes within a moment",
            "още няма картина: първата идва след миг",
        ))?;
    Ok((job, image))
}

fn png(image: &raytracer::film::Image, exposure: f32, job: &Job) -> Result<Reply, String> {
    let bytes = image.png_bytes(exposure).map_err(|e| e.to_string())?;
    Ok(with_progress(Reply::ok("image/png", bytes), job))
}

/// Headers that say how far the picture has come.
fn with_progress(reply: Reply, job: &Job) -> Reply {
    let s = job.status();
    reply
        .header("X-Lab-Job", s.id)
        .header("X-Lab-Version", s.version)
        .header("X-Lab-Spp", format!("{:.3}", s.spp))
        .header("X-Lab-Complete-Spp", s.complete_spp)
        .header("X-Lab-Done", s.done)
}

/// The answer to a start request: the new job's status.
fn started(job: Arc<Job>) -> Result<Reply, String> {
    Ok(Reply::json(&job.status()))
}

#[derive(Serialize)]
struct PageStatus {
    job: Option<super::job::JobStatus>,
    previous: Option<super::job::JobStatus>,
    running_renders: usize,
}

#[derive(Serialize)]
struct Catalogue {
    scenes: Vec<super::settings::SceneEntry>,
    /// `[name, what it does]` of every `--integrator` value.
    integrators: Vec<[String; 2]>,
    /// The integrators that render whole images (SPPM, Metropolis): the
    /// Render tab has them, the Stereo tab (pixel samples) not.
    whole_image: Vec<String>,
    composites: Vec<&'static str>,
    max_pixels: u64,
    max_spp: u32,
}

fn catalogue(state: &State) -> Catalogue {
    Catalogue {
        scenes: state.folder.list(),
        integrators: IntegratorKind::value_variants()
            .iter()
            .filter_map(|k| k.to_possible_value())
            .map(|v| {
                [
                    v.get_name().to_string(),
                    v.get_help().map(|h| h.to_string()).unwrap_or_default(),
                ]
            })
            .collect(),
        whole_image: IntegratorKind::value_variants()
            .iter()
            .filter(|k| !k.renders_pixel_samples())
            .filter_map(|k| k.to_possible_value())
            .map(|v| v.get_name().to_string())
            .collect(),
        composites: stereo::composite_names(),
        max_pixels: MAX_PIXELS,
        max_spp: MAX_SPP,
    }
}

/// The inspector: the paths of pixel (x, y), sample k of the page's render.
fn paths(state: &State, q: &Query) -> Result<Reply, String> {
    let job = page_job(state, q)?;
    let x: u32 = q.number("x", u32::MAX)?;
    let y: u32 = q.number("y", u32::MAX)?;
    if x >= job.width || y >= job.height {
        return Err(lang::pick(
            format!(
                "the pixel ({x}, {y}) is outside the {}×{} picture (give x and y)",
                job.width, job.height
            ),
            format!(
                "пикселът ({x}, {y}) е извън картината {}×{} (дайте x и y)",
                job.width, job.height
            ),
        ));
    }
    let sample: u32 = q.number("sample", 0)?;
    if sample >= job.target_spp {
        return Err(lang::pick(
            format!(
                "“sample k” must be below the render's {} spp, got {sample}",
                job.target_spp
            ),
            format!(
                "„проба k“ трябва да е под {} проби на пиксел на рендера, а е {sample}",
                job.target_spp
            ),
        ));
    }
    let Some(scene) = job.scene() else {
        return Err(lang::pick(
            "the inspector shows the paths of the Render tab's picture",
            "инспекторът показва пътищата на картината от раздела „Рендер“",
        )
        .into());
    };
    let integrator = job.integrator()?;
    let record = super::paths::record(integrator.as_ref(), &scene, [x, y], sample, job.seed())?;
    Ok(Reply::json(&record))
}

/// The address to open the page of a lab listening on `address`. A lab
/// listening on every interface (`--host 0.0.0.0` or `::`) is opened on this
/// machine by its loopback address: `http://0.0.0.0:P/` is no address to open.
pub fn page_url(mut address: SocketAddr) -> String {
    if address.ip().is_unspecified() {
        address.set_ip(if address.is_ipv4() {
            std::net::Ipv4Addr::LOCALHOST.into()
        } else {
            std::net::Ipv6Addr::LOCALHOST.into()
        });
    }
    format!("http://{address}/")
}
