//! The hemisphere at a point x: the figure every formula of the BRDF and
//! the rendering equation refers to. The normal n, the direction ω_i towards
//! the light and ω_o towards the viewer (both unit vectors leaving x, the
//! convention of the code), the angle θ_i between ω_i and n, a small cone of
//! directions dω_i around ω_i, and dashed the way the light travels, −ω_i
//! (the lecture's ω_i).
//!
//! Everything is computed from the directions themselves, in 3D, and then
//! seen from the side (the plane of incidence is the picture): the arc of θ_i
//! spans the real angle `acos(ω_i·n)`, the cone's edges are ω_i turned by
//! ±δ about `n × ω_i`, and every arrow is its unit vector times the same
//! length. The words (light, viewer) come in each language of the slides;
//! the symbols are the same in all of them.

use std::fmt::Write as _;

use raytracer::math::{Mat3, Vec3};

use super::series::escape;

/// The directions the figure shows, in the plane of incidence.
#[derive(Clone, Copy, Debug)]
pub struct Hemisphere {
    /// Angle of ω_i from the normal, in degrees (towards the left of the picture).
    pub theta_i_deg: f32,
    /// Angle of ω_o from the normal, in degrees (towards the right).
    pub theta_o_deg: f32,
    /// Half the opening angle of the cone dω_i around ω_i, in degrees.
    pub cone_deg: f32,
}

impl Default for Hemisphere {
    /// The lecture's picture: light from the upper left, the viewer to the
    /// upper right, a narrow cone around ω_i.
    fn default() -> Self {
        Hemisphere {
            theta_i_deg: 40.0,
            theta_o_deg: 55.0,
            cone_deg: 6.0,
        }
    }
}

/// The words of the figure in one language.
pub struct HemisphereWords {
    pub light: &'static str,
    pub viewer: &'static str,
    /// What the figure shows, for a screen reader.
    pub description: &'static str,
}

impl HemisphereWords {
    /// The words in `lang` (`en` or `bg`), as the slides of that language say them.
    pub fn for_lang(lang: &str) -> Option<Self> {
        match lang {
            "en" => Some(HemisphereWords {
                light: "light",
                viewer: "viewer",
                description: "The hemisphere above a point x: the normal n, the directions \
                              omega i and omega o, the angle theta i and the solid angle d omega i",
            }),
            "bg" => Some(HemisphereWords {
                light: "светлина",
                viewer: "наблюдател",
                description: "Полусферата над точка x: нормалата n, посоките омега i и омега o, \
                              ъгълът тета i и пространственият ъгъл d омега i",
            }),
            _ => None,
        }
    }
}

/// The languages the figure is drawn in.
pub const LANGS: [&str; 2] = ["bg", "en"];

// The picture: 400×240, x in the middle of the surface line.
const W: f32 = 400.0;
const H: f32 = 240.0;
pub const X: [f32; 2] = [200.0, 200.0];
/// Radius of the hemisphere Ω (the unit sphere, as drawn).
const RADIUS: f32 = 150.0;
/// Length of every unit vector as drawn.
const ARROW: f32 = 128.0;
/// Radius of the arc of θ_i.
const ARC: f32 = 46.0;
/// Where the light and the viewer sit, along ω_i and ω_o.
const LIGHT_AT: f32 = 180.0;
const VIEWER_AT: f32 = 178.0;
/// The dashed −ω_i: beside ω_i by this much, from this far along it to this near x.
const BESIDE: f32 = 17.0;
const DASH_FROM: f32 = 118.0;
const DASH_TO: f32 = 30.0;

const INK: &str = "#16181d";
const LIGHT: &str = "#c25b00";
const VIEWER: &str = "#1d5fb0";
const GREY: &str = "#9aa0b4";

/// The figure's directions as unit vectors: the surface is the plane z = 0,
/// n = +z, and the plane of incidence is x–z.
struct Directions {
    n: Vec3,
    wi: Vec3,
    wo: Vec3,
    /// The edges of the cone dω_i: ω_i turned by ±δ in the plane of incidence.
    cone: [Vec3; 2],
    /// In the plane of incidence, perpendicular to ω_i, away from n.
    beside: Vec3,
}

impl Directions {
    fn new(h: &Hemisphere) -> Self {
        let (ti, to) = (h.theta_i_deg.to_radians(), h.theta_o_deg.to_radians());
        let n = Vec3::Z;
        let wi = Vec3::new(-ti.sin(), 0.0, ti.cos());
        let wo = Vec3::new(to.sin(), 0.0, to.cos());
        // The axis of the plane of incidence; along −y for any θ_i > 0.
        let axis = n.cross(wi).try_normalize().unwrap_or(Vec3::NEG_Y);
        let turn = |a: f32| Mat3::from_axis_angle(axis, a) * wi;
        let d = h.cone_deg.to_radians();
        Directions {
            n,
            wi,
            wo,
            cone: [turn(-d), turn(d)],
            beside: axis.cross(wi),
        }
    }
}

