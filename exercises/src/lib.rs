//! The student's exercises of Lecture 11, one file each, in lecture order.
//!
//! Each exercise is a function with the signature the renderer calls, so that
//! `lesson11 render --student` can render a picture with the student's own
//! code ([`plug`] builds the integrators around them). Fill in a stub in
//! `src/exNN_*.rs`, run `cargo test`, and the grader (the `grading` crate in
//! `tests/`) reports every exercise as passed, failed (with a reason) or not
//! started. [`registry`] lists them with their slides and hints
//! (`info.toml`).
//!
//! With the cargo feature `solutions`, the reference solutions in
//! `solutions/` are compiled in place of the stubs (the grader's self-test
//! uses it; the course ships with the stubs).

pub mod plug;
pub mod registry;

pub use registry::{Exercise, registry};

/// The renderer the exercises plug into.
pub use raytracer;

// Each exercise: the stub in `src/`, or with the feature `solutions` the
// reference solution in `solutions/`. Stubs leave their arguments unused
// until they are solved, hence the `allow`.
#[allow(unused_variables)]
#[cfg_attr(feature = "solutions", path = "../solutions/ex01_stereo_eyes.rs")]
pub mod ex01_stereo_eyes;
#[allow(unused_variables)]
#[cfg_attr(feature = "solutions", path = "../solutions/ex02_anaglyph.rs")]
pub mod ex02_anaglyph;
#[allow(unused_variables)]
#[cfg_attr(feature = "solutions", path = "../solutions/ex03_lambert.rs")]
pub mod ex03_lambert;
#[allow(unused_variables)]
#[cfg_attr(feature = "solutions", path = "../solutions/ex04_phong.rs")]
pub mod ex04_phong;
#[allow(unused_variables)]
#[cfg_attr(feature = "solutions", path = "../solutions/ex05_cone_lobe.rs")]
pub mod ex05_cone_lobe;
#[allow(unused_variables)]
#[cfg_attr(feature = "solutions", path = "../solutions/ex06_mirror.rs")]
pub mod ex06_mirror;
#[allow(unused_variables)]
#[cfg_attr(feature = "solutions", path = "../solutions/ex07_cosine_sampling.rs")]
pub mod ex07_cosine_sampling;
#[allow(unused_variables)]
#[cfg_attr(feature = "solutions", path = "../solutions/ex08_phong_lobe_pdf.rs")]
pub mod ex08_phong_lobe_pdf;
#[allow(unused_variables)]
#[cfg_attr(feature = "solutions", path = "../solutions/ex09_albedo.rs")]
pub mod ex09_albedo;
#[allow(unused_variables)]
#[cfg_attr(feature = "solutions", path = "../solutions/ex10_naive_recursive.rs")]
pub mod ex10_naive_recursive;
#[allow(unused_variables)]
#[cfg_attr(feature = "solutions", path = "../solutions/ex11_path_tracing.rs")]
pub mod ex11_path_tracing;
#[allow(unused_variables)]
#[cfg_attr(feature = "solutions", path = "../solutions/ex12_nee.rs")]
pub mod ex12_nee;
#[allow(unused_variables)]
#[cfg_attr(feature = "solutions", path = "../solutions/ex13_mis.rs")]
pub mod ex13_mis;
#[allow(unused_variables)]
#[cfg_attr(feature = "solutions", path = "../solutions/ex14_light_tracing.rs")]
pub mod ex14_light_tracing;
#[allow(unused_variables)]
#[cfg_attr(feature = "solutions", path = "../solutions/ex15_bdpt.rs")]
pub mod ex15_bdpt;
#[allow(unused_variables)]
#[cfg_attr(feature = "solutions", path = "../solutions/ex16_metropolis.rs")]
pub mod ex16_metropolis;
#[allow(unused_variables)]
#[cfg_attr(feature = "solutions", path = "../solutions/ex17_photon_mapping.rs")]
pub mod ex17_photon_mapping;
#[allow(unused_variables)]
#[cfg_attr(feature = "solutions", path = "../solutions/ex18_instant_radiosity.rs")]
pub mod ex18_instant_radiosity;

/// The module names, in lecture order (they match `info.toml`).
pub const MODULES: &[&str] = &[
    "ex01_stereo_eyes",
    "ex02_anaglyph",
    "ex03_lambert",
    "ex04_phong",
    "ex05_cone_lobe",
    "ex06_mirror",
    "ex07_cosine_sampling",
    "ex08_phong_lobe_pdf",
    "ex09_albedo",
    "ex10_naive_recursive",
    "ex11_path_tracing",
    "ex12_nee",
    "ex13_mis",
    "ex14_light_tracing",
    "ex15_bdpt",
    "ex16_metropolis",
    "ex17_photon_mapping",
    "ex18_instant_radiosity",
];

/// Whether this build uses the reference solutions (feature `solutions`).
pub const SOLUTIONS: bool = cfg!(feature = "solutions");

/// The directory of this crate (for the files of the exercises and solutions).
pub fn crate_dir() -> &'static std::path::Path {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
}
