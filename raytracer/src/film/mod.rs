//! The film: where pixel estimates are accumulated and written out.

use crate::math::{Color, Vec2};

/// A contribution to an arbitrary raster position (light tracing connects a
/// light-path vertex to the camera and lands anywhere on the film).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Splat {
    pub raster: Vec2,
    pub value: Color,
}
