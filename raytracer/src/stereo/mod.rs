//! Stereoscopy: two eyes from one camera, and the ways to show the pair.
//!
//! Lecture topic: stereoscopy (first half of Lecture 11). A stereoscopic
//! picture is a pair of frames, one for each eye; nearer objects shift more
//! between the two viewpoints than farther ones (parallax), and the brain
//! reads that shift as depth. The course renders the two frames from two
//! viewpoints separated along the camera's `rightDir` by `stereoSeparation`
//! and, for an anaglyph, mixes them with suitable masks.
//!
//! - [`rig`]: the two eye cameras (parallel with off-axis frusta, or toe-in),
//!   rendered with the same random numbers;
//! - [`anaglyph`]: mixing for coloured glasses, with desaturation and
//!   Dubois' least-squares red–cyan; compositing is done in linear RGB (see
//!   there why);
//! - [`layout`]: side-by-side (parallel viewing), cross-eyed, over–under;
//! - [`crosstalk`]: what each eye sees through leaky filters (ghosting);
//! - [`lightfield`]: a grid of views across an aperture, refocused after the
//!   fact, and stereo pairs picked out of it.
//!
//! [`Composite`] names every way of showing a pair, for the command line.

pub mod anaglyph;
pub mod crosstalk;
pub mod layout;
pub mod lightfield;
pub mod rig;

pub use anaglyph::{Anaglyph, desaturate};
pub use layout::Layout;
pub use lightfield::{LightField, sharpness};
pub use rig::{Eye, StereoRig};

use crate::film::Image;

/// One way of showing a stereo pair as a single picture.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Composite {
    /// Mixed for coloured glasses.
    Anaglyph(Anaglyph),
    /// Placed next to each other.
    Layout(Layout),
    /// One eye's image alone.
    Eye(Eye),
}

impl Composite {
    /// Every composite: anaglyphs, layouts, then the two eyes.
    pub fn all() -> Vec<Composite> {
        let mut v: Vec<Composite> = Anaglyph::ALL.map(Composite::Anaglyph).to_vec();
        v.extend(Layout::ALL.map(Composite::Layout));
        v.extend(Eye::BOTH.map(Composite::Eye));
        v
    }

    /// Short name for files and the command line.
    pub fn name(self) -> &'static str {
        match self {
            Composite::Anaglyph(a) => a.name(),
            Composite::Layout(l) => l.name(),
            Composite::Eye(e) => e.name(),
        }
    }

    /// The picture for the pair `(left, right)`; `desaturate` ∈ [0, 1]
    /// applies to anaglyphs only (the other composites keep full colour).
    pub fn compose(self, left: &Image, right: &Image, desaturate: f32) -> Image {
        match self {
            Composite::Anaglyph(a) => a.compose(left, right, desaturate),
            Composite::Layout(l) => l.compose(left, right),
            Composite::Eye(Eye::Left) => left.clone(),
            Composite::Eye(Eye::Right) => right.clone(),
        }
    }
}

impl std::str::FromStr for Composite {
    type Err = String;

    /// A name as [`Composite::name`] gives it; also `gray`, `half-colour`,
    /// `parallel`, `cross`, `yellow-blue`.
    fn from_str(s: &str) -> Result<Self, String> {
        let s = s.trim().to_ascii_lowercase();
        let alias = match s.as_str() {
            "gray" => "grey",
            "half-colour" | "half-gray" | "half-grey" => "half-color",
            "parallel" | "sbs" => "side-by-side",
            "cross" => "cross-eyed",
            "yellow-blue" => "amber-blue",
            "dubois-red-cyan" => "dubois",
            other => other,
        };
        Composite::all()
            .into_iter()
            .find(|c| c.name() == alias)
            .ok_or_else(|| {
                let names: Vec<_> = Composite::all().iter().map(|c| c.name()).collect();
                format!(
                    "unknown stereo mode {s:?}: choose one of {}",
                    names.join(", ")
                )
            })
    }
}
