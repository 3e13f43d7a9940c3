//! The coarse preview of a picture whose first pass is not complete: the
//! render fills the film tile by tile, and a pixel without a sample is
//! black. The page's PNG shows such a pixel with the mean of the nearest
//! sampled ones instead ("pull–push": the sampled pixels are averaged into
//! ever coarser blocks, and a hole takes the value of the smallest block
//! around it that holds a sample), so the first frames show the whole
//! picture, coarse where it is not rendered yet. Only the PNG: the EXR and
//! every measurement read the film as it is.

use raytracer::film::{Film, Image};
use raytracer::math::{Color, UVec2};

/// The film's picture with its unsampled pixels filled from their sampled
/// neighbourhood; `None` when every pixel has a sample (the picture as is).
pub fn coarse_preview(film: &Film, image: &Image) -> Option<Image> {
    if film.unsampled_pixels() == 0 || film.total_samples() == 0 {
        return None;
    }
    let (w, h) = (image.width, image.height);
    // Level 0: the sampled pixels with weight 1.
    let mut levels: Vec<(u32, u32, Vec<Color>, Vec<f32>)> = Vec::new();
    let (mut sums, mut weights) = (Vec::new(), Vec::new());
    for y in 0..h {
        for x in 0..w {
            let sampled = film.sample_count(UVec2::new(x, y)) > 0;
            let wgt = if sampled { 1.0 } else { 0.0 };
            sums.push(image.get(x, y) * wgt);
            weights.push(wgt);
        }
    }
    levels.push((w, h, sums, weights));
    // Coarser levels: sums of 2×2 blocks, until one block is left.
    while let Some((lw, lh, s, wt)) = levels.last().filter(|l| l.0 > 1 || l.1 > 1) {
        let (cw, ch) = (lw.div_ceil(2), lh.div_ceil(2));
        let mut cs = vec![Color::ZERO; (cw * ch) as usize];
        let mut cwt = vec![0.0f32; (cw * ch) as usize];
        for y in 0..*lh {
            for x in 0..*lw {
                let (i, j) = ((y * lw + x) as usize, ((y / 2) * cw + x / 2) as usize);
                cs[j] += s[i];
                cwt[j] += wt[i];
            }
        }
        levels.push((cw, ch, cs, cwt));
    }
    Some(Image::from_fn(w, h, |x, y| {
        if film.sample_count(UVec2::new(x, y)) > 0 {
            return image.get(x, y);
        }
        for (k, (lw, _, s, wt)) in levels.iter().enumerate().skip(1) {
            let j = ((y >> k) * lw + (x >> k)) as usize;
            if wt[j] > 0.0 {
                return s[j] / wt[j];
            }
        }
        Color::ZERO
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A film with only its left half sampled shows its right half in the
    /// left half's colour, not black; a complete film needs no preview.
    #[test]
    fn unsampled_pixels_take_their_neighbourhoods_mean() {
        let mut film = Film::new(8, 4);
        for y in 0..4 {
            for x in 0..4 {
                film.add_sample(UVec2::new(x, y), Color::new(0.5, 0.25, 1.0));
            }
        }
        let image = film.image();
        let preview = coarse_preview(&film, &image).expect("half the film is unsampled");
        assert_eq!(image.get(6, 2), Color::ZERO);
        assert_eq!(preview.get(6, 2), Color::new(0.5, 0.25, 1.0));
        assert_eq!(preview.get(1, 1), image.get(1, 1));
        for y in 0..4 {
            for x in 4..8 {
                film.add_sample(UVec2::new(x, y), Color::ONE);
            }
        }
        assert!(coarse_preview(&film, &film.image()).is_none());
    }
}
