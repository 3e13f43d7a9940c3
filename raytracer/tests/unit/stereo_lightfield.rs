//! Unit tests of `stereo/lightfield.rs`.

use raytracer::integrator::Direct;
use raytracer::math::{Color, Vec2};
use raytracer::render::RenderOptions;
use raytracer::scene::Scene;
use raytracer::scene::{SceneOrigin, load_str};
use raytracer::stereo::lightfield::*;

/// A checker wall 3 m in front of the camera, lit by a white sky.
const WALL: &str = r#"
[camera]
position = [0, 0, 0]
look_at = [0, 0, -1]
up = [0, 1, 0]
fov = 45

[render]
width = 32
height = 24
spp = 8

[materials.check]
type = "lambert"
albedo = { checker = { a = 0.9, b = 0.05, scale = 12 } }

[[shapes]]
name = "wall"
type = "quad"
origin = [-3, -3, -3]
edge1 = [6, 0, 0]
edge2 = [0, 6, 0]
material = "check"

[environment]
radiance = 1
"#;

fn wall_field(n: u32, aperture: f32) -> LightField {
    let origin = SceneOrigin::Dir {
        name: "wall.toml".into(),
        dir: ".".into(),
    };
    let scene = Scene::build("wall", load_str(WALL, &origin).unwrap());
    let options = RenderOptions {
        spp: 8,
        seed: 3,
        progress: false,
        ..RenderOptions::default()
    };
    LightField::render(&scene, &Direct, &options, n, aperture)
}

#[test]
fn views_are_spread_over_the_aperture() {
    assert_eq!(LightField::offset(3, 0.6, 0, 0), Vec2::new(-0.3, 0.3));
    assert_eq!(LightField::offset(3, 0.6, 2, 2), Vec2::new(0.3, -0.3));
    assert_eq!(LightField::offset(1, 0.6, 0, 0), Vec2::ZERO);
}

/// Refocused at the wall's depth (3 m) the checker is much sharper than
/// refocused at 1.5 m, where the views' disparities (about 3 px between
/// neighbours) blur it; and the in-focus refocus is as sharp as a single
/// view, up to the noise averaging. Deterministic (fixed seed); the
/// margins are wide (measured: 0.061 at the wall, 0.0049 at 1.5 m,
/// 0.0033 at 12 m, 0.117 for one noisier view).
#[test]
fn refocusing_at_a_planes_depth_makes_it_sharpest() {
    let lf = wall_field(3, 0.6);
    let at_wall = sharpness(&lf.refocus(3.0));
    let too_near = sharpness(&lf.refocus(1.5));
    let too_far = sharpness(&lf.refocus(12.0));
    assert!(at_wall > 1.5 * too_near, "{at_wall} vs {too_near}");
    assert!(at_wall > 1.2 * too_far, "{at_wall} vs {too_far}");
    let single = sharpness(lf.view(1, 1));
    assert!(at_wall > 0.5 * single, "{at_wall} vs one view {single}");
}

/// A pair taken out of the grid and converged at the wall's depth lines
/// the wall up: its two images agree much better than the raw pair.
#[test]
fn a_converged_pair_from_the_grid_lines_up_at_its_depth() {
    let lf = wall_field(3, 0.6);
    let [l, r] = lf.stereo_pair(1, 0, 2, None);
    let raw = mean_abs_difference(&l, &r);
    let [l, r] = lf.stereo_pair(1, 0, 2, Some(3.0));
    let converged = mean_abs_difference(&l, &r);
    assert!(converged < 0.5 * raw, "{converged} vs {raw}");
    let sheet = lf.contact_sheet(2);
    assert_eq!((sheet.width, sheet.height), (3 * 32 + 4, 3 * 24 + 4));
    assert_eq!(sheet.get(34, 0), lf.view(1, 0).get(0, 0));
    assert_eq!(sheet.get(32, 0), Color::ZERO);
}
