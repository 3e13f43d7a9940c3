//! The stereo rig: two eye cameras derived from any camera.
//!
//! Lecture topic: stereoscopic rendering — "render two frames from two
//! viewpoints, separated along the camera's `rightDir`".
//!
//! # Convention
//!
//! The eyes sit at `position ∓ (stereoSeparation/2) · rightDir` (left eye at
//! minus, right eye at plus), so `stereoSeparation` is the full distance
//! between the eyes, the interocular distance (about 0.065 m for a person in
//! a scene modelled in metres). Beware when comparing with the course's C++
//! renderers: some versions offset each eye by ±separation (so their eyes are
//! 2·separation apart) and some by ±separation/2 as here; the same number
//! therefore gives twice the depth effect in the former.
//!
//! # Parallel eyes, off-axis frusta
//!
//! Both eyes look along the original `forward`; their image planes are
//! parallel, so a point has the same height (raster `y`) in both images: no
//! vertical parallax. Without more, they would converge at infinity (every
//! point would lie in front of the screen). To put the screen at the
//! zero-parallax distance `C`, each eye's image window is shifted sideways
//! (an asymmetric, off-axis frustum): a point on the plane at depth `C` is at
//! horizontal image-plane coordinate `(X ± s/2)/C` in the two eyes (`X` its
//! offset from the axis, `s` the separation), so shifting the left window by
//! `+s/(2C)` and the right one by `−s/(2C)` makes both `X/C` — the same pixel
//! in both images, for the whole plane.
//!
//! # Toe-in (deliberately flawed)
//!
//! The naïve alternative turns each eye towards the convergence point. The two
//! image planes are then no longer parallel, and a point away from the centre
//! lands at different heights in the two images — vertical parallax, which
//! the eyes cannot fuse comfortably. Kept to show exactly that.
//!
//! # Random numbers and the thin lens
//!
//! Both eyes are rendered with the same seed. Random numbers depend only on
//! (seed, pixel, sample, dimension), so the two images use identical
//! sequences: their noise is correlated and the eyes are not asked to fuse two
//! different noise patterns. The eyes keep the camera's lens: aperture radius
//! and focus distance are unchanged, and since a parallel eye's plane in focus
//! is perpendicular to the shared `forward`, both eyes focus on the same plane.

use crate::camera::{Camera, CameraParams};
use crate::film::Image;
use crate::integrator::Integrator;
use crate::math::{Vec2, Vec3A};
use crate::render::{RenderOptions, RenderResult, render};
use crate::scene::Scene;

/// Which eye.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Eye {
    Left,
    Right,
}

impl Eye {
    /// Both eyes, left first.
    pub const BOTH: [Eye; 2] = [Eye::Left, Eye::Right];

    /// −1 for the left eye, +1 for the right: the eye sits at
    /// `position + sign · (separation/2) · rightDir`.
    #[inline]
    pub fn sign(self) -> f32 {
        match self {
            Eye::Left => -1.0,
            Eye::Right => 1.0,
        }
    }

    /// "left" or "right" (file names).
    pub fn name(self) -> &'static str {
        match self {
            Eye::Left => "left",
            Eye::Right => "right",
        }
    }
}

/// How the two eyes are derived from a camera.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StereoRig {
    /// `stereoSeparation`: the full distance between the eyes, in scene units.
    pub separation: f32,
    /// Zero-parallax (convergence) distance along `forward`; `None` = the
    /// camera's focus distance.
    pub convergence: Option<f32>,
    /// Turn the eyes towards the convergence point instead of shifting their
    /// frusta (the flawed method, which causes vertical parallax).
    pub toe_in: bool,
}

impl Default for StereoRig {
    /// 6.5 cm between the eyes, converging at the focus distance, off-axis.
    fn default() -> Self {
        StereoRig {
            separation: 0.065,
            convergence: None,
            toe_in: false,
        }
    }
}

/// What is wrong with a rig's numbers.
#[derive(Clone, Debug, PartialEq)]
pub struct RigError(pub String);

impl std::fmt::Display for RigError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for RigError {}

impl StereoRig {
    /// Checks the numbers: a finite separation ≥ 0 and a finite convergence
    /// distance > 0.
    pub fn validate(&self) -> Result<(), RigError> {
        if !(self.separation.is_finite() && self.separation >= 0.0) {
            return Err(RigError(format!(
                "the stereo separation must be a finite distance ≥ 0, got {}",
                self.separation
            )));
        }
        match self.convergence {
            Some(c) if !(c.is_finite() && c > 0.0) => Err(RigError(format!(
                "the convergence distance must be positive, got {c}"
            ))),
            _ => Ok(()),
        }
    }

    /// The zero-parallax distance for `base`: the given one, else the focus distance.
    #[inline]
    pub fn convergence_distance(&self, base: &CameraParams) -> f32 {
        self.convergence.unwrap_or(base.focus_distance)
    }

    /// The parameters of one eye's camera, derived from the camera `base`.
    pub fn eye_params(&self, base: &Camera, eye: Eye) -> CameraParams {
        let p = base.params;
        let half = 0.5 * self.separation * eye.sign();
        let offset = half * base.right_dir();
        let position = p.position + offset;
        let c = self.convergence_distance(&p);
        if self.toe_in {
            // Both eyes look at the convergence point on the original axis.
            let target = p.position + c * base.forward();
            CameraParams {
                position,
                look_at: target,
                focus_distance: (target - position).length(),
                ..p
            }
        } else {
            // Parallel: the same view direction, the window shifted by
            // −sign·(s/2)/C so that depth C has zero parallax (module doc).
            CameraParams {
                position,
                look_at: p.look_at + offset,
                shift: p.shift + Vec2::new(-half / c, 0.0),
                ..p
            }
        }
    }

    /// One eye's camera, at the base camera's resolution.
    pub fn eye_camera(&self, base: &Camera, eye: Eye) -> Camera {
        Camera::new(self.eye_params(base, eye), base.width, base.height)
    }

    /// Both eye cameras, left first.
    pub fn eyes(&self, base: &Camera) -> [Camera; 2] {
        Eye::BOTH.map(|e| self.eye_camera(base, e))
    }

    /// Renders both eyes of `scene` with the same options (hence the same
    /// seed and random sequences), left first.
    pub fn render_pair(
        &self,
        scene: &Scene,
        integrator: &dyn Integrator,
        options: &RenderOptions,
    ) -> [RenderResult; 2] {
        let eyes = self.eyes(&scene.camera);
        let mut eye_scene = scene.clone();
        eyes.map(|camera| {
            eye_scene.camera = camera;
            render(&eye_scene, integrator, options)
        })
    }
}

/// The stereo pair as images, left first.
pub fn pair_images(results: &[RenderResult; 2]) -> [Image; 2] {
    [results[0].film.image(), results[1].film.image()]
}

/// The raster positions of the world point `p` in the two eyes (pinhole
/// projection through each lens centre), or `None` if either eye misses it.
pub fn project_pair(eyes: &[Camera; 2], p: Vec3A) -> Option<[Vec2; 2]> {
    Some([
        eyes[0].raster_of(p, eyes[0].position())?,
        eyes[1].raster_of(p, eyes[1].position())?,
    ])
}
