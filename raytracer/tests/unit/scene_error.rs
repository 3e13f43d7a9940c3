//! Unit tests of `scene/error.rs`.

use raytracer::scene::error::*;

#[test]
fn line_and_column_are_one_based_and_count_characters() {
    let text = "a = 1\nbé = [1, 2]\n";
    assert_eq!(line_column(text, 0), (1, 1));
    assert_eq!(line_column(text, 6), (2, 1));
    // 'é' is two bytes but one column.
    let off = text.find('[').unwrap();
    assert_eq!(line_column(text, off), (2, 6));
    assert_eq!(line_column(text, text.len()), (3, 1));
}

#[test]
fn field_path_finds_nested_keys_and_array_items() {
    let text = "[camera]\nfov = 40\n\n[[shapes]]\ntype = \"sphere\"\n\n\
                [[shapes]]\ntype = \"sphere\"\nradius = -1\n\n\
                [materials.white]\nalbedo = [1, 2, 3]\n";
    let at = |needle: &str| {
        let start = text.find(needle).unwrap();
        field_path(text, &(start..start + needle.len()))
    };
    assert_eq!(at("fov"), "camera.fov");
    assert_eq!(at("-1"), "shapes[1].radius");
    assert_eq!(at("2, 3"), "materials.white.albedo");
    let three = text.find("3]").unwrap();
    assert_eq!(
        field_path(text, &(three..three + 1)),
        "materials.white.albedo[2]"
    );
}

fn toml_error(text: &str) -> SceneError {
    let e = toml::from_str::<toml::Table>(text).unwrap_err();
    SceneError::from_toml("s.toml", text, &e)
}

#[test]
fn duplicates_name_the_key_or_the_table() {
    let e = toml_error("[camera]\nfov = 1\nfov = 2\n");
    assert_eq!(
        e.to_string(),
        "s.toml:3:1: duplicate key `fov`: each key may appear only once in a table"
    );
    let e = toml_error("[materials.m]\na = 1\n\n[materials.m]   # again\nb = 2\n");
    assert_eq!((e.line, e.column), (Some(4), Some(12)));
    assert_eq!(
        e.message,
        "duplicate table `[materials.m]`: each table may be defined only once"
    );
}

#[test]
fn deep_nesting_is_reported_at_its_line() {
    let text = format!(
        "a = 1\nb = {}{}\n",
        "[".repeat(100_000),
        "]".repeat(100_000)
    );
    let e = toml_error(&text);
    assert_eq!(e.line, Some(2), "{e}");
    assert!(e.message.contains("nested too deeply"), "{e}");
}

#[test]
fn display_names_file_line_column_and_field() {
    let e = SceneError {
        file: "cornell.toml".into(),
        line: Some(12),
        column: Some(10),
        path: "shapes[3].radius".into(),
        message: "must be positive, got -1".into(),
    };
    assert_eq!(
        e.to_string(),
        "cornell.toml:12:10: shapes[3].radius: must be positive, got -1"
    );
    let e = SceneError::whole_file("x.toml", "file not found");
    assert_eq!(e.to_string(), "x.toml: file not found");
}

// ---- Every kind of mistake gives a located error, never a panic. ----

use raytracer::scene::load::{SceneOrigin, load_str};

/// A valid scene to which each test adds one mistake.
const HEAD: &str = "[camera]\nposition = [0, 0, 5]\nlook_at = [0, 0, 0]\nfov = 40\n\n\
                    [materials.white]\ntype = \"lambert\"\nalbedo = 0.8\n\n\
                    [materials.red]\ntype = \"lambert\"\nalbedo = [0.8, 0.1, 0.1]\n\n";

fn load_err(text: &str) -> SceneError {
    let origin = SceneOrigin::Dir {
        name: "test.toml".into(),
        dir: std::env::temp_dir().join("scenefmt-no-such-dir"),
    };
    match load_str(text, &origin) {
        Ok(_) => panic!("expected an error for:\n{text}"),
        Err(e) => e,
    }
}

