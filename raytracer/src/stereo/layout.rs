//! Stereo pairs laid out next to each other, for viewing without glasses.
//!
//! Lecture topic: the "parallel" and "cross-eyed" methods. For parallel
//! viewing the left image is on the left: the eyes look straight ahead, as at
//! something far away, while focusing on the pictures (which must be small,
//! their centres no more than about 65 mm apart). For cross-eyed viewing the
//! images are swapped, the right eye's on the left: the eyes cross as if
//! looking at something near, and the pictures may be much larger. Over–under
//! stacks the left image above the right one (a format for viewers and
//! projectors). No colour is lost in any of them.

use super::anaglyph::assert_same_size;
use crate::film::Image;

/// How two eye images are placed in one picture.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Layout {
    /// Left image on the left: parallel viewing.
    SideBySide,
    /// Right image on the left: cross-eyed viewing.
    CrossEyed,
    /// Left image on top, right image below.
    OverUnder,
}

impl Layout {
    pub const ALL: [Layout; 3] = [Layout::SideBySide, Layout::CrossEyed, Layout::OverUnder];

    /// Short name for files and the command line.
    pub fn name(self) -> &'static str {
        match self {
            Layout::SideBySide => "side-by-side",
            Layout::CrossEyed => "cross-eyed",
            Layout::OverUnder => "over-under",
        }
    }

    /// Places the two images (left eye first).
    ///
    /// # Panics
    /// If the sizes differ.
    pub fn compose(self, left: &Image, right: &Image) -> Image {
        assert_same_size(left, right);
        let (w, h) = (left.width, left.height);
        match self {
            Layout::SideBySide => beside(left, right),
            Layout::CrossEyed => beside(right, left),
            Layout::OverUnder => Image::from_fn(w, 2 * h, |x, y| {
                if y < h {
                    left.get(x, y)
                } else {
                    right.get(x, y - h)
                }
            }),
        }
    }
}

fn beside(a: &Image, b: &Image) -> Image {
    let w = a.width;
    Image::from_fn(2 * w, a.height, |x, y| {
        if x < w { a.get(x, y) } else { b.get(x - w, y) }
    })
}
