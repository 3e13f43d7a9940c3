//! Unit tests of `texts.rs`.

use grading::texts::*;

const SOURCE: &str = r#"
/// A texture.
pub enum Texture {
Constant(Color),
Checker { a: Color, b: Color, scale: f32 },
}
impl Texture {
pub fn eval(&self, uv: Vec2) -> Color { let s = "{"; let c = '}'; todo!() }
}
pub struct CameraSample {
pub raster: Vec2,
/// Importance.
pub we: f32,
}
impl<'a> std::fmt::Display for CameraSample { fn fmt(&self) {} }
pub fn luminance(c: Color) -> f32 { 0.0 }
"#;

#[test]
fn the_index_finds_methods_fields_and_variants() {
    let mut api = Api::default();
    api.scan(SOURCE);
    let texture = &api.types["Texture"];
    assert!(texture.contains("eval") && texture.contains("Checker"));
    assert!(api.types["CameraSample"].contains("we"));
    assert!(api.types["CameraSample"].contains("fmt"));
    assert!(api.fns.contains("luminance"));
    assert!(api.fields.contains("raster"));
}

#[test]
fn unknown_names_are_reported_and_known_ones_are_not() {
    let mut api = Api::default();
    api.scan(SOURCE);
    api.modules.extend(["raytracer", "math"].map(String::from));
    // The mistake of the old exercise 3: the slide's texture.sample.
    assert_eq!(
        api.unknown_names("Texture::sample", true),
        ["Texture::sample"]
    );
    assert!(api.unknown_names("Texture::eval", true).is_empty());
    assert_eq!(api.unknown_names("albedo.sample(uv)", false), [".sample("]);
    assert!(api.unknown_names("albedo.eval(uv) / π", false).is_empty());
    assert!(
        api.unknown_names("raytracer::math::luminance(c)", false)
            .is_empty()
    );
    assert_eq!(
        api.unknown_names("raytracer::maths::luminance", false),
        ["raytracer::maths::luminance"]
    );
    assert_eq!(api.unknown_names("s.weight", true), [".weight"]);
    assert!(
        api.unknown_names("s.we, wo.z, Vec3A::ZERO, L_e, W_e", true)
            .is_empty()
    );
    assert_eq!(api.unknown_names("Sample", true), ["Sample"]);
    // Prose (a hint): names are no types, "e.g." is no call.
    assert!(
        api.unknown_names("Malley's method, e.g. 1 − cos θ", false)
            .is_empty()
    );
}

#[test]
fn a_stub_cites_its_slides_in_pairs() {
    let stub = "//! Exercise 3 — x.\n//!\n//! Slides: \"BRDF examples: diffuse and glossy\" (\"Примери за\n//! BRDF: дифузен и glossy\"), \"Properties of BRDFs\" (\"Свойства на BRDF-ите\").\n//!\n//! \"Not a slide\".\n";
    let (en, bg) = cited_slides(stub);
    assert_eq!(
        en,
        ["BRDF examples: diffuse and glossy", "Properties of BRDFs"]
    );
    assert_eq!(
        bg,
        ["Примери за BRDF: дифузен и glossy", "Свойства на BRDF-ите"]
    );
}

#[test]
fn comment_text_leaves_out_code_and_formulas() {
    let src = "//! a `X`\n//! ```text\n//! `Y`\n//! ```\nfn f() { `Z` }\n/// b\n";
    assert_eq!(comment_text(src), " a `X`\n b\n");
    assert_eq!(code_spans(&comment_text(src)), ["X"]);
}
