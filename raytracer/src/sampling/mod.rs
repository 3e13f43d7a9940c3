//! Monte Carlo sampling: the random numbers, the warps that turn them into
//! directions and points, and the heuristics that combine several estimators.
//!
//! Lecture topic: Monte Carlo integration, the tool behind every global
//! illumination algorithm of the lecture. An estimator reads `f(x) / pdf(x)`
//! with `x` drawn from `pdf`; every warp here therefore comes with its pdf (and
//! its inverse where that is cheap), and takes its uniform numbers `u`
//! explicitly so that tests can drive it with chosen values.

pub mod chi2;
pub mod distribution;
pub mod draw;
pub mod mis;
pub mod primary;
pub mod rng;
pub mod sincos;
pub mod warp;

pub use distribution::{Distribution1D, Distribution2D};
pub use draw::Draw;
pub use mis::{balance_heuristic, power_heuristic};
pub use primary::{PrimarySample, Stream};
pub use rng::Sampler;
