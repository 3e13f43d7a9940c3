//! The change of variables of light sampling, dω = cos θ_y dA / r²: a small
//! patch dA at y, turned by θ_y away from the direction to x, seen from x at
//! distance r. Facing x it would show all of dA; turned, it shows dA cos θ_y
//! (its shadow on the plane perpendicular to the ray, dashed), and at
//! distance r that covers dA cos θ_y / r² of the unit sphere around x: the
//! arc dω.
//!
//! Drawn from the geometry itself, in the plane that holds x, y and the
//! patch's normal: the cone's edges run from x to the patch's ends, the arc
//! is where they cross the circle of radius 1 (drawn at [`UNIT`] pixels),
//! and the angle θ_y is the real one between n_y and y → x. Only symbols, so
//! one figure serves every language.

use std::fmt::Write as _;

use raytracer::math::Vec2;

/// The figure's geometry, in picture units (y up; the SVG flips it).
#[derive(Clone, Copy, Debug)]
pub struct SolidAngle {
    /// The distance r from x to y.
    pub r: f32,
    /// Half the length of the patch dA.
    pub half: f32,
    /// The angle θ_y between the patch's normal and the direction to x, degrees.
    pub theta_y_deg: f32,
    /// The direction from x to y, degrees above the horizontal.
    pub elevation_deg: f32,
}

impl Default for SolidAngle {
    fn default() -> Self {
        SolidAngle {
            r: 310.0,
            half: 60.0,
            theta_y_deg: 50.0,
            elevation_deg: 20.0,
        }
    }
}

/// The radius of the unit circle around x, in pixels.
const UNIT: f32 = 80.0;
/// Where x sits, and the picture's size.
pub const X: Vec2 = Vec2::new(90.0, 90.0);
const SIZE: (f32, f32) = (480.0, 300.0);

/// A point of the picture (y up) as SVG coordinates.
fn p(v: Vec2) -> String {
    format!("{:.1} {:.1}", v.x, SIZE.1 - v.y)
}

fn line(s: &mut String, a: Vec2, b: Vec2, style: &str) {
    let _ = writeln!(s, "<path d=\"M {} L {}\" {style}/>", p(a), p(b));
}

fn text(s: &mut String, at: Vec2, what: &str) {
    let _ = writeln!(
        s,
        "<text x=\"{:.1}\" y=\"{:.1}\">{what}</text>",
        at.x,
        SIZE.1 - at.y
    );
}

/// `base` with a subscript.
fn sub(base: &str, sub: &str) -> String {
    format!("{base}<tspan font-size=\"15\" dy=\"5\">{sub}</tspan><tspan dy=\"-5\"> </tspan>")
}

