//! Anaglyphs: both eye images mixed into one, each seen through a coloured filter.
//!
//! Lecture topic: anaglyph glasses — each frame passes through a colour filter
//! and the two are mixed into one picture; glasses with the same filters let
//! each eye see only its own frame. The lecture names red–blue, red–cyan,
//! red–green and yellow glasses; here also amber–blue (ColorCode 3-D, the
//! lecture's "yellow") and green–magenta (TrioScopics). The left eye wears the
//! first colour of each name.
//!
//! Every mode is linear: `out = M_L · D(a) · left + M_R · D(a) · right`, with
//! 3×3 matrices `M_L`, `M_R` and the desaturation `D(a) = (1 − a) I + a · 1 wᵀ`
//! (`w` the Rec. 709 luminance weights): `a = 0` keeps the colours, `a = 1`
//! turns both images grey first. Desaturating is the lecture's remedy for
//! saturated scenes: a pure red object sends nothing through the cyan filter,
//! so the right eye sees a hole there and the two eyes cannot fuse it.
//!
//! # Why in linear RGB
//!
//! A filter multiplies light, channel by channel, and the display adds the
//! channels' light: both are linear in radiance, not in the sRGB-encoded
//! values of a PNG. Luminance is also a weighted sum of *linear* values, and
//! Dubois derived his matrices for linear intensities. So compositing happens
//! on the film's linear radiance and sRGB encoding comes last, when writing.
//! Mixing encoded values would make grey modes too dark in the mid-tones and
//! change the balance between the eyes.
//!
//! The modes:
//!
//! | mode | red | green | blue |
//! |---|---|---|---|
//! | red–cyan colour | left R | right G | right B |
//! | red–cyan half-colour | left Y | right G | right B |
//! | red–cyan grey | left Y | right Y | right Y |
//! | red–blue | left Y | 0 | right Y |
//! | red–green | left Y | right Y | 0 |
//! | amber–blue | left R | left G | right Y |
//! | green–magenta | right R | left G | right B |
//! | Dubois red–cyan | least-squares matrices | | |
//!
//! (`Y` = luminance.) Red–blue and red–green filters are not complementary:
//! each passes one primary only, so each eye gets its image's luminance in
//! that primary (colour is lost anyway). Amber–blue gives the blue eye the
//! right image's luminance, since a blue filter alone would hide everything
//! that has no blue in it.

use glam::Mat3A;

use super::rig::Eye;
use crate::film::Image;
use crate::math::{Color, Vec3A};

/// Rec. 709 luminance weights (as [`crate::math::luminance`]).
pub const LUMA: Vec3A = Vec3A::new(0.2126, 0.7152, 0.0722);

/// A 3×3 matrix given row by row.
fn rows(r: [[f32; 3]; 3]) -> Mat3A {
    Mat3A::from_cols_array_2d(&r).transpose()
}

/// The matrix that puts the luminance into the channels marked 1 in `mask`.
fn luma_into(mask: [f32; 3]) -> Mat3A {
    let w = LUMA.to_array();
    rows(mask.map(|m| w.map(|x| m * x)))
}

/// The matrix that keeps the channels marked 1 in `mask`.
fn keep(mask: [f32; 3]) -> Mat3A {
    Mat3A::from_diagonal(glam::Vec3::from_array(mask))
}

/// The desaturation matrix `D(a) = (1 − a) I + a · 1 wᵀ`.
pub fn desaturation(amount: f32) -> Mat3A {
    Mat3A::IDENTITY * (1.0 - amount) + luma_into([1.0, 1.0, 1.0]) * amount
}

/// `c` desaturated by `amount` ∈ [0, 1]: 0 leaves it unchanged, 1 gives the
/// grey of the same luminance; in between, a straight line (luminance is kept).
#[inline]
pub fn desaturate(c: Color, amount: f32) -> Color {
    let y = LUMA.dot(c);
    c + amount * (Vec3A::splat(y) - c)
}

/// Anaglyph glasses and how the two images are mixed for them.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Anaglyph {
    /// Red–cyan in colour: red from the left image, green and blue from the right.
    RedCyan,
    /// Red–cyan, half colour: the left image's luminance in red (less rivalry
    /// between the eyes on red objects), the right image's green and blue.
    HalfColor,
    /// Red–cyan grey: both images as luminance.
    Grey,
    /// Red–blue glasses.
    RedBlue,
    /// Red–green glasses.
    RedGreen,
    /// Amber–blue glasses (ColorCode 3-D).
    AmberBlue,
    /// Green–magenta glasses (TrioScopics).
    GreenMagenta,
    /// Red–cyan with Dubois' least-squares matrices: the best quality.
    Dubois,
}

impl Anaglyph {
    pub const ALL: [Anaglyph; 8] = [
        Anaglyph::RedCyan,
        Anaglyph::HalfColor,
        Anaglyph::Grey,
        Anaglyph::RedBlue,
        Anaglyph::RedGreen,
        Anaglyph::AmberBlue,
        Anaglyph::GreenMagenta,
        Anaglyph::Dubois,
    ];

