//! Unit tests of `scene/load.rs`.

use raytracer::brdf::{Brdf, Glass, Lambert, Mirror, Phong, Texture};
use raytracer::light::{Light, PointLight};
use raytracer::math::{Color, Vec2, Vec3A};
use raytracer::scene::Emitter;
use raytracer::scene::RenderSettings;
use raytracer::scene::load::*;
use std::path::Path;

fn origin() -> SceneOrigin {
    SceneOrigin::Dir {
        name: "test.toml".into(),
        dir: ".".into(),
    }
}

const CAMERA: &str = "[camera]\nposition = [0, 0, 5]\nlook_at = [0, 0, 1]\nfov = 40\n";

/// Light brighter than 32-bit products can carry is refused where it is
/// given (emission, an environment's radiance, a point light's
/// intensity), naming the bound; 10¹² itself is accepted.
#[test]
fn radiance_too_bright_for_f32_is_refused() {
    let shape = "[materials.m]\ntype = \"lambert\"\nalbedo = 0.5\n\
                 [[shapes]]\nname = \"s\"\ntype = \"sphere\"\ncenter = [0, 0, 0]\nradius = 1\nmaterial = \"m\"\n";
    for (extra, ok) in [
        ("emission = 3e38\n", false),
        ("emission = [1, 1e13, 1]\n", false),
        ("emission = 1e12\n", true),
    ] {
        let text = format!("{CAMERA}{shape}{extra}");
        match load_str(&text, &origin()) {
            Ok(_) => assert!(ok, "{extra} was accepted"),
            Err(e) => {
                let e = e.to_string();
                assert!(!ok, "{extra}: {e}");
                assert!(e.contains("too bright") && e.contains("test.toml"), "{e}");
            }
        }
    }
    let sky = format!("{CAMERA}[environment]\nradiance = 1e30\n");
    assert!(
        load_str(&sky, &origin())
            .unwrap_err()
            .to_string()
            .contains("too bright")
    );
}

#[test]
fn defaults_fill_what_the_file_leaves_out() {
    let parts = load_str(CAMERA, &origin()).unwrap();
    let c = parts.camera;
    assert_eq!(c.up, Vec3A::Y);
    assert_eq!(c.aperture_radius, 0.0);
    assert_eq!(c.focus_distance, 4.0, "distance to look_at");
    assert_eq!(c.shift, Vec2::ZERO);
    assert_eq!(parts.settings, RenderSettings::default());
    assert!(parts.objects.is_empty() && parts.lights.is_empty());

    let text = format!("{CAMERA}[render]\nmax_depth = -1\n");
    assert_eq!(load_str(&text, &origin()).unwrap().settings.max_depth, None);
    let text = format!(
        "{CAMERA}aperture_radius = 0.1\nfocus_distance = 2\n\
         [render]\nwidth = 40\nheight = 30\nspp = 7\nmax_depth = 8\nrr_depth = 3\nseed = 9\n"
    );
    let parts = load_str(&text, &origin()).unwrap();
    assert_eq!(
        parts.settings,
        RenderSettings {
            width: 40,
            height: 30,
            spp: 7,
            max_depth: Some(8),
            rr_depth: 3,
            seed: 9
        }
    );
    assert_eq!(parts.camera.aperture_radius, 0.1);
    assert_eq!(parts.camera.focus_distance, 2.0);
}

