//! The path inspector end to end with an example record in place of the
//! recorder (which `raytracer` does not have yet): the endpoint answers the
//! record as JSON with every vertex projected into the picture, and the page
//! draws it over the picture in headless Chromium.

#[path = "../../../tests/support/chromium.rs"]
mod chromium;

use std::io::{Read, Write};
use std::net::{SocketAddr, TcpStream};
use std::time::Duration;

use raytracer::math::{Vec2, Vec3A};
use serde_json::Value;

use super::paths::{
    Measure, PathQuery, PathRecord, PathRole, PathVertex, Pdf, RecordedPath, Segment, SegmentEnd,
    SegmentKind, VertexKind, VertexRef,
};
use super::{Lab, LabConfig};

/// An example of the record's shape (not an integrator's record): the
/// camera ray through the pixel's centre, its first hit, one bounce towards
/// the back wall, and a shadow ray from the first hit to the ceiling light.
fn example(q: &PathQuery) -> Result<PathRecord, String> {
    let camera = &q.scene.camera;
    let centre = Vec2::new(q.pixel[0] as f32 + 0.5, q.pixel[1] as f32 + 0.5);
    let ray = camera.generate_ray(centre, Vec2::splat(0.5));
    let first = q.scene.intersect(&ray).ok_or("the pixel sees nothing")?;
    let towards_wall = (Vec3A::new(0.0, 0.0, -1.0) - first.p).normalize();
    let second = q
        .scene
        .intersect(&raytracer::math::Ray::new(
            first.p + 1e-3 * first.ng,
            towards_wall,
        ))
        .ok_or("the bounce sees nothing")?;
    let vertex = |p: Vec3A, kind, pdf: Option<Pdf>| PathVertex {
        position: p.to_array(),
        raster: None,
        kind,
        brdf: (kind == VertexKind::Surface).then(|| "white".to_string()),
        pdf,
        throughput: [0.5; 3],
        mis_weight: None,
        contribution: [0.0; 3],
    };
    Ok(PathRecord {
        integrator: q.integrator.to_string(),
        pixel: q.pixel,
        sample: q.sample,
        estimate: [0.1, 0.2, 0.3],
        paths: vec![RecordedPath {
            role: PathRole::Camera,
            parent: None,
            vertices: vec![
                vertex(camera.position(), VertexKind::Camera, None),
                vertex(
                    first.p,
                    VertexKind::Surface,
                    Some(Pdf {
                        value: 1.0,
                        measure: Measure::Area,
                    }),
                ),
                vertex(
                    second.p,
                    VertexKind::Surface,
                    Some(Pdf {
                        value: 0.3,
                        measure: Measure::SolidAngle,
                    }),
                ),
            ],
        }],
        segments: vec![Segment {
            kind: SegmentKind::ShadowRay,
            from: VertexRef { path: 0, vertex: 1 },
            to: SegmentEnd::Point {
                position: [0.0, 0.99, 0.0],
                raster: None,
            },
            occluded: false,
            strategy: None,
            mis_weight: Some(0.75),
            contribution: [0.1, 0.2, 0.3],
        }],
        truncated: None,
    })
}

fn start() -> Lab {
    let config = LabConfig {
        paths: example,
        ..LabConfig::default()
    };
    Lab::start(SocketAddr::from(([127, 0, 0, 1], 0)), config).unwrap()
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
    let mut text = String::new();
    s.read_to_string(&mut text).unwrap();
    let status = text.split_whitespace().nth(1).unwrap().parse().unwrap();
    let body = text.split_once("\r\n\r\n").unwrap().1.to_string();
    (status, body)
}

#[test]
fn the_inspector_serves_a_record_projected_into_the_picture() {
    let lab = start();
    let (status, _) = request(&lab, "POST", "/api/render?page=t&width=64&height=64&spp=1");
    assert_eq!(status, 200);
    let (status, body) = request(&lab, "GET", "/api/paths?page=t&x=20&y=40&sample=0");
    assert_eq!(status, 200, "{body}");
    let r: Value = serde_json::from_str(&body).unwrap();
    assert_eq!(r["pixel"], serde_json::json!([20, 40]));
    assert_eq!(r["paths"][0]["role"], "camera");
    assert_eq!(r["paths"][0]["vertices"][1]["pdf"]["measure"], "area");
    assert_eq!(r["segments"][0]["kind"], "shadow-ray");
    // The first hit lies on the ray through the pixel's centre: it projects there.
    let raster = &r["paths"][0]["vertices"][1]["raster"];
    let (x, y) = (raster[0].as_f64().unwrap(), raster[1].as_f64().unwrap());
    assert!(
        (x - 20.5).abs() < 1e-2 && (y - 40.5).abs() < 1e-2,
        "{raster}"
    );
    assert!(r["segments"][0]["to"]["point"]["raster"].is_array(), "{r}");
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

/// The page draws the record: the path, its vertices and the shadow ray
/// over the picture, and a table row per vertex and segment.
#[test]
fn the_page_draws_the_paths_over_the_picture() {
    let Some(chromium) = chromium::chromium() else {
        eprintln!("skipped: no chromium, so the inspector's drawing was not tried in a browser");
        return;
    };
    let lab = start();
    let dom = chromium::run(
        &chromium,
        &format!("{}#selftest", lab.url()),
        &[
            "--window-size=1300,900".into(),
            "--virtual-time-budget=120000".into(),
            "--dump-dom".into(),
        ],
        Duration::from_secs(240),
    )
    .unwrap();
    lab.stop();
    let report = chromium::selftest_report(&dom).expect("a #selftest report");
    let r: Value = serde_json::from_str(&report).unwrap();
    assert_eq!(r["inspector"]["status"], 200, "{r}");
    // The clicked pixel, one path, its three vertices, one shadow ray.
    assert_eq!(r["inspector"]["marks"], 1 + 1 + 3 + 1, "{r}");
    assert_eq!(r["inspector"]["rows"], 3 + 1, "{r}");
    assert!(
        r["inspector"]["text"]
            .as_str()
            .unwrap()
            .contains("estimate (0.100, 0.200, 0.300)"),
        "{r}"
    );
}
