//! The tile z-map: where two estimates of one picture disagree by more than
//! their noise explains. Each tile of the image is painted with its signed z
//! (of the channel whose |z| is largest) in a diverging colour map — blue
//! below, white at 0, red above — and a colour bar under the map shows the
//! scale, with a tick at every whole z and a longer one at ±threshold.

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

/// The z-map of `z` over a `width`×`height` image, its colours spanning
/// z ∈ [−scale, scale], with a colour bar below it (ticks at whole z, long
/// ticks at ±threshold).
pub fn zmap_image(z: &ZTest, width: u32, height: u32, scale: f32, threshold: f32) -> Image {
    let bar = (height / 10).max(6);
    let gap = (bar / 3).max(2);
    let total = height + gap + bar;
    let background = linear([255.0; 3]);
    let ticks: Vec<(f32, bool)> = {
        let whole = scale.floor() as i32;
        let mut t: Vec<(f32, bool)> = (-whole..=whole).map(|k| (k as f32, false)).collect();
        t.push((threshold, true));
        t.push((-threshold, true));
        t
    };
    let column_of = |v: f32| ((v / scale + 1.0) * 0.5 * (width - 1) as f32).round() as i64;
    Image::from_fn(width, total, |x, y| {
        if y < height {
            let tile = (y / z.tile) * z.grid.x + x / z.tile;
            return diverging(tile_z(z.z[tile as usize]) / scale);
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