#[test]
fn materials_lights_and_environment_are_built() {
    let text = format!(
        "{CAMERA}\
         [materials.floor]\ntype = \"lambert\"\nalbedo = {{ checker = {{ a = 0.8, b = [0.1, 0.2, 0.3], scale = 4 }} }}\n\
         [materials.shiny]\ntype = \"phong\"\nalbedo = [0.5, 0.4, 0.3]\nexponent = 100\n\
         [materials.mirror]\ntype = \"mirror\"\n\
         [materials.glass]\ntype = \"glass\"\ntint = 0.9\n\
         [[shapes]]\nname = \"ball\"\ntype = \"sphere\"\ncenter = [1, 2, 3]\nradius = 0.5\nmaterial = \"glass\"\n\
         [[shapes]]\ntype = \"sphere\"\ncenter = [0, 0, 0]\nradius = 9\nmaterial = \"floor\"\nemission = 0.5\ntwo_sided = true\n\
         [[lights]]\ntype = \"point\"\nposition = [0, 4, 0]\nintensity = 30\n\
         [environment]\nradiance = [0.1, 0.2, 0.3]\n"
    );
    let parts = load_str(&text, &origin()).unwrap();
    assert_eq!(parts.brdf_names, ["floor", "shiny", "mirror", "glass"]);
    match &parts.brdfs[0] {
        Brdf::Lambert(Lambert {
            albedo: Texture::Checker { a, b, scale },
        }) => {
            assert_eq!(*a, Color::splat(0.8));
            assert_eq!(*b, Color::new(0.1, 0.2, 0.3));
            assert_eq!(*scale, 4.0);
        }
        other => panic!("{other:?}"),
    }
    assert!(matches!(
        parts.brdfs[1],
        Brdf::Phong(Phong {
            exponent: 100.0,
            ..
        })
    ));
    assert!(
        matches!(parts.brdfs[2], Brdf::Mirror(Mirror { reflectance }) if reflectance == Color::ONE)
    );
    assert!(
        matches!(parts.brdfs[3], Brdf::Glass(Glass { ior: 1.5, tint }) if tint == Color::splat(0.9))
    );

    assert_eq!(parts.objects[0].name, "ball");
    assert_eq!(parts.objects[0].brdf, 3);
    assert_eq!(parts.objects[0].emitter, None);
    assert_eq!(parts.objects[1].name, "sphere#1");
    assert_eq!(
        parts.objects[1].emitter,
        Some(Emitter {
            radiance: Color::splat(0.5),
            two_sided: true
        })
    );
    assert!(matches!(
        parts.lights[0],
        Light::Point(PointLight { position, intensity })
            if position == Vec3A::new(0.0, 4.0, 0.0) && intensity == Color::splat(30.0)
    ));
    match &parts.lights[1] {
        Light::Environment(env) => {
            assert_eq!(env.radiance, Color::new(0.1, 0.2, 0.3));
            assert!(env.map.is_none());
        }
        other => panic!("{other:?}"),
    }
}

/// The example of `raytracer/scenes/README.md` is a valid scene.
#[test]
fn the_readme_example_loads() {
    let readme = include_str!("../../scenes/README.md");
    let start = readme.find("```toml\n").expect("an example") + "```toml\n".len();
    let example = &readme[start..start + readme[start..].find("```").unwrap()];
    let parts = load_str(example, &origin()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(parts.objects.len(), 3);
    assert_eq!(parts.lights.len(), 1);
    assert!(parts.objects[2].emitter.is_some());
}

#[test]
fn load_file_reads_only_regular_files_of_a_sane_size() {
    let dir = std::env::temp_dir().join(format!("scenefmt-kinds-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let e = load_file(&dir).unwrap_err();
    assert!(
        e.to_string().ends_with(": is a folder, not a scene file"),
        "{e}"
    );
    if Path::new("/dev/zero").exists() {
        let e = load_file(Path::new("/dev/zero")).unwrap_err();
        assert!(e.message.starts_with("is not a regular file"), "{e}");
    }
    let big = dir.join("big.toml");
    std::fs::File::create(&big)
        .unwrap()
        .set_len(MAX_SCENE_FILE_BYTES + 1)
        .unwrap();
    let e = load_file(&big).unwrap_err();
    assert!(e.message.contains("at most 16 MiB"), "{e}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn load_file_reads_from_disk_and_names_a_missing_file() {
    let dir = std::env::temp_dir().join(format!("scenefmt-load-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("s.toml");
    std::fs::write(&path, CAMERA).unwrap();
    assert_eq!(load_file(&path).unwrap().camera.vfov_deg, 40.0);
    let missing = dir.join("nope.toml");
    let e = load_file(&missing).unwrap_err();
    assert_eq!(e.file, missing.display().to_string());
    assert!(e.message.starts_with("cannot read"), "{e}");
    std::fs::remove_dir_all(&dir).unwrap();
}
