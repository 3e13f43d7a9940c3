//! The images of bidirectional path tracing's strategies, one per `(s, t)`.
//!
//! Lecture topic: "Bidirectional path tracing" — every strategy estimates the
//! same paths, and MIS lets each count where it is good. Rendering each
//! strategy alone, unweighted and weighted, shows both halves of that
//! sentence (pbrt's `visualizestrategies`); the lesson's slides show them.
//! This lives with the render loop, above the integrators: it renders a
//! [`Bdpt`] many times, each time keeping one strategy.

use super::{RenderOptions, render};
use crate::film::Image;
use crate::integrator::{Bdpt, StrategyFilter};
use crate::scene::Scene;

/// One image per strategy `(s, t)` with `s + t ≤ D + 1` (`t ≥ 1`,
/// `max_depth = D`, paths of at least two vertices): `((s, t), weighted,
/// unweighted)`. The weighted images add up to the BDPT image; an unweighted
/// image is that strategy's own estimate of all the paths it can generate
/// (noisy where it is a poor strategy, black where it is impossible). Two
/// renders per strategy with `options`; keep the image small.
pub fn render_strategies(
    scene: &Scene,
    options: &RenderOptions,
    max_depth: u32,
) -> Vec<((u32, u32), Image, Image)> {
    let mut out = Vec::new();
    for n in 2..=max_depth + 1 {
        for t in 1..=n {
            let s = n - t;
            let image = |weighted: bool| {
                let bdpt = Bdpt {
                    max_depth: Some(max_depth),
                    rr_depth: u32::MAX,
                    strategy_images: Some(StrategyFilter { s, t, weighted }),
                };
                let options = RenderOptions {
                    label: format!("bdpt s={s} t={t}"),
                    ..options.clone()
                };
                render(scene, &bdpt, &options).film.image()
            };
            out.push(((s, t), image(true), image(false)));
        }
    }
    out
}
