//! The lab in process: the path inspector's endpoint answers the recorded
//! sample with every vertex projected into the picture, a page that stops
//! asking has its render stopped, and a biased integrator is built on its
//! render's thread.

use std::io::{Read, Write};
use std::net::{SocketAddr, TcpStream};
use std::time::Duration;

use serde_json::Value;

use lesson11::commands::lab::{Lab, LabConfig};

fn start() -> Lab {
    Lab::start(SocketAddr::from(([127, 0, 0, 1], 0)), LabConfig::default()).unwrap()
}

fn request(lab: &Lab, method: &str, path: &str) -> (u16, String) {
    let address = lab
        .url()
        .trim_start_matches("http://")
        .trim_end_matches('/')
        .to_string();
    let mut s = TcpStream::connect(&address).unwrap();
    write!(
        s,
        "{method} {path} HTTP/1.1\r\nHost: {address}\r\nConnection: close\r\n\r\n"
    )
    .unwrap();
    let mut bytes = Vec::new();
    s.read_to_end(&mut bytes).unwrap();
    let text = String::from_utf8_lossy(&bytes).into_owned();
    let status = text.split_whitespace().nth(1).unwrap().parse().unwrap();
    let body = text.split_once("\r\n\r\n").unwrap().1.to_string();
    (status, body)
}

/// The path tracer's record of a pixel: the camera ray leaves the lens and
/// its first hit projects into the clicked pixel; shadow rays end on the
/// lamp, which the picture shows.
#[test]
fn the_inspector_serves_a_record_projected_into_the_picture() {
    let lab = start();
    let render = "/api/render?page=t&width=64&height=64&spp=1&integrator=path&max-depth=4";
    let (status, _) = request(&lab, "POST", render);
    assert_eq!(status, 200);
    let (status, body) = request(&lab, "GET", "/api/paths?page=t&x=20&y=40&sample=0");
    assert_eq!(status, 200, "{body}");
    let r: Value = serde_json::from_str(&body).unwrap();
    assert_eq!(r["pixel"], serde_json::json!([20, 40]));
    assert_eq!(r["integrator"], "path");
    let camera = &r["paths"][0];
    assert_eq!(camera["role"], "camera");
    assert_eq!(camera["vertices"][0]["kind"], "camera");
    assert_eq!(camera["vertices"][1]["pdf"]["measure"], "solid-angle");
    assert!(camera["vertices"][1]["brdf"].is_string(), "{r}");
    let raster = &camera["vertices"][1]["raster"];
    let (x, y) = (raster[0].as_f64().unwrap(), raster[1].as_f64().unwrap());
    assert!(
        (20.0..21.0).contains(&x) && (40.0..41.0).contains(&y),
        "{raster}"
    );
    let shadow = r["segments"].as_array().unwrap();
    assert!(!shadow.is_empty(), "{r}");
    for s in shadow {
        assert_eq!(s["kind"], "shadow-ray");
        assert!(
            s["to"]["point"]["raster"].is_array(),
            "the lamp is in the picture: {s}"
        );
    }
    // Out of the picture, or past the render's samples: 400 with a reason.
    for bad in ["x=64&y=0&sample=0", "x=1&y=1&sample=1"] {
        let (status, body) = request(&lab, "GET", &format!("/api/paths?page=t&{bad}"));
        assert_eq!(status, 400, "{bad}: {body}");
    }
    lab.stop();
}

/// A page that stops asking (a closed tab) has its render stopped; one
/// that asks keeps it.
#[test]
fn the_render_of_a_closed_page_stops() {
    let lab = start();
    for page in ["gone", "here"] {
        let (status, _) = request(
            &lab,
            "POST",
            &format!("/api/render?page={page}&width=32&height=32&spp=65536"),
        );
        assert_eq!(status, 200);
    }
    std::thread::sleep(Duration::from_millis(300));
    request(&lab, "GET", "/api/status?page=here");
    lab.pages().stop_idle(Duration::from_millis(200));
    std::thread::sleep(Duration::from_millis(300));
    let done = |page: &str| {
        let (_, body) = request(&lab, "GET", &format!("/api/status?page={page}"));
        let s: Value = serde_json::from_str(&body).unwrap();
        s["job"]["done"] == true && s["job"]["interrupted"] == true
    };
    assert!(done("gone"), "the render of the page that went away stops");
    assert!(!done("here"), "the render of the page that asks goes on");
    lab.stop();
}

