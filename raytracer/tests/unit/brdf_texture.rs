//! Unit tests of `brdf/texture.rs`.

use raytracer::brdf::texture::*;
use raytracer::math::{Color, Vec2};

#[test]
fn checker_alternates() {
    let (a, b) = (Color::new(1.0, 0.0, 0.0), Color::new(0.0, 0.0, 1.0));
    let t = Texture::Checker { a, b, scale: 4.0 };
    // Squares of size 1/4.
    assert_eq!(t.eval(Vec2::new(0.1, 0.1)), a);
    assert_eq!(t.eval(Vec2::new(0.3, 0.1)), b);
    assert_eq!(t.eval(Vec2::new(0.3, 0.3)), a);
    assert_eq!(t.eval(Vec2::new(0.1, 0.3)), b);
    assert_eq!(t.eval(Vec2::new(0.6, 0.9)), b);
    // Negative coordinates continue the pattern (no mirrored square at 0).
    assert_eq!(t.eval(Vec2::new(-0.1, 0.1)), b);
    assert_eq!(t.eval(Vec2::new(-0.1, -0.1)), a);
    assert_eq!(Texture::Constant(a).eval(Vec2::new(7.0, -3.0)), a);
}

#[test]
fn srgb_decoding_is_exact() {
    assert!((srgb_to_linear(0.5) - 0.214_041).abs() < 1e-5);
    assert_eq!(srgb_to_linear(0.0), 0.0);
    assert!((srgb_to_linear(1.0) - 1.0).abs() < 1e-6);
    assert!((srgb_to_linear(0.04) - 0.04 / 12.92).abs() < 1e-9);
    // Continuous at the junction of the two pieces.
    assert!((srgb_to_linear(0.040_45) - srgb_to_linear(0.040_46)).abs() < 1e-5);
}

#[test]
fn image_lookup_is_bilinear_and_wraps() {
    // 2×2: top row red, green; bottom row blue, white.
    let px = vec![Color::X, Color::Y, Color::Z, Color::ONE];
    let img = ImageTexture::new(2, 2, px).unwrap();
    // Pixel centres: (u, v) = (0.25, 0.75) is the top-left pixel.
    assert!((img.eval(Vec2::new(0.25, 0.75)) - Color::X).length() < 1e-6);
    assert!((img.eval(Vec2::new(0.75, 0.25)) - Color::ONE).length() < 1e-6);
    // Halfway between the two top pixels.
    let mid = img.eval(Vec2::new(0.5, 0.75));
    assert!((mid - Color::new(0.5, 0.5, 0.0)).length() < 1e-6);
    // Wrap-around: u = 0 is halfway between the right and left columns.
    let edge = img.eval(Vec2::new(0.0, 0.75));
    assert!((edge - Color::new(0.5, 0.5, 0.0)).length() < 1e-6);
    assert!((img.eval(Vec2::new(1.25, -0.25)) - Color::X).length() < 1e-6);
    assert!(ImageTexture::new(2, 2, vec![Color::ONE; 3]).is_err());
}

