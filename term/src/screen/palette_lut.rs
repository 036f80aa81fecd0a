//! Precomputed nearest-palette-colour tables over a 64x64x64 grid of RGB values, filled once on first use
//! (through [`OnceLock`]) from the exact Oklab search in [`super::palette`] (its lightness-pruned form).
//!
//! The 64 grid levels per channel are spaced evenly in `(v / 255)^(1 / 1.2)`, a little denser towards
//! black than even spacing, because Oklab stretches dark colours apart; then the level nearest to each of
//! the six cube levels (0, 95, 135, 175, 215, 255) is moved onto it, so black, white and every cube colour
//! are grid points and map exactly. A channel value goes to its nearest level, and a table entry holds the
//! palette colour nearest to its grid point. A lookup is three loads into a 256-byte table and one into
//! the 256 KiB table. `tests/screen_palette.rs` measures how often and by how much the result differs from
//! the exact search.

use std::sync::OnceLock;

use super::oklab::{Oklab, srgb_to_linear};
use super::palette::{CUBE_LEVELS, nearest_ansi16_pruned, nearest_xterm256_pruned};

/// Levels per channel in the tables.
pub const LUT_LEVELS: usize = 64;
/// The exponent of the level spacing: before snapping, level `q` is the channel value `255 * (q / 63)^LUT_GAMMA`.
pub const LUT_GAMMA: f32 = 1.2;

/// The palette index for 256-colour mode (always 16..=255), from the lookup table.
#[inline]
pub fn nearest_xterm256(r: u8, g: u8, b: u8) -> u8 {
    xterm256_table()[lut_index(r, g, b)]
}

/// The ANSI colour index for 16-colour mode (0..=15), from the lookup table.
#[inline]
pub fn nearest_ansi16(r: u8, g: u8, b: u8) -> u8 {
    ansi16_table()[lut_index(r, g, b)]
}

/// The channel values of the grid levels, ascending.
pub fn grid_levels() -> &'static [u8; LUT_LEVELS] {
    &levels().values
}

struct Levels {
    /// Channel value of each level.
    values: [u8; LUT_LEVELS],
    /// Level of each channel value.
    of_value: [u8; 256],
}

fn levels() -> &'static Levels {
    static LEVELS: OnceLock<Levels> = OnceLock::new();
    LEVELS.get_or_init(|| {
        let top = (LUT_LEVELS - 1) as f32;
        let mut values: [u8; LUT_LEVELS] =
            std::array::from_fn(|q| (255.0 * (q as f32 / top).powf(LUT_GAMMA)).round() as u8);
        for anchor in CUBE_LEVELS {
            let nearest = (0..LUT_LEVELS).min_by_key(|&q| values[q].abs_diff(anchor)).unwrap_or(0);
            values[nearest] = anchor;
        }
        let warp = |v: u8| (f32::from(v) / 255.0).powf(1.0 / LUT_GAMMA);
        let of_value = std::array::from_fn(|v| {
            let target = warp(v as u8);
            (0..LUT_LEVELS)
                .min_by(|&p, &q| (warp(values[p]) - target).abs().total_cmp(&(warp(values[q]) - target).abs()))
                .unwrap_or(0) as u8
        });
        Levels { values, of_value }
    })
}

#[inline]
fn lut_index(r: u8, g: u8, b: u8) -> usize {
    let level = &levels().of_value;
    let (r, g, b) =
        (usize::from(level[usize::from(r)]), usize::from(level[usize::from(g)]), usize::from(level[usize::from(b)]));
    (r * LUT_LEVELS + g) * LUT_LEVELS + b
}

fn xterm256_table() -> &'static [u8] {
    static TABLE: OnceLock<Box<[u8]>> = OnceLock::new();
    TABLE.get_or_init(|| build_table(nearest_xterm256_pruned))
}

fn ansi16_table() -> &'static [u8] {
    static TABLE: OnceLock<Box<[u8]>> = OnceLock::new();
    TABLE.get_or_init(|| build_table(nearest_ansi16_pruned))
}

/// Fills a table with `nearest` applied to every grid point.
fn build_table(nearest: fn(Oklab) -> u8) -> Box<[u8]> {
    let values = grid_levels();
    let linear: [f32; LUT_LEVELS] = std::array::from_fn(|q| srgb_to_linear(f32::from(values[q]) / 255.0));
    let mut table = vec![0u8; LUT_LEVELS * LUT_LEVELS * LUT_LEVELS].into_boxed_slice();
    for (i, entry) in table.iter_mut().enumerate() {
        let (r, g, b) = (i / (LUT_LEVELS * LUT_LEVELS), (i / LUT_LEVELS) % LUT_LEVELS, i % LUT_LEVELS);
        *entry = nearest(Oklab::from_linear_srgb(linear[r], linear[g], linear[b]));
    }
    table
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::screen::palette::{ANSI16_RGB, xterm256_rgb};

    #[test]
    fn levels_ascend_and_hold_the_cube_levels() {
        let values = grid_levels();
        assert!(values.windows(2).all(|w| w[0] < w[1]), "{values:?}");
        for anchor in CUBE_LEVELS {
            let level = levels().of_value[usize::from(anchor)];
            assert_eq!(values[usize::from(level)], anchor);
        }
        assert_eq!(nearest_xterm256(0, 0, 0), 16);
        assert_eq!(nearest_xterm256(255, 255, 255), 231);
        assert_eq!(nearest_ansi16(0, 0, 0), 0);
    }

    #[test]
    fn palette_colours_look_up_to_themselves() {
        for index in 16..=255u8 {
            let (r, g, b) = xterm256_rgb(index);
            assert_eq!(nearest_xterm256(r, g, b), index, "{:?}", (r, g, b));
        }
        for (index, &(r, g, b)) in ANSI16_RGB.iter().enumerate() {
            assert_eq!(usize::from(nearest_ansi16(r, g, b)), index);
        }
    }
}
