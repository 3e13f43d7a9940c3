//! The student's exercises of Lecture 11, one file each, in lecture order.
//!
//! Each exercise is a function with the signature the renderer calls, so that
//! `lesson11 <chapter> --student` can render a picture with the student's own
//! code. The exercises themselves arrive with the exercises issue; this crate
//! already sits in the workspace between `lesson11` and `raytracer`.

/// The renderer the exercises plug into.
pub use raytracer;