#[test]
fn png_is_loaded_as_linear_and_errors_name_the_file() {
    let dir = std::env::temp_dir().join(format!("brdf-texture-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("two.png");
    let write = |color: png::ColorType, depth: png::BitDepth, data: &[u8]| {
        let file = std::fs::File::create(&path).unwrap();
        let mut encoder = png::Encoder::new(std::io::BufWriter::new(file), 2, 1);
        encoder.set_color(color);
        encoder.set_depth(depth);
        let mut writer = encoder.write_header().unwrap();
        writer.write_image_data(data).unwrap();
        writer.finish().unwrap();
    };
    let g = srgb_to_linear(128.0 / 255.0);
    assert!((g - 0.2158).abs() < 1e-4);
    let second = Color::new(1.0, 0.0, srgb_to_linear(64.0 / 255.0));
    // 2×1 sRGB: mid grey (128) and (255, 0, 64), as RGB, as RGBA, and as
    // 16-bit RGB (128·257 is 128/255 exactly); grey alone as 8-bit grey.
    for (color, depth, data) in [
        (
            png::ColorType::Rgb,
            png::BitDepth::Eight,
            vec![128, 128, 128, 255, 0, 64],
        ),
        (
            png::ColorType::Rgba,
            png::BitDepth::Eight,
            vec![128, 128, 128, 7, 255, 0, 64, 9],
        ),
        (
            png::ColorType::Rgb,
            png::BitDepth::Sixteen,
            [128u16 * 257, 128 * 257, 128 * 257, 65535, 0, 64 * 257]
                .iter()
                .flat_map(|v| v.to_be_bytes())
                .collect(),
        ),
    ] {
        write(color, depth, &data);
        let t = ImageTexture::load(&path).unwrap();
        assert_eq!((t.width, t.height), (2, 1));
        assert!(
            (t.pixels[0] - Color::splat(g)).length() < 1e-6,
            "{color:?} {depth:?}"
        );
        assert!(
            (t.pixels[1] - second).length() < 1e-6,
            "{color:?} {depth:?}"
        );
    }
    write(png::ColorType::Grayscale, png::BitDepth::Eight, &[128, 255]);
    let t = ImageTexture::load(&path).unwrap();
    assert_eq!(t.pixels, vec![Color::splat(g), Color::ONE]);
    std::fs::write(&path, b"not a png").unwrap();
    let err = ImageTexture::load(&path).unwrap_err();
    assert!(err.contains("two.png"), "{err}");
    std::fs::remove_dir_all(&dir).ok();

    let missing = std::path::Path::new("/nonexistent/dir/albedo.png");
    let err = ImageTexture::load(missing).unwrap_err();
    assert!(err.contains("/nonexistent/dir/albedo.png"), "{err}");
}

/// A PNG whose header claims a huge image (here 40 000 × 40 000, 4.8 GB
/// of samples, in a file of a few dozen bytes) is refused with a line
/// naming the file, before its pixels are allocated.
#[test]
fn a_huge_png_is_refused_before_it_is_allocated() {
    let crc = |bytes: &[u8]| {
        let mut c = !0u32;
        for &b in bytes {
            c ^= b as u32;
            for _ in 0..8 {
                c = if c & 1 != 0 {
                    (c >> 1) ^ 0xEDB8_8320
                } else {
                    c >> 1
                };
            }
        }
        !c
    };
    let chunk = |kind: &[u8], data: &[u8]| {
        let mut body = kind.to_vec();
        body.extend_from_slice(data);
        let mut out = (data.len() as u32).to_be_bytes().to_vec();
        out.extend_from_slice(&body);
        out.extend_from_slice(&crc(&body).to_be_bytes());
        out
    };
    let mut ihdr = 40_000u32.to_be_bytes().to_vec();
    ihdr.extend_from_slice(&40_000u32.to_be_bytes());
    ihdr.extend_from_slice(&[8, 2, 0, 0, 0]); // 8-bit RGB
    let mut file = b"\x89PNG\r\n\x1a\n".to_vec();
    file.extend(chunk(b"IHDR", &ihdr));
    // The start of the pixel data (a zlib stream with one empty block):
    // a decoder reads up to here before it says the image's size.
    file.extend(chunk(b"IDAT", &[0x78, 0x01, 0x01, 0x00, 0x00, 0xff, 0xff]));
    file.extend(chunk(b"IEND", &[]));
    let dir = std::env::temp_dir().join(format!("huge_png_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("huge.png");
    std::fs::write(&path, &file).unwrap();
    let err = ImageTexture::load(&path).unwrap_err();
    std::fs::remove_dir_all(&dir).ok();
    assert!(
        err.contains("huge.png") && err.contains("40000 × 40000 pixels"),
        "{err}"
    );
}

/// A JPEG photograph is read as sRGB and decoded to linear; a file of
/// another format is refused by what its bytes say, whatever its name;
/// a truncated JPEG is named in one line.
#[test]
fn jpeg_is_loaded_as_linear_and_other_formats_are_refused() {
    let dir = std::env::temp_dir().join(format!("jpeg-texture-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("grey.jpg");
    // A flat 16 × 8 image of sRGB 128: JPEG keeps a flat block exact to
    // a unit or so.
    let flat = image::RgbImage::from_pixel(16, 8, image::Rgb([128, 128, 128]));
    flat.save_with_format(&path, image::ImageFormat::Jpeg)
        .unwrap();
    let t = ImageTexture::load(&path).unwrap();
    assert_eq!((t.width, t.height), (16, 8));
    let lo = srgb_to_linear(127.0 / 255.0);
    let hi = srgb_to_linear(129.0 / 255.0);
    for p in &t.pixels {
        assert!((lo..=hi).contains(&p.x) && p.x == p.y && p.y == p.z, "{p}");
    }
    // Truncated: the header and half the data.
    let bytes = std::fs::read(&path).unwrap();
    let cut = dir.join("cut.jpg");
    std::fs::write(&cut, &bytes[..bytes.len() / 2]).unwrap();
    let err = ImageTexture::load(&cut).unwrap_err();
    assert!(err.contains("cut.jpg") && !err.contains('\n'), "{err}");
    // A Radiance HDR file named .png is not a texture.
    let hdr = dir.join("sky.png");
    let px = vec![image::Rgb([1.0f32, 0.5, 0.25]); 4];
    image::codecs::hdr::HdrEncoder::new(std::fs::File::create(&hdr).unwrap())
        .encode(&px, 2, 2)
        .unwrap();
    let err = ImageTexture::load(&hdr).unwrap_err();
    assert!(
        err.contains("sky.png") && err.contains("PNG or JPEG"),
        "{err}"
    );
    std::fs::remove_dir_all(&dir).ok();
}
