//! Where the student's functions plug into the renderer: integrators and
//! image operations built from renderer pieces plus the exercises, so that
//! `lesson11 render --student` (and the grader) render with the student's code.
//!
//! One file per exercise that plugs in (`stereo`, `naive`, `path`, `light`,
//! `bdpt`, `metropolis`, `photon`, `vpl`), and [`StudentRender`], the list
//! `render --student` chooses from; everything is re-exported here, so
//! `exercises::plug::StudentPathTracer` and the like name them.

mod bdpt;
mod light;
mod metropolis;
mod naive;
mod path;
mod photon;
mod stereo;
mod student_render;
mod vpl;

pub use bdpt::*;
pub use light::*;
pub use metropolis::*;
pub use naive::*;
pub use path::*;
pub use photon::*;
pub use stereo::*;
pub use student_render::*;
pub use vpl::*;