/// Checks the error's place: the line and column of the first `needle`
/// after `after` in `text`, and the field path.
fn assert_at(e: &SceneError, text: &str, after: &str, needle: &str, path: &str) {
    let from = text.find(after).expect("after");
    let offset = from + text[from..].find(needle).expect("needle");
    let (line, column) = line_column(text, offset);
    assert_eq!(e.file, "test.toml");
    assert_eq!((e.line, e.column), (Some(line), Some(column)), "{e}");
    assert_eq!(e.path, path, "{e}");
}

#[test]
fn the_base_scene_is_valid() {
    let origin = SceneOrigin::Dir {
        name: "test.toml".into(),
        dir: ".".into(),
    };
    let text = format!(
        "{HEAD}[[shapes]]\ntype = \"sphere\"\ncenter = [0, 0, 0]\nradius = 1\nmaterial = \"red\"\n"
    );
    let parts = load_str(&text, &origin).expect("valid");
    assert_eq!(parts.objects.len(), 1);
    assert_eq!(parts.brdf_names, ["white", "red"], "file order");
}

#[test]
fn bad_toml_syntax() {
    let text = format!("{HEAD}[[shapes]\ntype = \"sphere\"\n");
    let e = load_err(&text);
    assert_eq!((e.line, e.column), (Some(14), Some(10)), "{e}");
    assert_eq!(
        e.to_string(),
        "test.toml:14:10: unclosed array table, expected `]`"
    );
}

#[test]
fn unknown_field() {
    let text = format!(
        "{HEAD}[[shapes]]\ntype = \"sphere\"\ncenter = [0, 0, 0]\nradiuss = 1\nmaterial = \"red\"\n"
    );
    let e = load_err(&text);
    assert_at(&e, &text, "[[shapes]]", "radiuss", "shapes[0].radiuss");
    assert!(e.message.contains("unknown field `radiuss`"), "{e}");
    assert!(
        e.message.contains("`radius`"),
        "lists the known fields: {e}"
    );
}

#[test]
fn wrong_type() {
    let text = format!(
        "{HEAD}[[shapes]]\ntype = \"sphere\"\ncenter = [0, 0, 0]\nradius = \"big\"\nmaterial = \"red\"\n"
    );
    let e = load_err(&text);
    assert_at(&e, &text, "radius", "\"big\"", "shapes[0].radius");
    assert!(e.message.contains("expected a number"), "{e}");

    let text = HEAD.replace("position = [0, 0, 5]", "position = [0, 5]");
    let e = load_err(&text);
    assert_at(&e, &text, "", "[0, 5]", "camera.position");
    assert!(e.message.contains("expected 3 numbers, got 2"), "{e}");
}

#[test]
fn unknown_material_lists_the_known_ones() {
    let text = format!(
        "{HEAD}[[shapes]]\ntype = \"sphere\"\ncenter = [0, 0, 0]\nradius = 1\nmaterial = \"whit\"\n"
    );
    let e = load_err(&text);
    assert_at(&e, &text, "[[shapes]]", "\"whit\"", "shapes[0].material");
    assert!(e.message.contains("unknown material `whit`"), "{e}");
    assert!(e.message.contains("white, red"), "{e}");

    let text = format!("{HEAD}[materials.m]\ntype = \"metal\"\n");
    let e = load_err(&text);
    assert_at(&e, &text, "[materials.m]", "\"metal\"", "materials.m.type");
    assert!(e.message.contains("lambert, phong, mirror, glass"), "{e}");
}

#[test]
fn missing_mesh_file() {
    let text =
        format!("{HEAD}[[shapes]]\ntype = \"mesh\"\nfile = \"bunny.obj\"\nmaterial = \"red\"\n");
    let e = load_err(&text);
    assert_at(&e, &text, "[[shapes]]", "\"bunny.obj\"", "shapes[0].file");
    assert!(e.message.contains("mesh file not found"), "{e}");
    assert!(e.message.contains("bunny.obj"), "{e}");
}

