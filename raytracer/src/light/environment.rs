//! Environment light: radiance arriving from infinitely far away.

use std::sync::Arc;

use crate::math::{Color, Vec3A};

/// Light from every direction: a constant radiance, optionally multiplied by
/// a lat-long map.
#[derive(Clone, Debug)]
pub struct EnvironmentLight {
    /// Constant radiance, or the scale of the map.
    pub radiance: Color,
    pub map: Option<Arc<EnvironmentMap>>,
    /// Centre and radius of a sphere bounding the scene (set by the scene;
    /// emission starts on a disk of this radius).
    pub scene_center: Vec3A,
    pub scene_radius: f32,
}

/// A lat-long (equirectangular) radiance map.
#[derive(Clone, Debug)]
pub struct EnvironmentMap {
    pub width: u32,
    pub height: u32,
    /// Row-major, top row (up, +y) first.
    pub pixels: Vec<Color>,
}

impl EnvironmentMap {
    /// Loads a lat-long map from an EXR file (linear RGB).
    pub fn load(path: &std::path::Path) -> Result<EnvironmentMap, String> {
        let _ = path;
        todo!("light helper")
    }
}
