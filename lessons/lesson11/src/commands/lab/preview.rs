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
