//! Unit tests of `plots/hemisphere.rs`.

use lesson11::plots::hemisphere::*;

/// The attribute `name` of the element with `id`.
fn attr<'a>(svg: &'a str, id: &str, name: &str) -> &'a str {
    let start = svg
        .find(&format!("id=\"{id}\""))
        .unwrap_or_else(|| panic!("no element {id}"));
    let element = &svg[svg[..start].rfind('<').unwrap()..];
    let element = &element[..element.find('>').unwrap()];
    let key = format!(" {name}=\"");
    let at = element
        .find(&key)
        .unwrap_or_else(|| panic!("{id} has no {name}"))
        + key.len();
    &element[at..at + element[at..].find('"').unwrap()]
}

fn num(svg: &str, id: &str, name: &str) -> f32 {
    attr(svg, id, name).parse().unwrap()
}

/// The numbers of a path's `d`, in order.
fn path_numbers(svg: &str, id: &str) -> Vec<f32> {
    attr(svg, id, "d")
        .split(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-'))
        .filter(|t| !t.is_empty())
        .map(|t| t.parse().unwrap())
        .collect()
}

/// A line of the drawing as a vector from its start to its end.
fn line(svg: &str, id: &str) -> ([f32; 2], [f32; 2]) {
    let p = [num(svg, id, "x1"), num(svg, id, "y1")];
    let q = [num(svg, id, "x2"), num(svg, id, "y2")];
    (p, [q[0] - p[0], q[1] - p[1]])
}

fn len(v: [f32; 2]) -> f32 {
    v[0].hypot(v[1])
}

/// The angle between two vectors of the picture, in degrees.
fn angle(a: [f32; 2], b: [f32; 2]) -> f32 {
    ((a[0] * b[0] + a[1] * b[1]) / (len(a) * len(b)))
        .clamp(-1.0, 1.0)
        .acos()
        .to_degrees()
}

fn from_x(p: [f32; 2]) -> [f32; 2] {
    [p[0] - X[0], p[1] - X[1]]
}

/// What the test reads off a drawing, checked against the angles it was drawn with.
fn check(h: Hemisphere) {
    let svg = hemisphere_svg(&h, &HemisphereWords::for_lang("en").unwrap());
    let (n0, n) = line(&svg, "n");
    let (i0, wi) = line(&svg, "omega-i");
    let (o0, wo) = line(&svg, "omega-o");
    // The arrows leave x and are unit vectors scaled alike.
    for p in [n0, i0, o0] {
        assert!(len(from_x(p)) < 0.01, "{p:?} is not x");
    }
    for v in [wi, wo] {
        assert!(
            (len(v) - len(n)).abs() < 0.02,
            "{} against {}",
            len(v),
            len(n)
        );
    }
    assert!(
        (angle(n, [0.0, -1.0]) < 0.01),
        "n is perpendicular to the surface"
    );
    assert!((angle(n, wi) - h.theta_i_deg).abs() < 0.02);
    assert!((angle(n, wo) - h.theta_o_deg).abs() < 0.02);
    assert!(
        wi[0] < 0.0 && wo[0] > 0.0,
        "ω_i and ω_o on either side of n"
    );

    // The arc of θ_i: centred on x, from n to ω_i, spanning θ_i.
    let a = path_numbers(&svg, "theta-i");
    let (start, r, end) = ([a[0], a[1]], a[2], [a[7], a[8]]);
    for p in [start, end] {
        assert!((len(from_x(p)) - r).abs() < 0.02, "{p:?} is not on the arc");
    }
    assert!(angle(from_x(start), n) < 0.05, "the arc starts on n");
    assert!(angle(from_x(end), wi) < 0.05, "the arc ends on ω_i");
    assert!((angle(from_x(start), from_x(end)) - angle(n, wi)).abs() < 0.05);
    // From n it turns towards ω_i (counter-clockwise on the screen here).
    assert_eq!(a[6], 0.0, "sweep flag");

    // The cone dω_i: from x to the hemisphere, around ω_i, ±δ wide.
    let c = path_numbers(&svg, "d-omega-i");
    let (apex, e0, e1) = ([c[0], c[1]], [c[2], c[3]], [c[9], c[10]]);
    assert!(len(from_x(apex)) < 0.01);
    let radius = path_numbers(&svg, "omega")[2];
    for e in [e0, e1] {
        assert!((len(from_x(e)) - radius).abs() < 0.02);
        assert!((angle(from_x(e), wi) - h.cone_deg).abs() < 0.05);
    }
    assert!((angle(from_x(e0), from_x(e1)) - 2.0 * h.cone_deg).abs() < 0.05);

    // −ω_i: parallel to ω_i, pointing the other way, into x.
    let (m0, m) = line(&svg, "minus-omega-i");
    assert!((angle(m, wi) - 180.0).abs() < 0.05);
    let towards_x = angle(m, [-m0[0] + X[0], -m0[1] + X[1]]);
    assert!(towards_x < 10.0, "it ends near x: {towards_x}°");
    assert!(attr(&svg, "minus-omega-i", "stroke-dasharray").contains(' '));
}

#[test]
fn the_drawing_holds_its_geometry() {
    check(Hemisphere::default());
    check(Hemisphere {
        theta_i_deg: 25.0,
        theta_o_deg: 70.0,
        cone_deg: 10.0,
    });
}

#[test]
fn the_arc_of_theta_i_follows_the_angle() {
    let svg = |t: f32| {
        hemisphere_svg(
            &Hemisphere {
                theta_i_deg: t,
                ..Hemisphere::default()
            },
            &HemisphereWords::for_lang("en").unwrap(),
        )
    };
    assert_ne!(
        attr(&svg(30.0), "theta-i", "d"),
        attr(&svg(40.0), "theta-i", "d")
    );
}

#[test]
fn each_language_has_its_words_and_the_same_drawing() {
    let h = Hemisphere::default();
    let en = hemisphere_svg(&h, &HemisphereWords::for_lang("en").unwrap());
    let bg = hemisphere_svg(&h, &HemisphereWords::for_lang("bg").unwrap());
    for (svg, words) in [
        (&en, ["light", "viewer"]),
        (&bg, ["светлина", "наблюдател"]),
    ] {
        for w in words {
            assert!(svg.contains(&format!(">{w}</text>")), "{w}");
        }
        assert!(svg.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\""));
        assert!(svg.trim_end().ends_with("</svg>"));
        for id in [
            "n",
            "omega-i",
            "omega-o",
            "minus-omega-i",
            "theta-i",
            "d-omega-i",
        ] {
            assert_eq!(svg.matches(&format!("id=\"{id}\"")).count(), 1, "{id}");
        }
    }
    let shapes = |svg: &str| {
        svg[..svg.find("<g font-family").unwrap()]
            .split_once("<rect")
            .unwrap()
            .1
            .to_string()
    };
    assert_eq!(shapes(&en), shapes(&bg), "the same geometry in both");
    for lang in LANGS {
        assert!(HemisphereWords::for_lang(lang).is_some());
    }
}