/// Photon mapping's maps are built on the render's own thread: the request
/// that starts it answers at once, in the build phase; the inspector asks
/// to wait until the maps are built, then records photon mapping's samples.
#[test]
fn a_biased_integrator_is_built_on_the_jobs_thread() {
    crate::english();
    let lab = start();
    let render = "/api/render?page=b&width=16&height=16&spp=1&integrator=photon";
    let (status, body) = request(&lab, "POST", render);
    assert_eq!(status, 200, "{body}");
    let s: Value = serde_json::from_str(&body).unwrap();
    assert_eq!(s["phase"], "building", "{s}");
    let inspect = "/api/paths?page=b&x=8&y=8&sample=0";
    let (status, body) = request(&lab, "GET", inspect);
    if status != 200 {
        assert_eq!(status, 400, "{body}");
        assert!(body.contains("still building the photon maps"), "{body}");
    }
    let end = std::time::Instant::now() + Duration::from_secs(60);
    loop {
        let (_, body) = request(&lab, "GET", "/api/status?page=b");
        let s: Value = serde_json::from_str(&body).unwrap();
        if s["job"]["done"] == true {
            assert_eq!(s["job"]["interrupted"], false, "{s}");
            assert!(
                s["job"]["note"]
                    .as_str()
                    .unwrap()
                    .starts_with("photon maps: ")
            );
            break;
        }
        assert!(std::time::Instant::now() < end, "not done: {s}");
        std::thread::sleep(Duration::from_millis(20));
    }
    let (status, body) = request(&lab, "GET", inspect);
    assert_eq!(status, 200, "{body}");
    let r: Value = serde_json::from_str(&body).unwrap();
    assert_eq!(r["integrator"], "photon");
    // The inspector says the same of photon mapping wherever it speaks of
    // it: its record says it records no paths, so SPPM's note must not send
    // the student to photon mapping's paths (it said "photon mapping's are").
    assert!(
        r["truncated"]
            .as_str()
            .is_some_and(|t| t.contains("does not record its paths")),
        "{r}"
    );
    assert!(
        lesson11::commands::lab::job::SPPM_NO_SAMPLES.contains("photon mapping does not record")
    );
    lab.stop();
}

/// A "student" integrator for the tests of the "Your code" tab: the path
/// tracer, but wrong in a way chosen by `fault`.
struct Faulty {
    fault: Fault,
}

#[derive(Clone, Copy)]
enum Fault {
    /// Half the light on the left half of the picture (x < 32).
    HalfOnTheLeft,
    /// A panic at pixel (5, 5).
    Panics,
    /// NaN at every pixel of row 0.
    NanOnRowZero,
}

impl raytracer::integrator::Integrator for Faulty {
    fn name(&self) -> &'static str {
        "faulty"
    }

    fn sample(
        &self,
        scene: &raytracer::scene::Scene,
        pixel: raytracer::math::UVec2,
        sampler: &mut raytracer::sampling::Sampler,
        splats: &mut Vec<raytracer::film::Splat>,
    ) -> raytracer::math::Color {
        let c = raytracer::integrator::PathTracer::default().sample(scene, pixel, sampler, splats);
        match self.fault {
            Fault::HalfOnTheLeft if pixel.x < 32 => c * 0.5,
            Fault::Panics if pixel.x == 5 && pixel.y == 5 => panic!("index out of bounds"),
            Fault::NanOnRowZero if pixel.y == 0 => raytracer::math::Color::splat(f32::NAN),
            _ => c,
        }
    }
}