/// A point of the picture: `v` (in picture units, z up) from x.
fn at(v: Vec3) -> [f32; 2] {
    [X[0] + v.x, X[1] - v.z]
}

/// The sweep flag of the short arc around x from `a` to `b`: 1 when it
/// turns clockwise on the screen (y down).
fn sweep(a: [f32; 2], b: [f32; 2]) -> u8 {
    let (ax, ay, bx, by) = (a[0] - X[0], a[1] - X[1], b[0] - X[0], b[1] - X[1]);
    u8::from(ax * by - ay * bx > 0.0)
}

fn arrow(s: &mut String, id: &str, from: [f32; 2], to: [f32; 2], colour: &str, extra: &str) {
    let _ = writeln!(
        s,
        "<line id=\"{id}\" x1=\"{:.2}\" y1=\"{:.2}\" x2=\"{:.2}\" y2=\"{:.2}\" stroke=\"{colour}\" {extra} marker-end=\"url(#ah-{id})\"/>",
        from[0], from[1], to[0], to[1]
    );
}

/// A symbol with a subscript, e.g. ω with i.
fn symbol(base: &str, sub: &str) -> String {
    format!("{base}<tspan font-size=\"13\" dy=\"4\">{sub}</tspan>")
}

/// The figure as an SVG document, with the words of one language.
pub fn hemisphere_svg(h: &Hemisphere, words: &HemisphereWords) -> String {
    let d = Directions::new(h);
    let x = at(Vec3::ZERO);
    let mut s = String::new();
    let _ = writeln!(
        s,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{W}\" height=\"{H}\" viewBox=\"0 0 {W} {H}\" role=\"img\" aria-label=\"{}\">",
        escape(words.description).replace('"', "&quot;")
    );
    let _ = writeln!(
        s,
        "<title>{}</title><rect width=\"100%\" height=\"100%\" fill=\"white\"/>",
        escape(words.description)
    );
    // One arrowhead per arrow, in its colour (a marker cannot take the line's).
    s.push_str("<defs>");
    for (id, colour) in [
        ("n", INK),
        ("omega-i", LIGHT),
        ("omega-o", VIEWER),
        ("minus-omega-i", LIGHT),
    ] {
        let _ = write!(
            s,
            "<marker id=\"ah-{id}\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"6\" markerHeight=\"6\" orient=\"auto\"><path d=\"M0,0L10,5L0,10z\" fill=\"{colour}\"/></marker>"
        );
    }
    s.push_str("</defs>\n");

    // The hemisphere Ω: the unit sphere's upper half, seen from the side.
    let (left, right) = (at(Vec3::NEG_X * RADIUS), at(Vec3::X * RADIUS));
    let _ = writeln!(
        s,
        "<path id=\"omega\" d=\"M {:.2},{:.2} A {RADIUS},{RADIUS} 0 0 1 {:.2},{:.2}\" fill=\"none\" stroke=\"{GREY}\" stroke-dasharray=\"4 4\"/>",
        left[0], left[1], right[0], right[1]
    );
    // The cone dω_i: the directions within δ of ω_i, up to the hemisphere.
    let (c0, c1) = (at(d.cone[0] * RADIUS), at(d.cone[1] * RADIUS));
    let _ = writeln!(
        s,
        "<path id=\"d-omega-i\" d=\"M {:.2},{:.2} L {:.2},{:.2} A {RADIUS},{RADIUS} 0 0 {} {:.2},{:.2} Z\" fill=\"#ffcf4d\" fill-opacity=\"0.45\"/>",
        x[0],
        x[1],
        c0[0],
        c0[1],
        sweep(c0, c1),
        c1[0],
        c1[1]
    );
    // The surface: a line with hatching below it.
    let mut hatch = String::new();
    let mut hx = X[0] - 160.0;
    while hx <= X[0] + 165.0 {
        let _ = write!(hatch, "M{hx},{} l-9,11 ", X[1] + 1.0);
        hx += 18.0;
    }
    let _ = writeln!(
        s,
        "<path d=\"{}\" stroke=\"{GREY}\" stroke-width=\"1.2\"/>",
        hatch.trim_end()
    );
    let _ = writeln!(
        s,
        "<line id=\"surface\" x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"{INK}\" stroke-width=\"2\"/>",
        X[0] - 180.0,
        X[1],
        X[0] + 180.0,
        X[1]
    );
    // θ_i: the arc from n to ω_i, as wide as the angle between them.
    let theta_i = d.wi.dot(d.n).clamp(-1.0, 1.0).acos();
    let (a0, a1) = (at(d.n * ARC), at(d.wi * ARC));
    let _ = writeln!(
        s,
        "<path id=\"theta-i\" d=\"M {:.2},{:.2} A {ARC},{ARC} 0 {} {} {:.2},{:.2}\" fill=\"none\" stroke=\"{INK}\" stroke-width=\"1.2\"/>",
        a0[0],
        a0[1],
        u8::from(theta_i > std::f32::consts::PI),
        sweep(a0, a1),
        a1[0],
        a1[1]
    );
    // The arrows: every unit vector as long as the others.
    let (tip_n, tip_i, tip_o) = (at(d.n * ARROW), at(d.wi * ARROW), at(d.wo * ARROW));
    arrow(&mut s, "n", x, tip_n, INK, "stroke-width=\"2.4\"");
    arrow(&mut s, "omega-i", x, tip_i, LIGHT, "stroke-width=\"2.4\"");
    arrow(&mut s, "omega-o", x, tip_o, VIEWER, "stroke-width=\"2.4\"");
    // −ω_i, dashed beside ω_i: the way the light travels, into x.
    let (dash0, dash1) = (
        at(d.wi * DASH_FROM + d.beside * BESIDE),
        at(d.wi * DASH_TO + d.beside * BESIDE),
    );
    arrow(
        &mut s,
        "minus-omega-i",
        dash0,
        dash1,
        LIGHT,
        "stroke-width=\"1.6\" stroke-dasharray=\"6 4\"",
    );
    // The light (a sun) and the viewer (an eye) where the arrows point.
    let sun = at(d.wi * LIGHT_AT);
    let eye = at(d.wo * VIEWER_AT);
    let _ = writeln!(
        s,
        "<circle cx=\"{:.2}\" cy=\"{:.2}\" r=\"9\" fill=\"#ffc933\" stroke=\"{LIGHT}\" stroke-width=\"1.5\"/>\
         <ellipse cx=\"{:.2}\" cy=\"{:.2}\" rx=\"13\" ry=\"7\" fill=\"#fff\" stroke=\"{VIEWER}\" stroke-width=\"1.5\"/>\
         <circle cx=\"{:.2}\" cy=\"{:.2}\" r=\"3.5\" fill=\"{VIEWER}\"/>",
        sun[0], sun[1], eye[0], eye[1], eye[0], eye[1]
    );

    // The symbols, each beside what it names.
    let text = |s: &mut String, p: [f32; 2], attrs: &str, body: &str| {
        let _ = write!(
            s,
            "<text x=\"{:.1}\" y=\"{:.1}\"{attrs}>{body}</text>",
            p[0], p[1]
        );
    };
    s.push_str(
        "<g font-family=\"STIX Two Text,Cambria,Times New Roman,serif\" font-style=\"italic\" font-size=\"20\" fill=\"#16181d\">",
    );
    let upright = " font-weight=\"bold\" font-style=\"normal\"";
    text(&mut s, [tip_n[0] + 8.0, tip_n[1] + 14.0], upright, "n");
    text(&mut s, [x[0] - 6.0, x[1] + 28.0], upright, "x");
    let fill = |c: &str| format!(" fill=\"{c}\"");
    text(
        &mut s,
        [tip_i[0] + 10.0, tip_i[1] + 4.0],
        &fill(LIGHT),
        &symbol("ω", "i"),
    );
    text(
        &mut s,
        [tip_o[0] - 2.0, tip_o[1] - 12.0],
        &fill(VIEWER),
        &symbol("ω", "o"),
    );
    // θ_i on the bisector of its arc, just outside it.
    let half = Mat3::from_axis_angle(
        d.n.cross(d.wi).try_normalize().unwrap_or(Vec3::NEG_Y),
        0.5 * theta_i,
    ) * d.n;
    let t = at(half * (ARC + 18.0));
    text(
        &mut s,
        [t[0], t[1] + 6.0],
        " text-anchor=\"middle\"",
        &symbol("θ", "i"),
    );
    // dω_i outside the cone's outer edge, on the hemisphere.
    let outer = at(d.cone[1] * RADIUS);
    text(
        &mut s,
        [outer[0] - 12.0, outer[1] + 8.0],
        " text-anchor=\"end\"",
        &symbol("dω", "i"),
    );
    // −ω_i beside the middle of its dashed arrow.
    let mid = at(d.wi * (0.5 * (DASH_FROM + DASH_TO)) + d.beside * (BESIDE + 14.0));
    text(
        &mut s,
        [mid[0], mid[1] + 6.0],
        &format!(" text-anchor=\"end\"{}", fill(LIGHT)),
        &symbol("−ω", "i"),
    );
    s.push_str("</g>\n");
    let _ = writeln!(
        s,
        "<g font-family=\"system-ui,sans-serif\" font-size=\"14\" fill=\"#444\" text-anchor=\"middle\">\
         <text x=\"{:.1}\" y=\"{:.1}\">{}</text><text x=\"{:.1}\" y=\"{:.1}\">{}</text></g>",
        sun[0],
        sun[1] - 16.0,
        escape(words.light),
        eye[0],
        eye[1] - 14.0,
        escape(words.viewer)
    );
    s.push_str("</svg>\n");
    s
}