/// The figure as an SVG document.
pub fn solid_angle_svg(g: &SolidAngle) -> String {
    let u = Vec2::from_angle(g.elevation_deg.to_radians());
    let y = X + g.r * u;
    // The patch's normal: −u turned by θ_y, clockwise (up and to the left
    // of the ray); its tangent is perpendicular.
    let n_y = Vec2::from_angle(-g.theta_y_deg.to_radians()).rotate(-u);
    let t = n_y.perp();
    let ends = [y - g.half * t, y + g.half * t];
    // Its shadow on the plane perpendicular to the ray: dA cos θ_y.
    let across = u.perp();
    let shadow = g.half * t.dot(across).abs();
    let shown = [y - shadow * across, y + shadow * across];
    let mut s = String::new();
    let _ = writeln!(
        s,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\" \
         role=\"img\" aria-label=\"d omega equals cos theta y dA over r squared\">\
         <rect width=\"100%\" height=\"100%\" fill=\"white\"/>",
        w = SIZE.0,
        h = SIZE.1
    );
    let (ink, grey, blue) = ("#16181d", "#8a8f99", "#1d5fb0");
    // The unit circle around x, faint, and the arc dω on it.
    let _ = writeln!(
        s,
        "<circle cx=\"{:.1}\" cy=\"{:.1}\" r=\"{UNIT}\" fill=\"none\" stroke=\"#d4d7e0\" stroke-dasharray=\"3 4\"/>",
        X.x,
        SIZE.1 - X.y
    );
    let on_circle = ends.map(|e| X + UNIT * (e - X).normalize());
    let _ = writeln!(
        s,
        "<path d=\"M {} A {UNIT} {UNIT} 0 0 0 {}\" fill=\"none\" stroke=\"{blue}\" stroke-width=\"5\"/>",
        p(on_circle[0]),
        p(on_circle[1])
    );
    // The cone from x to the patch's ends, and the ray from x to y.
    let thin = format!("stroke=\"{grey}\" stroke-width=\"1.2\"");
    for e in ends {
        line(&mut s, X, e, &thin);
    }
    line(
        &mut s,
        X,
        y,
        &format!("stroke=\"{ink}\" stroke-width=\"1.5\""),
    );
    // The patch, its shadow across the ray and its normal.
    line(
        &mut s,
        shown[0],
        shown[1],
        &format!("stroke=\"{blue}\" stroke-width=\"2\" stroke-dasharray=\"5 4\""),
    );
    line(
        &mut s,
        ends[0],
        ends[1],
        &format!("stroke=\"{ink}\" stroke-width=\"5\""),
    );
    let tip = y + 70.0 * n_y;
    line(
        &mut s,
        y,
        tip,
        &format!("stroke=\"{ink}\" stroke-width=\"1.8\""),
    );
    let head = [tip - 10.0 * n_y + 5.0 * t, tip - 10.0 * n_y - 5.0 * t];
    let _ = writeln!(
        s,
        "<path d=\"M {} L {} L {} Z\" fill=\"{ink}\"/>",
        p(tip),
        p(head[0]),
        p(head[1])
    );
    // θ_y: the arc at y from the direction to x to n_y.
    let a = 34.0;
    let (from, to) = (y - a * u, y + a * n_y);
    let sweep = u8::from((-u).perp_dot(n_y) > 0.0);
    let _ = writeln!(
        s,
        "<path d=\"M {} A {a} {a} 0 0 {sweep} {}\" fill=\"none\" stroke=\"{ink}\" stroke-width=\"1.2\"/>",
        p(from),
        p(to)
    );
    for (v, r) in [(X, 4.0), (y, 4.0)] {
        let _ = writeln!(
            s,
            "<circle cx=\"{:.1}\" cy=\"{:.1}\" r=\"{r}\" fill=\"{ink}\"/>",
            v.x,
            SIZE.1 - v.y
        );
    }
    // The symbols.
    let _ = writeln!(
        s,
        "<g font-family=\"STIX Two Text,Cambria,Times New Roman,serif\" font-style=\"italic\" \
         font-size=\"22\" fill=\"{ink}\">"
    );
    let bold = |v: &str| format!("<tspan font-weight=\"bold\" font-style=\"normal\">{v}</tspan>");
    text(&mut s, X + Vec2::new(-20.0, -26.0), &bold("x"));
    text(&mut s, y + Vec2::new(8.0, -26.0), &bold("y"));
    text(&mut s, tip + Vec2::new(-34.0, 6.0), &sub(&bold("n"), "y"));
    let mid = X + 0.55 * g.r * u;
    text(&mut s, mid + Vec2::new(4.0, -30.0), "r");
    let bisect = (from - y + to - y).normalize();
    text(
        &mut s,
        y + 56.0 * bisect + Vec2::new(-12.0, -8.0),
        &sub("θ", "y"),
    );
    let top = if ends[0].y > ends[1].y {
        ends[0]
    } else {
        ends[1]
    };
    text(&mut s, top + Vec2::new(10.0, -4.0), "dA");
    let arc_mid = X + (UNIT + 6.0) * (y - X).normalize();
    let _ = writeln!(
        s,
        "<text x=\"{:.1}\" y=\"{:.1}\" fill=\"{blue}\">dω</text>",
        arc_mid.x - 10.0,
        SIZE.1 - arc_mid.y - 24.0
    );
    let low = if shown[0].y < shown[1].y {
        shown[0]
    } else {
        shown[1]
    };
    let _ = writeln!(
        s,
        "<text x=\"{:.1}\" y=\"{:.1}\" fill=\"{blue}\" text-anchor=\"middle\">dA cos θ<tspan font-size=\"15\" dy=\"5\">y</tspan></text>",
        low.x,
        SIZE.1 - low.y + 40.0
    );
    s.push_str("</g>\n</svg>\n");
    s
}
