//! The renderer's integration tests, one module per file beside this one,
//! built as one test binary: one link instead of one per file keeps a cold
//! `cargo test` within its time budget. `cargo test -p raytracer --test
//! integration furnace` runs one file's tests.

mod biased;
mod common;
mod cornell;
mod determinism;
mod direct_lighting;
mod door;
mod furnace;
mod lamp_coverage;
mod layering;
mod light_and_bdpt;
mod light_choice;
mod metropolis;
mod mitsuba_cornell;
mod photo_sky;
mod record;
mod scale;
mod scene_fuzz;
mod shading_normals;
mod unit;
mod wavefront;
