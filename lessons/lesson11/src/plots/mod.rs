//! Plots as SVG files: line charts (linear or log–log axes) and polar plots of
//! BRDF lobes. SVG needs no fonts or libraries at build time and every browser
//! shows it, so the lesson's page stays self-contained.

mod chart;
mod polar;
mod series;

pub use chart::{Chart, Scale};
pub use polar::polar_svg;
pub use series::Series;