/// The "Your code" tab's job with `student` as the student's integrator,
/// beside the path tracer, on a 64×64 Cornell box; waits until it ends.
fn student_job(
    lab: &Lab,
    page: &str,
    student: Box<dyn raytracer::integrator::Integrator + Send>,
    spp: u32,
) -> std::sync::Arc<lesson11::commands::lab::job::Job> {
    use raytracer::integrator::PathTracer;
    let mut scene = raytracer::scene::Scene::builtin("cornell").unwrap();
    scene.set_resolution(64, 64);
    let spec = lesson11::commands::lab::job::JobSpec {
        kind: "student",
        command: String::new(),
        eyes: vec![scene.clone(), scene],
        build_for: None,
        plan: lesson11::integrators::IntegratorPlan::Ready(Box::new(PathTracer::default())),
        options: raytracer::render::RenderOptions {
            spp,
            progress: false,
            ..Default::default()
        },
        wavefront: None,
        student: Some(lesson11::commands::lab::job::StudentPair {
            exercise: "ex13_mis",
            make: Box::new(move || (student, Box::new(PathTracer::default()))),
        }),
        race: None,
    };
    let job = lab.pages().start(page, spec).unwrap();
    let end = std::time::Instant::now() + Duration::from_secs(120);
    while !job.status().done {
        assert!(std::time::Instant::now() < end, "not done");
        std::thread::sleep(Duration::from_millis(20));
    }
    job
}

fn faulty_job(
    lab: &Lab,
    page: &str,
    fault: Fault,
    spp: u32,
) -> std::sync::Arc<lesson11::commands::lab::job::Job> {
    student_job(lab, page, Box::new(Faulty { fault }), spp)
}

/// Issue 27, "your integrator, live": a deliberately wrong integrator (half
/// the light on the left half) is shown by the z-map where it is wrong: red
/// tiles on the left, none on the right; over HTTP, the map and its verdict.
#[test]
fn the_z_map_shows_where_a_wrong_integrator_differs() {
    let lab = start();
    let job = faulty_job(&lab, "z", Fault::HalfOnTheLeft, 64);
    assert_eq!(job.status().error, None);
    let map = lesson11::commands::lab::student::ZMap::of(&job).expect("both pictures");
    assert!(!map.consistent(), "{}", map.verdict());
    let grid = map.test.grid;
    assert_eq!((grid.x, grid.y), (4, 4));
    let red = |tx: u32, ty: u32| {
        map.test.z[(ty * grid.x + tx) as usize].abs().max_element() as f64 > map.threshold
    };
    let left = (0..4).flat_map(|ty| (0..2).map(move |tx| (tx, ty)));
    let right = (0..4).flat_map(|ty| (2..4).map(move |tx| (tx, ty)));
    assert!(
        left.filter(|&(x, y)| red(x, y)).count() >= 4,
        "{}",
        map.verdict()
    );
    assert_eq!(
        right.filter(|&(x, y)| red(x, y)).count(),
        0,
        "{}",
        map.verdict()
    );
    let (status, _) = request(&lab, "GET", "/api/zmap.png?page=z");
    assert_eq!(status, 200);
    lab.stop();
}

/// The same integrator that is right everywhere gives no red tile.
#[test]
fn the_z_map_of_a_right_integrator_is_consistent() {
    let lab = start();
    let right = Box::new(raytracer::integrator::PathTracer::default());
    let job = student_job(&lab, "ok", right, 64);
    let map = lesson11::commands::lab::student::ZMap::of(&job).unwrap();
    assert!(map.consistent(), "{}", map.verdict());
    lab.stop();
}

/// A student's panic is a message on the page, and the lab goes on; a
/// student's NaN samples are counted as the student's.
#[test]
fn a_students_panic_or_nan_is_a_message_not_a_crash() {
    crate::english();
    let lab = start();
    let job = faulty_job(&lab, "p", Fault::Panics, 4);
    let s = job.status();
    let e = s.error.expect("the panic is reported");
    assert!(
        e.contains("panicked at pixel (5, 5)") && e.contains("index out of bounds"),
        "{e}"
    );
    let (status, _) = request(&lab, "GET", "/api/scenes");
    assert_eq!(status, 200, "the lab goes on");
    let job = faulty_job(&lab, "n", Fault::NanOnRowZero, 2);
    let s = job.status();
    assert_eq!(s.error, None);
    assert_eq!(s.nonfinite_by_eye, vec![64 * 2, 0]);
    lab.stop();
}
