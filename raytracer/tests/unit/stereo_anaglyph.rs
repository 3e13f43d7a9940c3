//! Unit tests of `stereo/anaglyph.rs`.

use raytracer::film::Image;
use raytracer::math::{Color, Vec3A};
use raytracer::stereo::anaglyph::*;
use raytracer::stereo::rig::Eye;
use std::fmt::Write as _;

const WHITE: Color = Vec3A::ONE;
const BLACK: Color = Vec3A::ZERO;

/// Fixed colour pairs (left, right) and what each mode makes of them,
/// rounded to 3 decimals.
#[test]
fn mixing_tables() {
    let pairs = [
        ("white | black", WHITE, BLACK),
        ("black | white", BLACK, WHITE),
        ("red | red", Vec3A::X, Vec3A::X),
        ("green | blue", Vec3A::Y, Vec3A::Z),
        (
            "orange | grey",
            Vec3A::new(0.9, 0.4, 0.1),
            Vec3A::splat(0.5),
        ),
    ];
    let mut table = String::new();
    for desat in [0.0, 1.0] {
        writeln!(table, "desaturate = {desat}").unwrap();
        for mode in Anaglyph::ALL {
            write!(table, "{:>14}:", mode.name()).unwrap();
            for (_, l, r) in pairs {
                let c = mode.mix(l, r, desat);
                write!(table, "  ({:6.3} {:6.3} {:6.3})", c.x, c.y, c.z).unwrap();
            }
            table.push('\n');
        }
    }
    let header: Vec<_> = pairs.iter().map(|p| p.0).collect();
    insta::assert_snapshot!(format!("columns: {}\n{table}", header.join(", ")));
}

#[test]
fn desaturation_endpoints() {
    let c = Vec3A::new(0.9, 0.4, 0.1);
    assert_eq!(desaturate(c, 0.0), c);
    let g = desaturate(c, 1.0);
    assert!((g.x - g.y).abs() < 1e-6 && (g.y - g.z).abs() < 1e-6);
    assert!((LUMA.dot(g) - LUMA.dot(c)).abs() < 1e-6, "luminance kept");
    // Halfway is halfway.
    let h = desaturate(c, 0.5);
    assert!((h - 0.5 * (c + g)).length() < 1e-6);
    // The matrix form agrees with the function.
    for a in [0.0, 0.3, 1.0] {
        assert!((desaturation(a) * c - desaturate(c, a)).length() < 1e-6);
    }
    // Fully desaturated red–cyan colour is the grey anaglyph.
    let (l, r) = (Vec3A::new(0.9, 0.1, 0.2), Vec3A::new(0.1, 0.7, 0.3));
    let a = Anaglyph::RedCyan.mix(l, r, 1.0);
    let b = Anaglyph::Grey.mix(l, r, 0.0);
    assert!((a - b).length() < 1e-6, "{a} vs {b}");
    // And a saturated red object becomes visible to the cyan eye.
    let red = Vec3A::X;
    let seen = |a: f32| {
        Anaglyph::RedCyan
            .mix(BLACK, red, a)
            .dot(Anaglyph::RedCyan.filter(Eye::Right))
    };
    assert_eq!(seen(0.0), 0.0);
    assert!(seen(1.0) > 0.3);
}

/// Each eye's filter passes its own image only: with ideal filters, the
/// left eye sees nothing of a right-only image, for every mode except
/// Dubois (whose least-squares matrices trade a little leakage for colour).
#[test]
fn ideal_filters_separate_the_eyes() {
    for mode in Anaglyph::ALL {
        let [fl, fr] = mode.filters();
        let right_only = mode.mix(BLACK, Vec3A::new(0.3, 0.6, 0.9), 0.0);
        let left_only = mode.mix(Vec3A::new(0.3, 0.6, 0.9), BLACK, 0.0);
        if mode == Anaglyph::Dubois {
            assert!(fl.dot(right_only) < 0.01 && fr.dot(left_only) < 0.01);
        } else {
            assert_eq!(fl * right_only, BLACK, "{}", mode.name());
            assert_eq!(fr * left_only, BLACK, "{}", mode.name());
        }
    }
}

#[test]
fn compose_agrees_with_mix() {
    let l = Image::from_fn(3, 2, |x, y| Vec3A::new(x as f32 * 0.3, y as f32, 0.5));
    let r = Image::from_fn(3, 2, |x, y| Vec3A::new(0.2, x as f32 * 0.4, y as f32));
    for mode in Anaglyph::ALL {
        let img = mode.compose(&l, &r, 0.4);
        for y in 0..2 {
            for x in 0..3 {
                let m = mode.mix(l.get(x, y), r.get(x, y), 0.4);
                assert!((img.get(x, y) - m).length() < 1e-6);
            }
        }
    }
}
