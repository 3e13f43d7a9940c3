//! Unit tests of `pictures.rs`.

use grading::pictures::*;
use raytracer::film::Image;
use raytracer::math::Color;

#[test]
fn small_images_are_enlarged_by_whole_blocks() {
    assert_eq!(scale_for(32), 8);
    assert_eq!(scale_for(4), 64);
    assert_eq!(scale_for(300), 1);
    let img = Image::from_fn(2, 2, |x, y| Color::splat((x + 2 * y) as f32));
    let big = enlarge(&img, 3);
    assert_eq!((big.width, big.height), (6, 6));
    assert_eq!(big.get(2, 2), img.get(0, 0));
    assert_eq!(big.get(3, 5), img.get(1, 1));
    let dir = std::env::temp_dir().join(format!("grading-pictures-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("small.png");
    write_enlarged(&img, &path).unwrap();
    assert_eq!(png_size(&path).unwrap(), (256, 256));
    let flat = |_: f64| 1.0;
    let hist = Histogram {
        lo: 0.0,
        hi: 1.0,
        counts: vec![5, 5, 10],
        expected_density: &flat,
    };
    assert!((hist.observed_density(2) - 1.5).abs() < 1e-12);
    let path = dir.join("hist.png");
    write_histograms(&[hist], &path).unwrap();
    assert_eq!(png_size(&path).unwrap(), (512, 192));
    let _ = std::fs::remove_dir_all(&dir);
}
