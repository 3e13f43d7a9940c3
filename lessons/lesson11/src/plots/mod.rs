//! Plots as SVG files: line charts (linear or log–log axes), stacked bars and
//! polar plots of BRDF lobes. SVG needs no fonts or libraries at build time and every browser
//! shows it, so the lesson's page stays self-contained. One plot is an image
//! instead, because it lies over a rendered picture pixel for pixel: the tile
//! z-map of two renders.

mod bars;
mod chart;
mod polar;
mod series;
mod zmap;

pub use bars::Bars;
pub use chart::{Chart, Scale};
pub use polar::polar_svg;
pub use series::Series;
pub use zmap::zmap_image;
