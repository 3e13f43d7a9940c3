//! Plots as SVG files: line charts (linear or log–log axes), stacked bars,
//! polar plots of BRDF lobes and the lecture's figure of the hemisphere at a
//! point (in each language of the slides). SVG needs no fonts or libraries at
//! build time and every browser shows it, so the lesson's page stays
//! self-contained. One plot is an image
//! instead, because it lies over a rendered picture pixel for pixel: the tile
//! z-map of two renders. Path figures, and signed pictures with their
//! numbered colour bars, are SVG drawn over a picture, which they embed.

pub mod bars;
pub mod chart;
pub mod data_uri;
pub mod hemisphere;
pub mod palette;
pub mod path_figure;
pub mod polar;
pub mod series;
pub mod signed_map;
pub mod solid_angle;
pub mod zmap;

pub use bars::{Bars, Part};
pub use chart::{Chart, Scale};
pub use hemisphere::{Hemisphere, HemisphereWords, LANGS, hemisphere_svg};
pub use palette::Drawn;
pub use path_figure::{Labels, in_picture, path_figure_svg, pick_sample};
pub use polar::polar_svg;
pub use series::Series;
pub use signed_map::{round_scale, signed_map_svg};
pub use solid_angle::{SolidAngle, solid_angle_svg};
pub use zmap::zmap_image;
