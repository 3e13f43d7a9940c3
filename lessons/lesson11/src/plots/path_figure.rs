//! Path figures: one recorded pixel sample drawn over the picture it
//! belongs to, in the camera's projection — the slides' pictures of a naive
//! recursion tree, a path-tracing path with its shadow rays, a light path
//! joined to the camera, and two subpaths joined by a connection `(s, t)`.
//!
//! The record comes from `raytracer`'s path recorder, the one the lab's
//! path inspector draws. In its own projection the camera sees every ray
//! that leaves the lens as a single point (the pixel), so the lens `x₀` is
//! drawn below the picture and the rays that reach it (the camera ray, light
//! tracing's connections to the camera) are drawn to it. Figures carry
//! symbols only (`x₀ …`, `y₀ …`, `(s, t)`), no words, so that one file serves
//! the slides of every language.

use std::fmt::Write as _;

use raytracer::integrator::Integrator;
use raytracer::integrator::record::{
    PathRecord, PathRole, SegmentEnd, SegmentKind, VertexKind, VertexRef, record_sample,
};
use raytracer::math::UVec2;
use raytracer::scene::Scene;

use super::data_uri::png_data_uri;

/// Vertex labels drawn beside the vertices.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Labels {
    None,
    /// `x₀ x₁ …` on camera paths, `y₀ y₁ …` on light paths.
    Subpaths,
}

const CAMERA: &str = "#ffd23f";
const LIGHT: &str = "#5cc8ff";
const BRANCH: &str = "#d08cff";
const SHADOW: &str = "#7dff7d";
const BLOCKED: &str = "#ff6b6b";
const CONNECTION: &str = "#ff6bd5";

