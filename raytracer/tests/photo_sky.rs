//! The scene of files a student or an instructor already has
//! (`scenes/photo-sky/`): a JPEG photograph as a texture and a Radiance HDR
//! sky as the only light, loaded from disk and rendered.

use raytracer::integrator::{DirectStrategy, PathTracer};
use raytracer::render::{RenderOptions, render};
use raytracer::scene::Scene;

#[test]
fn a_jpeg_texture_under_a_radiance_hdr_sky_renders() {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/photo-sky/photo-sky.toml");
    let mut scene = Scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
    scene.set_resolution(48, 36);
    let pt = PathTracer {
        max_depth: Some(4),
        rr_depth: 3,
        strategy: DirectStrategy::Mis,
    };
    let options = RenderOptions {
        spp: 16,
        seed: 7,
        threads: None,
        tile_size: 16,
        progress: false,
        label: String::new(),
    };
    let result = render(&scene, &pt, &options);
    assert_eq!(result.film.nonfinite_count(), 0);
    let img = result.film.image();
    // The top row sees the sky above the horizon: blue (sky.hdr's upper half
    // has b = 1 > r, g), so the HDR map is what lights the scene.
    for x in 0..img.width {
        let c = img.get(x, 0);
        assert!(c.z > c.x && c.z > 0.5, "sky pixel ({x}, 0): {c}");
    }
    // The bottom row sees the brick floor: red-brown on average (bricks.jpg is
    // r > g > b), and the texture shows (bricks and mortar differ by more than
    // the noise of 16 samples does).
    let row: Vec<_> = (0..img.width).map(|x| img.get(x, img.height - 1)).collect();
    let mean = row.iter().copied().sum::<raytracer::math::Color>() / row.len() as f32;
    assert!(mean.x > mean.y && mean.y > mean.z, "floor mean {mean}");
    // The floor's BRDF is the photograph: at the centre of a mortar texel
    // (row 0) it is grey, at the centre of a brick texel (row 8) red-brown;
    // a JPEG decoded without its sRGB curve or with its rows flipped would
    // not tell them apart this way. Looked up exactly, not sampled.
    let down = raytracer::math::Ray::new(
        raytracer::math::Vec3A::new(0.0, 1.0, 1.0),
        raytracer::math::Vec3A::new(0.0, -1.0, 0.0),
    );
    let floor = scene.intersect(&down).expect("the floor is below");
    let brdf = scene.brdf(&floor);
    let up = raytracer::math::Vec3A::Z;
    let texel = |x: f32, y: f32| {
        let uv = raytracer::math::Vec2::new((x + 0.5) / 128.0, 1.0 - (y + 0.5) / 128.0);
        brdf.eval(up, up, uv) * std::f32::consts::PI
    };
    let mortar = texel(10.0, 0.0);
    let brick = texel(10.0, 8.0);
    assert!(mortar.y / mortar.x > 0.8, "mortar {mortar}");
    assert!(brick.y / brick.x < 0.3, "brick {brick}");
}