#[test]
fn zero_or_negative_sphere_radius() {
    for r in ["-1", "0"] {
        let text = format!(
            "{HEAD}[[shapes]]\ntype = \"sphere\"\ncenter = [0, 0, 0]\nradius = {r}\nmaterial = \"red\"\n"
        );
        let e = load_err(&text);
        assert_at(&e, &text, "radius", r, "shapes[0].radius");
        assert_eq!(e.message, format!("must be positive, got {r}"));
        assert!(
            e.to_string()
                .ends_with(&format!("shapes[0].radius: must be positive, got {r}"))
        );
    }
}

/// `1e-50` is not 0, but becomes 0 as a 32-bit float: the error says so
/// instead of "got 0".
#[test]
fn a_number_too_small_for_f32_is_not_reported_as_zero() {
    let text = format!(
        "{HEAD}[[shapes]]\ntype = \"sphere\"\ncenter = [0, 0, 0]\nradius = 1e-50\nmaterial = \"red\"\n"
    );
    let e = load_err(&text);
    assert_at(&e, &text, "radius", "1e-50", "shapes[0].radius");
    assert!(e.message.starts_with("1e-50 is too close to 0"), "{e}");
}

#[test]
fn mesh_files_that_are_folders_or_devices_say_so() {
    let dir = std::env::temp_dir().join(format!("scenefmt-mesh-kinds-{}", std::process::id()));
    std::fs::create_dir_all(dir.join("folder.obj")).unwrap();
    let origin = SceneOrigin::Dir {
        name: "test.toml".into(),
        dir: dir.clone(),
    };
    let mesh = |file: &str| {
        let text =
            format!("{HEAD}[[shapes]]\ntype = \"mesh\"\nfile = \"{file}\"\nmaterial = \"red\"\n");
        load_str(&text, &origin).unwrap_err().to_string()
    };
    let e = mesh("folder.obj");
    assert!(e.ends_with("folder.obj is a folder, not a file"), "{e}");
    if std::path::Path::new("/dev/zero").exists() {
        let e = mesh("/dev/zero");
        assert!(
            e.ends_with("/dev/zero is not a regular file (a device, a pipe or a socket)"),
            "{e}"
        );
    }
    assert!(mesh("nope.obj").contains("mesh file not found"));
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn zero_area_light() {
    let text = format!(
        "{HEAD}[[shapes]]\ntype = \"quad\"\norigin = [0, 1, 0]\nedge1 = [1, 0, 0]\nedge2 = [-2, 0, 0]\nmaterial = \"white\"\nemission = 10\n"
    );
    let e = load_err(&text);
    assert_at(&e, &text, "edge2", "[-2", "shapes[0].edge2");
    assert!(e.message.contains("no area"), "{e}");

    // A rectangle squashed flat by its scale.
    let text = format!(
        "{HEAD}[[shapes]]\ntype = \"rectangle\"\nscale = [1, 0, 1]\nmaterial = \"white\"\nemission = 10\n"
    );
    let e = load_err(&text);
    assert_at(&e, &text, "scale", "[1, 0", "shapes[0].scale");
}

#[test]
fn zero_image_size() {
    for field in ["width", "height", "spp"] {
        let text = format!("{HEAD}[render]\n{field} = 0\n");
        let e = load_err(&text);
        assert_at(&e, &text, "[render]", "0", &format!("render.{field}"));
        assert_eq!(e.message, "must be at least 1, got 0");
    }
    let text = format!("{HEAD}[render]\nwidth = -3\n");
    let e = load_err(&text);
    assert_at(&e, &text, "[render]", "-3", "render.width");
}

#[test]
fn non_finite_numbers() {
    for bad in ["nan", "inf", "-inf", "1e300"] {
        let text = HEAD.replace("fov = 40", &format!("fov = {bad}"));
        let e = load_err(&text);
        assert_at(&e, &text, "", bad, "camera.fov");
        assert!(e.message.contains("finite"), "{e}");
    }
    let text = format!(
        "{HEAD}[[shapes]]\ntype = \"sphere\"\ncenter = [0, nan, 0]\nradius = 1\nmaterial = \"red\"\n"
    );
    let e = load_err(&text);
    assert_at(&e, &text, "center", "nan", "shapes[0].center[1]");
}

#[test]
fn camera_looking_along_its_up_vector() {
    let text = HEAD.replace("fov = 40", "up = [0, 0, -2]\nfov = 40");
    let e = load_err(&text);
    assert_at(&e, &text, "", "[0, 0, -2]", "camera.up");
    assert!(e.message.contains("looks along its up vector"), "{e}");

    let text = HEAD.replace("look_at = [0, 0, 0]", "look_at = [0, 0, 5]");
    let e = load_err(&text);
    assert_at(&e, &text, "look_at", "[0, 0, 5]", "camera.look_at");
}

#[test]
fn negative_radiance() {
    let text = format!(
        "{HEAD}[[shapes]]\ntype = \"sphere\"\ncenter = [0, 0, 0]\nradius = 1\nmaterial = \"red\"\nemission = [1, -1, 1]\n"
    );
    let e = load_err(&text);
    assert_at(&e, &text, "emission", "[1, -1", "shapes[0].emission");
    assert!(e.message.contains("must not be negative"), "{e}");

    let text = format!("{HEAD}[environment]\nradiance = -0.5\n");
    let e = load_err(&text);
    assert_at(&e, &text, "[environment]", "-0.5", "environment.radiance");

    let text = format!(
        "{HEAD}[[lights]]\ntype = \"point\"\nposition = [0, 1, 0]\nintensity = [-1, 0, 0]\n"
    );
    let e = load_err(&text);
    assert_at(&e, &text, "intensity", "[-1", "lights[0].intensity");
}

#[test]
fn phong_exponent_below_zero() {
    let text = format!("{HEAD}[materials.shiny]\ntype = \"phong\"\nalbedo = 0.5\nexponent = -2\n");
    let e = load_err(&text);
    assert_at(&e, &text, "exponent", "-2", "materials.shiny.exponent");
    assert_eq!(e.message, "must be ≥ 0, got -2");
}

#[test]
fn glass_ior_not_positive() {
    for ior in ["0", "-1.5"] {
        let text = format!("{HEAD}[materials.g]\ntype = \"glass\"\nior = {ior}\n");
        let e = load_err(&text);
        assert_at(&e, &text, "ior", ior, "materials.g.ior");
        assert!(e.message.starts_with("must be positive"), "{e}");
    }
}

#[test]
fn fields_of_another_type_and_missing_fields() {
    let text = format!(
        "{HEAD}[[shapes]]\ntype = \"sphere\"\ncenter = [0, 0, 0]\nradius = 1\nedge1 = [1, 0, 0]\nmaterial = \"red\"\n"
    );
    let e = load_err(&text);
    assert_at(&e, &text, "edge1", "[1, 0, 0]", "shapes[0].edge1");
    assert_eq!(e.message, "`edge1` is not used by a sphere");

    let text =
        format!("{HEAD}[[shapes]]\ntype = \"sphere\"\ncenter = [0, 0, 0]\nmaterial = \"red\"\n");
    let e = load_err(&text);
    assert_eq!(e.path, "shapes[0]");
    assert_eq!(e.message, "a sphere needs `radius`");

    let text = format!("{HEAD}[[shapes]]\ntype = \"cube\"\nmaterial = \"red\"\nemission = 1\n");
    let e = load_err(&text);
    assert_at(&e, &text, "emission", "1", "shapes[0].emission");
}

#[test]
fn albedo_above_one_breaks_energy_conservation() {
    let text = HEAD.replace(
        "albedo = 0.8",
        "albedo = { checker = { a = 0.5, b = 1.2, scale = 4 } }",
    );
    let e = load_err(&text);
    assert_at(&e, &text, "b = ", "1.2", "materials.white.albedo.checker.b");
    assert!(e.message.contains("energy conservation"), "{e}");
}
