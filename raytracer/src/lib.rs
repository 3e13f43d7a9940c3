//! `raytracer`: the shared physically based renderer of the course.
//!
//! # Brief overview
//!
//! One module per concept, named as Lecture 11 names it, listed from the
//! bottom layer up:
//!
//! | layer | module | what | lecture |
//! |---|---|---|---|
//! | 0 | [`math`] | vectors, rays, robust ray offsets | — |
//! | 1 | [`frame`] | the local shading frame | — |
//! | 2 | [`sampling`] | counter-based random numbers, warps with their pdfs, MIS heuristics | Monte Carlo |
//! | 3 | [`geometry`] | spheres, quads, OBJ meshes, transforms, the BVH, ray hits | — |
//! | 3 | [`film`] | accumulation, splatting, PNG and EXR output | — |
//! | 4 | [`camera`] | pinhole and thin lens; importance for light tracing | stereoscopy, paths |
//! | 4 | [`brdf`] | Lambert, normalized Phong, mirror, glass | BRDFs |
//! | 4 | [`light`] | area, point and environment lights | `L_e` of the rendering equation |
//! | 5 | [`scene`] | the scene, its TOML format and the built-in scenes | Cornell box |
//! | 6 | [`integrator`] | direct light, AO, naive recursion, path, light and bidirectional tracing; photon mapping, SPPM, instant radiosity, irradiance caching | rendering equation, GI algorithms: unbiased and biased |
//! | 7 | [`render`] | the parallel, deterministic loop over pixels; BDPT's strategy images; Metropolis light transport's chains | GI algorithms: Metropolis |
//! | 8 | [`stereo`] | stereo rig, anaglyphs, side-by-side, crosstalk, light fields | stereoscopy |
//! | 8 | [`metrics`] | image statistics and comparisons for the lessons and the grader | — |
//! | 8 | [`wavefront`] | the path tracer as a second engine: all of a tile's paths in lockstep, stage by stage | path tracing (how it runs fast) |
//!
//! A scene is loaded (or taken from the built-in ones), an integrator
//! estimates the radiance of each pixel sample, and the render loop gathers
//! the estimates on a film:
//!
//! ```no_run
//! use raytracer::{integrator::Direct, render, render::RenderOptions, scene::Scene};
//! let scene = Scene::builtin("cornell").unwrap();
//! let options = RenderOptions::from(&scene.settings);
//! let result = render::render(&scene, &Direct::default(), &options);
//! result.film.write_png("cornell.png", 0.0).unwrap();
//! ```
//!
//! # Layers
//!
//! Arrows point down: a module uses only modules on lower layers, never one
//! on its own layer or above, so each can be read (and tested) knowing only
//! what lies below it. `tests/layering.rs` reads the sources and fails on an
//! import against this order, which it takes from the block below (the tests,
//! all in `tests/` — the unit tests in `tests/unit/` — may use the whole crate):
//!
//! ```text
//! 8 stereo metrics wavefront
//! 7 render
//! 6 integrator
//! 5 scene
//! 4 camera brdf light
//! 3 geometry film
//! 2 sampling
//! 1 frame
//! 0 math
//! ```
//!
//! The film sits low although the render loop fills it: it needs nothing but
//! `math`, and the integrators hand it their splats. A scene says how it
//! wants to be rendered ([`scene::RenderSettings`]); the render loop turns
//! that into its options ([`render::RenderOptions`]), not the other way round.

pub mod brdf;
pub mod camera;
pub mod film;
pub mod frame;
pub mod geometry;
pub mod integrator;
pub mod light;
pub mod math;
pub mod metrics;
pub mod render;
pub mod sampling;
pub mod scene;
pub mod stereo;
pub mod wavefront;