/// The SVG of `record` (projected with [`PathRecord::project`] by the
/// camera of a `width`×`height` picture) over that picture (`png`).
pub fn path_figure_svg(
    record: &PathRecord,
    png: &[u8],
    (width, height): (u32, u32),
    labels: Labels,
) -> String {
    let (w, h) = (width as f32, height as f32);
    let unit = w.max(h) / 200.0;
    let margin = 0.16 * h;
    let lens = [w / 2.0, h + 0.5 * margin];
    let pixel = [record.pixel[0] as f32 + 0.5, record.pixel[1] as f32 + 0.5];
    // Where a vertex is drawn: its projection; the lens below the picture.
    let at = |r: VertexRef| -> Option<[f32; 2]> {
        let v = record.vertex(r);
        if v.kind == VertexKind::Camera {
            Some(lens)
        } else {
            v.raster
        }
    };
    let mut s = String::new();
    let _ = writeln!(
        s,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" viewBox=\"0 0 {w} {}\" \
         font-family=\"serif\" font-style=\"italic\" font-size=\"{}\">",
        640.0,
        640.0 * (h + margin) / w,
        h + margin,
        7.0 * unit
    );
    let _ = writeln!(
        s,
        "<rect width=\"{w}\" height=\"{}\" fill=\"#111\"/><clipPath id=\"picture\"><rect width=\"{w}\" height=\"{h}\"/></clipPath>",
        h + margin
    );
    let _ = writeln!(
        s,
        "<image href=\"{}\" width=\"{w}\" height=\"{h}\" image-rendering=\"pixelated\"/>",
        png_data_uri(png)
    );
    // Dimmed a little, so that the paths stand out.
    let _ = writeln!(
        s,
        "<rect width=\"{w}\" height=\"{h}\" fill=\"#000\" opacity=\"0.3\"/>"
    );
    let line = |s: &mut String, a: [f32; 2], b: [f32; 2], colour: &str, width: f32, dash: bool| {
        let dash = if dash {
            format!(" stroke-dasharray=\"{} {}\"", 3.0 * unit, 2.0 * unit)
        } else {
            String::new()
        };
        let _ = writeln!(
            s,
            "<line x1=\"{:.2}\" y1=\"{:.2}\" x2=\"{:.2}\" y2=\"{:.2}\" stroke=\"{colour}\" stroke-width=\"{:.2}\"{dash}/>",
            a[0],
            a[1],
            b[0],
            b[1],
            width * unit
        );
    };
    // Rays inside the picture are clipped to it; those that reach the lens are not.
    let mut inside = String::new();
    let mut to_lens = String::new();
    // Shadow rays and connections first, under the paths.
    for seg in &record.segments {
        let Some(a) = at(seg.from) else { continue };
        let colour = match seg.kind {
            _ if seg.occluded => BLOCKED,
            SegmentKind::ShadowRay => SHADOW,
            SegmentKind::Connection => CONNECTION,
        };
        if seg.splat.is_some() {
            // Light tracing's t = 1: the vertex joined to the lens.
            line(&mut to_lens, a, lens, colour, 0.8, true);
            continue;
        }
        let b = match &seg.to {
            SegmentEnd::Vertex(r) => at(*r),
            SegmentEnd::Point { raster, .. } => *raster,
        };
        let Some(b) = b else { continue };
        line(&mut inside, a, b, colour, 0.9, true);
        if let Some([s_, t]) = seg.strategy
            && seg.kind == SegmentKind::Connection
        {
            let _ = writeln!(
                inside,
                "<text x=\"{:.2}\" y=\"{:.2}\" fill=\"{CONNECTION}\" stroke=\"#000\" stroke-width=\"{:.2}\" paint-order=\"stroke\" font-style=\"normal\" text-anchor=\"middle\">(s, t) = ({s_}, {t})</text>",
                (a[0] + b[0]) / 2.0,
                (a[1] + b[1]) / 2.0 - 3.0 * unit,
                0.8 * unit
            );
        }
    }
    for (p, path) in record.paths.iter().enumerate() {
        let colour = match path.role {
            PathRole::Camera => CAMERA,
            PathRole::Light => LIGHT,
            PathRole::Branch => BRANCH,
        };
        let mut previous = path.parent.and_then(at);
        for (i, v) in path.vertices.iter().enumerate() {
            let here = at(VertexRef { path: p, vertex: i });
            if let (Some(a), Some(b)) = (previous, here) {
                // The camera ray leaves the lens and lands on the pixel.
                let (target, b) = if i == 1 && path.role == PathRole::Camera {
                    (&mut to_lens, pixel)
                } else {
                    (&mut inside, b)
                };
                line(target, a, b, colour, 1.1, false);
            }
            if v.kind == VertexKind::Camera {
                previous = here;
                continue;
            }
            let Some(q) = here else {
                previous = None;
                continue;
            };
            let lit = v.kind == VertexKind::Light && v.contribution.iter().any(|&c| c > 0.0);
            let _ = writeln!(
                inside,
                "<circle cx=\"{:.2}\" cy=\"{:.2}\" r=\"{:.2}\" fill=\"{colour}\" stroke=\"{}\" stroke-width=\"{:.2}\"/>",
                q[0],
                q[1],
                if lit { 3.0 } else { 1.8 } * unit,
                if lit { "#fff" } else { "#000" },
                0.6 * unit
            );
            previous = here;
        }
    }
    let _ = writeln!(
        s,
        "<g clip-path=\"url(#picture)\">\n{inside}</g>\n{to_lens}"
    );
    // The lens, below the picture.
    let r = 4.0 * unit;
    let _ = writeln!(
        s,
        "<path d=\"M {:.2} {:.2} L {:.2} {:.2} L {:.2} {:.2} Z\" fill=\"{CAMERA}\"/>",
        lens[0],
        lens[1] - r,
        lens[0] - r,
        lens[1] + r,
        lens[0] + r,
        lens[1] + r
    );
    if labels == Labels::Subpaths {
        for path in &record.paths {
            let letter = match path.role {
                PathRole::Camera => "x",
                PathRole::Light => "y",
                PathRole::Branch => continue,
            };
            for (i, v) in path.vertices.iter().enumerate() {
                let q = if v.kind == VertexKind::Camera {
                    Some([lens[0] + 1.6 * r, lens[1] + r])
                } else {
                    v.raster
                        .filter(|q| q[0] >= 0.0 && q[1] >= 0.0 && q[0] < w && q[1] < h)
                };
                let Some(q) = q else { continue };
                let _ = writeln!(
                    s,
                    "<text x=\"{:.2}\" y=\"{:.2}\" fill=\"#fff\" stroke=\"#000\" stroke-width=\"{:.2}\" paint-order=\"stroke\">{letter}{}</text>",
                    q[0] + 2.5 * unit,
                    q[1] - 2.5 * unit,
                    0.8 * unit,
                    subscript(i)
                );
            }
        }
    }
    s.push_str("</svg>\n");
    s
}

/// Whether the recorded vertex `r` is seen inside the `width`×`height`
/// picture (the lens counts as seen: it is drawn below it).
pub fn in_picture(record: &PathRecord, r: VertexRef, (width, height): (u32, u32)) -> bool {
    let v = record.vertex(r);
    v.kind == VertexKind::Camera
        || v.raster
            .is_some_and(|[x, y]| x >= 0.0 && y >= 0.0 && x < width as f32 && y < height as f32)
}

/// `n` in Unicode subscript digits.
pub fn subscript(n: usize) -> String {
    n.to_string()
        .chars()
        .map(|c| char::from_u32(0x2080 + c.to_digit(10).unwrap_or(0)).unwrap_or(c))
        .collect()
}

/// The sample a figure shows: of pixel `pixel`'s samples `0..64` (seed
/// `seed`), the first with the highest `score` — a deterministic choice of
/// an instructive sample (one that bounces a few times, one whose shadow
/// rays reach the lamp). The record is projected into the picture.
pub fn pick_sample(
    integrator: &dyn Integrator,
    scene: &Scene,
    pixel: UVec2,
    seed: u64,
    score: impl Fn(&PathRecord) -> u32,
) -> PathRecord {
    let mut best: Option<(u32, PathRecord)> = None;
    for k in 0..64 {
        let (mut record, _) = record_sample(integrator, scene, pixel, seed, k);
        record.project(&scene.camera);
        let sc = score(&record);
        if best.as_ref().is_none_or(|(b, _)| sc > *b) {
            best = Some((sc, record));
        }
    }
    best.expect("64 samples were recorded").1
}
