//! The tile z-map: where two estimates of one picture disagree by more than
//! their noise explains. Each tile of the image is painted with its signed z
//! (of the channel whose |z| is largest) in a diverging colour map — blue
//! below, white at 0, red above — and a colour bar under the map shows the
//! scale, with a tick at every whole z, a longer one at ±threshold, and the
//! numbers of the ticks under it (drawn into the picture, which is a PNG
//! laid over the render pixel for pixel, with a small bitmap font).

use raytracer::film::Image;
use raytracer::math::Color;
use raytracer::metrics::ZTest;

/// Moreland's cool–warm diverging map (sRGB): blue, grey, red.
const COOL: [f32; 3] = [59.0, 76.0, 192.0];
const MID: [f32; 3] = [221.0, 221.0, 221.0];
const WARM: [f32; 3] = [180.0, 4.0, 38.0];
const TICK: [f32; 3] = [20.0, 20.0, 20.0];

/// sRGB 8-bit to linear (the inverse of the PNG writer's encoding).
fn linear(srgb: [f32; 3]) -> Color {
    let f = |v: f32| {
        let v = v / 255.0;
        if v <= 0.04045 {
            v / 12.92
        } else {
            ((v + 0.055) / 1.055).powf(2.4)
        }
    };
    Color::new(f(srgb[0]), f(srgb[1]), f(srgb[2]))
}

/// The colour of `t` ∈ [−1, 1] (clamped): COOL at −1, MID at 0, WARM at +1,
/// interpolated in sRGB.
pub fn diverging(t: f32) -> Color {
    let t = t.clamp(-1.0, 1.0);
    let (from, to, s) = if t < 0.0 {
        (MID, COOL, -t)
    } else {
        (MID, WARM, t)
    };
    linear(std::array::from_fn(|c| from[c] + s * (to[c] - from[c])))
}

/// The signed z of each tile: the channel with the largest |z|.
fn tile_z(z: Color) -> f32 {
    let a = z.to_array();
    a.into_iter()
        .fold(0.0f32, |m, v| if v.abs() > m.abs() { v } else { m })
}

/// The glyphs of the bar's numbers, 5 × 7 pixels, one row per byte (bit 4
/// the leftmost pixel).
fn glyph(c: char) -> Option<[u8; 7]> {
    Some(match c {
        '0' => [0x0e, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0e],
        '1' => [0x04, 0x0c, 0x04, 0x04, 0x04, 0x04, 0x0e],
        '2' => [0x0e, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1f],
        '3' => [0x1f, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0e],
        '4' => [0x02, 0x06, 0x0a, 0x12, 0x1f, 0x02, 0x02],
        '5' => [0x1f, 0x10, 0x1e, 0x01, 0x01, 0x11, 0x0e],
        '6' => [0x06, 0x08, 0x10, 0x1e, 0x11, 0x11, 0x0e],
        '7' => [0x1f, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08],
        '8' => [0x0e, 0x11, 0x11, 0x0e, 0x11, 0x11, 0x0e],
        '9' => [0x0e, 0x11, 0x11, 0x0f, 0x01, 0x02, 0x0c],
        '-' => [0x00, 0x00, 0x00, 0x1f, 0x00, 0x00, 0x00],
        '+' => [0x00, 0x04, 0x04, 0x1f, 0x04, 0x04, 0x00],
        '.' => [0x00, 0x00, 0x00, 0x00, 0x00, 0x0c, 0x0c],
        'z' => [0x00, 0x00, 0x1f, 0x02, 0x04, 0x08, 0x1f],
        '=' => [0x00, 0x00, 0x1f, 0x00, 0x1f, 0x00, 0x00],
        _ => return None,
    })
}

/// A number as the bar prints it: `-4`, `0`, `+4`.
fn tick_text(v: i32) -> String {
    if v > 0 {
        format!("+{v}")
    } else {
        v.to_string()
    }
}

/// The z-map of `z` over a `width`×`height` image, its colours spanning
/// z ∈ [−scale, scale], with a colour bar below it (ticks at whole z, long
/// ticks at ±threshold) and the whole z of some ticks written under it, as
/// many as fit with a glyph's width between them.
pub fn zmap_image(z: &ZTest, width: u32, height: u32, scale: f32, threshold: f32) -> Image {
    let bar = (height / 10).max(6);
    let gap = (bar / 3).max(2);
    // The numbers: 5 × 7 glyphs, each pixel `px` wide, so that they are
    // 14 px high on a 256-wide map.
    let px = (width / 128).max(1);
    let (glyph_w, glyph_h) = (6 * px, 7 * px);
    let text_gap = 2 * px;
    let total = height + gap + bar + text_gap + glyph_h + px;
    let background = linear([255.0; 3]);
    let ticks: Vec<(f32, bool)> = {
        let whole = scale.floor() as i32;
        let mut t: Vec<(f32, bool)> = (-whole..=whole).map(|k| (k as f32, false)).collect();
        t.push((threshold, true));
        t.push((-threshold, true));
        t
    };
    let column_of = |v: f32| ((v / scale + 1.0) * 0.5 * (width - 1) as f32).round() as i64;
    // Which whole z get a number: every `step`-th, from 0 outwards, the
    // step the smallest that leaves a glyph's width between neighbours.
    let whole = scale.floor() as i32;
    let widest = tick_text(-whole).len() as i64 * glyph_w as i64;
    let per_unit = (width - 1) as f32 / (2.0 * scale);
    let step = (1..=whole.max(1))
        .find(|&s| s as f32 * per_unit >= (widest + glyph_w as i64) as f32)
        .unwrap_or(whole.max(1));
    let labels: Vec<(i64, String)> = (-whole..=whole)
        .filter(|k| k % step == 0)
        .map(|k| (column_of(k as f32), tick_text(k)))
        .collect();
    let text_top = height + gap + bar + text_gap;
    let ink = |x: u32, y: u32| -> bool {
        if y < text_top || y >= text_top + glyph_h {
            return false;
        }
        let row = ((y - text_top) / px) as usize;
        labels.iter().any(|(centre, text)| {
            let w = text.len() as i64 * glyph_w as i64 - px as i64;
            let left = (centre - w / 2).clamp(0, (width as i64 - w).max(0));
            let dx = x as i64 - left;
            if dx < 0 || dx >= w + px as i64 {
                return false;
            }
            let (k, col) = (
                (dx / glyph_w as i64) as usize,
                (dx % glyph_w as i64) / px as i64,
            );
            col < 5
                && text
                    .chars()
                    .nth(k)
                    .and_then(glyph)
                    .is_some_and(|g| g[row] & (0x10 >> col) != 0)
        })
    };
    Image::from_fn(width, total, |x, y| {
        if y < height {
            let tile = (y / z.tile) * z.grid.x + x / z.tile;
            return diverging(tile_z(z.z[tile as usize]) / scale);
        }
        if y >= height + gap + bar {
            return if ink(x, y) { linear(TICK) } else { background };
        }
        if y < height + gap {
            return background;
        }
        let row = y - height - gap;
        for &(v, long) in &ticks {
            let reach = if long { bar * 3 / 4 } else { bar / 2 };
            if column_of(v) == x as i64 && row < reach && v.abs() <= scale {
                return linear(TICK);
            }
        }
        diverging(2.0 * x as f32 / (width - 1).max(1) as f32 - 1.0)
    })
}
