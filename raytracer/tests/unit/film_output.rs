//! Unit tests of `film/output.rs`.

use raytracer::film::Image;
use raytracer::film::output::*;
use raytracer::math::Color;
use std::io::{self, Write};
use std::path::{Path, PathBuf};

/// A fresh directory for one test (removed at the end of the test).
fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("raytracer-film-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn srgb_curve() {
    assert_eq!(srgb8(0.0), 0);
    assert_eq!(srgb8(1.0), 255);
    assert_eq!(srgb8(5.0), 255);
    assert_eq!(srgb8(-1.0), 0);
    assert_eq!(srgb8(f32::NAN), 0);
    // 1.055 · 0.5^(1/2.4) − 0.055 = 0.73536 → 187.5 → 188.
    assert_eq!(srgb8(0.5), 188);
    // The linear toe: 12.92 · 0.002 · 255 = 6.59 → 7.
    assert_eq!(srgb8(0.002), 7);
    // The two pieces meet (continuity at the threshold).
    let t = 0.003_130_8f32;
    assert!((linear_to_srgb(t) - (1.055 * t.powf(1.0 / 2.4) - 0.055)).abs() < 1e-6);
}

#[test]
fn png_and_exr_round_trip() {
    let dir = temp_dir("roundtrip");
    let img = Image::from_fn(5, 3, |x, y| {
        Color::new(0.5, x as f32 * 1.37 + 1e-7, -(y as f32) * 1e5 + 0.1)
    });
    let exr = dir.join("a.exr");
    img.write_exr(&exr).unwrap();
    let back = Image::read_exr(&exr).unwrap();
    assert_eq!(back.width, 5);
    assert_eq!(back.height, 3);
    for (a, b) in img.pixels.iter().zip(&back.pixels) {
        for c in 0..3 {
            assert_eq!(a[c].to_bits(), b[c].to_bits());
        }
    }

    let png = dir.join("a.png");
    img.write_png(&png, 0.0).unwrap();
    // The file's pixels as (width, height, RGB bytes).
    let decode = |path: &Path| {
        let file = std::fs::File::open(path).unwrap();
        let mut reader = png::Decoder::new(std::io::BufReader::new(file))
            .read_info()
            .unwrap();
        assert_eq!(
            reader.info().srgb,
            Some(png::SrgbRenderingIntent::Perceptual)
        );
        let mut buf = vec![0; reader.output_buffer_size().unwrap()];
        let frame = reader.next_frame(&mut buf).unwrap();
        assert_eq!(frame.color_type, png::ColorType::Rgb);
        (frame.width, frame.height, buf)
    };
    let (w, h, rgb) = decode(&png);
    assert_eq!((w, h), (5, 3));
    let pixel = |x: usize, y: usize| &rgb[3 * (y * 5 + x)..3 * (y * 5 + x) + 3];
    // 0.1 linear: 1.055 · 0.1^(1/2.4) − 0.055 = 0.3492 → 89.04 → 89.
    assert_eq!(pixel(0, 0), [188, 0, 89]);
    assert_eq!(pixel(4, 2), [188, 255, 0]);
    // One stop brighter: 0.5 → 1.0.
    img.write_png(&png, 1.0).unwrap();
    assert_eq!(decode(&png).2[0], 255);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The names in `dir`, sorted (to see that no temporary file is left).
fn names(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

/// Five writes of the same 300×200 image (20 blocks of 64×64 pixels,
/// which the `exr` crate's parallel writer would put in the order they
/// finish) give the same bytes.
#[test]
fn the_same_pixels_give_the_same_bytes() {
    let dir = temp_dir("deterministic");
    let img = Image::from_fn(300, 200, |x, y| {
        Color::new(
            (x * y) as f32 * 0.37,
            (x ^ y) as f32,
            (x + 7 * y) as f32 % 3.0,
        )
    });
    let bytes = |ext: &str, i: usize| {
        let path = dir.join(format!("{i}.{ext}"));
        match ext {
            "exr" => img.write_exr(&path).unwrap(),
            _ => img.write_png(&path, 0.0).unwrap(),
        }
        std::fs::read(&path).unwrap()
    };
    for ext in ["exr", "png"] {
        let first = bytes(ext, 0);
        for i in 1..5 {
            assert!(bytes(ext, i) == first, "{ext} write {i} differs");
        }
    }
    // The bytes a server sends are the file's bytes.
    assert!(img.exr_bytes().unwrap() == bytes("exr", 5));
    assert!(img.png_bytes(0.0).unwrap() == bytes("png", 5));
    assert!(img.png_bytes(1.0).unwrap() != bytes("png", 5));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A staged file replaces its destination only on commit; an error while
/// writing, or a drop without commit, leaves the old file and no
/// temporary one.
#[test]
fn files_are_replaced_whole_or_not_at_all() {
    let dir = temp_dir("staged");
    let target = dir.join("a.txt");
    write_file(&target, "old").unwrap();
    let staged = StagedFile::write(&target, "text", |w| w.write_all(b"new")).unwrap();
    assert_eq!(std::fs::read_to_string(&target).unwrap(), "old");
    assert_eq!(names(&dir).len(), 2, "{:?}", names(&dir));
    assert_eq!(staged.target(), target);
    drop(staged);
    assert_eq!(names(&dir), ["a.txt"]);

    let e = StagedFile::write(&target, "text", |w| {
        w.write_all(b"half")?;
        Err(io::Error::other("disk full"))
    })
    .unwrap_err();
    assert!(
        e.to_string().contains("a.txt") && e.to_string().contains("disk full"),
        "{e}"
    );
    assert_eq!(std::fs::read_to_string(&target).unwrap(), "old");
    assert_eq!(names(&dir), ["a.txt"]);

    let b = dir.join("b.txt");
    let staged = [
        StagedFile::write(&target, "text", |w| w.write_all(b"new a")).unwrap(),
        StagedFile::write(&b, "text", |w| w.write_all(b"new b")).unwrap(),
    ];
    commit_all(staged).unwrap();
    assert_eq!(std::fs::read_to_string(&target).unwrap(), "new a");
    assert_eq!(std::fs::read_to_string(&b).unwrap(), "new b");
    assert_eq!(names(&dir), ["a.txt", "b.txt"]);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn errors_name_the_file() {
    let img = Image::new(2, 2);
    let missing = std::env::temp_dir().join("raytracer-no-such-dir-7d1f/x.png");
    let e = img.write_png(&missing, 0.0).unwrap_err();
    assert_eq!(e.kind(), io::ErrorKind::NotFound);
    assert!(e.to_string().contains("raytracer-no-such-dir-7d1f"), "{e}");
    assert!(e.to_string().contains("does not exist"), "{e}");
    let e = img.write_exr(missing.with_extension("exr")).unwrap_err();
    assert!(e.to_string().contains("x.exr"), "{e}");
    let e = Image::read_exr(missing.with_extension("exr")).unwrap_err();
    assert!(e.to_string().contains("cannot read EXR"), "{e}");
}