    /// Short name for files and the command line.
    pub fn name(self) -> &'static str {
        match self {
            Anaglyph::RedCyan => "red-cyan",
            Anaglyph::HalfColor => "half-color",
            Anaglyph::Grey => "grey",
            Anaglyph::RedBlue => "red-blue",
            Anaglyph::RedGreen => "red-green",
            Anaglyph::AmberBlue => "amber-blue",
            Anaglyph::GreenMagenta => "green-magenta",
            Anaglyph::Dubois => "dubois",
        }
    }

    /// The glasses to wear.
    pub fn glasses(self) -> &'static str {
        match self {
            Anaglyph::RedCyan | Anaglyph::HalfColor | Anaglyph::Grey | Anaglyph::Dubois => {
                "red (left) – cyan (right)"
            }
            Anaglyph::RedBlue => "red (left) – blue (right)",
            Anaglyph::RedGreen => "red (left) – green (right)",
            Anaglyph::AmberBlue => "amber (left) – blue (right)",
            Anaglyph::GreenMagenta => "green (left) – magenta (right)",
        }
    }

    /// The ideal transmission of each eye's filter per RGB channel, left first.
    pub fn filters(self) -> [Color; 2] {
        const R: Color = Vec3A::new(1.0, 0.0, 0.0);
        const G: Color = Vec3A::new(0.0, 1.0, 0.0);
        const B: Color = Vec3A::new(0.0, 0.0, 1.0);
        const CYAN: Color = Vec3A::new(0.0, 1.0, 1.0);
        const AMBER: Color = Vec3A::new(1.0, 1.0, 0.0);
        const MAGENTA: Color = Vec3A::new(1.0, 0.0, 1.0);
        match self {
            Anaglyph::RedCyan | Anaglyph::HalfColor | Anaglyph::Grey | Anaglyph::Dubois => {
                [R, CYAN]
            }
            Anaglyph::RedBlue => [R, B],
            Anaglyph::RedGreen => [R, G],
            Anaglyph::AmberBlue => [AMBER, B],
            Anaglyph::GreenMagenta => [G, MAGENTA],
        }
    }

    /// The filter in front of `eye`.
    pub fn filter(self, eye: Eye) -> Color {
        self.filters()[match eye {
            Eye::Left => 0,
            Eye::Right => 1,
        }]
    }

    /// The mixing matrices `[M_L, M_R]` (without desaturation).
    pub fn matrices(self) -> [Mat3A; 2] {
        match self {
            Anaglyph::RedCyan => [keep([1.0, 0.0, 0.0]), keep([0.0, 1.0, 1.0])],
            Anaglyph::HalfColor => [luma_into([1.0, 0.0, 0.0]), keep([0.0, 1.0, 1.0])],
            Anaglyph::Grey => [luma_into([1.0, 0.0, 0.0]), luma_into([0.0, 1.0, 1.0])],
            Anaglyph::RedBlue => [luma_into([1.0, 0.0, 0.0]), luma_into([0.0, 0.0, 1.0])],
            Anaglyph::RedGreen => [luma_into([1.0, 0.0, 0.0]), luma_into([0.0, 1.0, 0.0])],
            Anaglyph::AmberBlue => [keep([1.0, 1.0, 0.0]), luma_into([0.0, 0.0, 1.0])],
            Anaglyph::GreenMagenta => [keep([0.0, 1.0, 0.0]), keep([1.0, 0.0, 1.0])],
            // E. Dubois, "A projection method to generate anaglyph stereo
            // images", ICASSP 2001: the least-squares red–cyan matrices as
            // widely reproduced (Bino, the Wikipedia article on anaglyphs).
            // They map *linear* RGB of each eye to linear RGB of the
            // anaglyph, chosen so that what each eye sees through its filter
            // is as close as possible (in a CIE XYZ least-squares sense) to
            // the original image. Dubois later (2009) published slightly
            // different values measured for other filters and displays.
            Anaglyph::Dubois => [
                rows([
                    [0.456, 0.500, 0.176],
                    [-0.040, -0.038, -0.016],
                    [-0.015, -0.021, -0.005],
                ]),
                rows([
                    [-0.043, -0.088, -0.002],
                    [0.378, 0.734, -0.018],
                    [-0.072, -0.113, 1.226],
                ]),
            ],
        }
    }

    /// One anaglyph pixel from the two eyes' linear colours, after
    /// desaturating both by `desaturate` ∈ [0, 1]. Negative results (Dubois
    /// can give them) are clamped to 0: a display cannot emit less than
    /// nothing.
    #[inline]
    pub fn mix(self, left: Color, right: Color, desaturate_amount: f32) -> Color {
        let [ml, mr] = self.matrices();
        let d = desaturation(desaturate_amount);
        (ml * (d * left) + mr * (d * right)).max(Vec3A::ZERO)
    }

    /// The anaglyph of two equally sized linear images.
    ///
    /// # Panics
    /// If the sizes differ.
    pub fn compose(self, left: &Image, right: &Image, desaturate_amount: f32) -> Image {
        assert_same_size(left, right);
        let [ml, mr] = self.matrices();
        let d = desaturation(desaturate_amount);
        let (ml, mr) = (ml * d, mr * d);
        Image {
            width: left.width,
            height: left.height,
            pixels: left
                .pixels
                .iter()
                .zip(&right.pixels)
                .map(|(&l, &r)| (ml * l + mr * r).max(Vec3A::ZERO))
                .collect(),
        }
    }
}

/// Panics with a clear message unless both images have the same size.
pub fn assert_same_size(a: &Image, b: &Image) {
    assert!(
        a.width == b.width && a.height == b.height,
        "the eye images differ in size: {}×{} and {}×{}",
        a.width,
        a.height,
        b.width,
        b.height
    );
}
