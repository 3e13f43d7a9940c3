//! The grader of the exercises in `exercises/`.
//!
//! Layered as the course's design describes: exact answers, sampling
//! routines by chi-square, estimators by furnace z-tests, whole integrators
//! against reference images. The graded exercises arrive with the exercises
//! issue; the physical validation of the renderer itself lives in
//! `raytracer/tests/`.

pub use exercises;
