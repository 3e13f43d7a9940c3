//! `raytracer`: the shared physically based renderer of the course.
//!
//! # Brief overview
//!
//! One module per concept, named as Lecture 11 names it:
//!
//! | module | what | lecture |
//! |---|---|---|
//! | [`math`], [`frame`] | vectors, rays, robust ray offsets, the shading frame | — |
//! | [`sampling`] | counter-based random numbers, warps with their pdfs, MIS | Monte Carlo |
//! | [`geometry`] | spheres, quads, OBJ meshes, transforms, the BVH | — |
//! | [`camera`] | pinhole and thin lens; importance for light tracing | stereoscopy, paths |
//! | [`brdf`] | Lambert, normalized Phong, mirror, glass | BRDFs |
//! | [`light`] | area, point and environment lights | `L_e` of the rendering equation |
//! | [`scene`] | the scene, its TOML format and the built-in scenes | Cornell box |
//! | [`integrator`] | direct light, AO, naive recursion, path, light and bidirectional tracing | rendering equation, GI algorithms |
//! | [`film`] | accumulation, splatting, PNG and EXR output | — |
//! | [`render`] | the parallel, deterministic loop over pixels | — |
//! | [`stereo`] | stereo rig, anaglyphs, side-by-side, crosstalk, light fields | stereoscopy |
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
