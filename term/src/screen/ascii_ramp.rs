//! ASCII mode: one pixel per cell, drawn as a character from a lightness ramp, coloured per colour mode.
//!
//! The ramp assumes a dark terminal background: dark pixels become sparse characters, light ones dense.

use std::sync::OnceLock;

use super::cell::Cell;
use super::cell_grid::CellGrid;
use super::color::Color;
use super::color_mode::ColorMode;
use super::oklab::srgb_to_linear;
use super::pixel_frame::PixelFrame;

/// The characters of the lightness ramp, darkest first.
pub const ASCII_RAMP: &[u8; 10] = b" .:-=+*#%@";

/// Linear-light value of every 8-bit sRGB channel value.
fn linear_table() -> &'static [f32; 256] {
    static TABLE: OnceLock<[f32; 256]> = OnceLock::new();
    TABLE.get_or_init(|| std::array::from_fn(|v| srgb_to_linear(v as f32 / 255.0)))
}

/// Relative luminance Y (linear light, Rec. 709 / sRGB primaries) of a pixel `0x00RRGGBB`, in `0.0..=1.0`.
#[inline]
pub fn relative_luminance(pixel: u32) -> f32 {
    let [_, r, g, b] = pixel.to_be_bytes();
    let linear = linear_table();
    0.2126 * linear[usize::from(r)] + 0.7152 * linear[usize::from(g)] + 0.0722 * linear[usize::from(b)]
}

/// Where each ramp step after the first begins, as relative luminance: step `k` covers perceived lightness
/// `cbrt(y)` from `k / 10` on, so the steps are even in lightness (Oklab's L for greys).
const RAMP_THRESHOLDS: [f32; 9] = [0.001, 0.008, 0.027, 0.064, 0.125, 0.216, 0.343, 0.512, 0.729];

/// The ramp character for a relative luminance `y` in `0.0..=1.0`, in steps even in perceived lightness.
#[inline]
pub fn ramp_char(y: f32) -> char {
    let step = RAMP_THRESHOLDS.iter().filter(|&&t| y >= t).count();
    char::from(ASCII_RAMP[step])
}

/// The ASCII-mode cell for one pixel: the ramp character, in the pixel's colour quantised per `colors`.
///
/// A space gets the default foreground (its colour would not show); the background is always the default.
#[inline]
pub fn ascii_cell(pixel: u32, colors: ColorMode) -> Cell {
    let ch = ramp_char(relative_luminance(pixel));
    let fg = if ch == ' ' { Color::Default } else { colors.quantize(pixel) };
    Cell::new(ch, fg, Color::Default)
}

/// Fills `grid` (resized to the frame's size: one cell per pixel) with [`ascii_cell`]s.
pub fn fill_ascii_cells(grid: &mut CellGrid, frame: PixelFrame<'_>, colors: ColorMode) {
    grid.reset(frame.width(), frame.height(), Cell::BLANK);
    for (cell, &pixel) in grid.cells.iter_mut().zip(frame.pixels()) {
        *cell = ascii_cell(pixel, colors);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn black_is_blank_and_white_is_densest() {
        assert_eq!(ramp_char(relative_luminance(0x000000)), ' ');
        assert_eq!(ramp_char(relative_luminance(0xFFFFFF)), '@');
    }

    #[test]
    fn ramp_is_monotonic_in_grey_level() {
        let mut last = 0;
        for v in 0..=255u32 {
            let ch = ramp_char(relative_luminance(v * 0x010101)) as u8;
            let step = ASCII_RAMP.iter().position(|&c| c == ch).unwrap();
            assert!(step >= last);
            last = step;
        }
        assert_eq!(last, ASCII_RAMP.len() - 1);
    }

    #[test]
    fn thresholds_are_the_cubes_of_even_lightness_steps() {
        assert_eq!(RAMP_THRESHOLDS.len() + 1, ASCII_RAMP.len());
        for (k, &t) in RAMP_THRESHOLDS.iter().enumerate() {
            let lightness = (k + 1) as f32 / ASCII_RAMP.len() as f32;
            assert!((t - lightness.powi(3)).abs() < 1e-6);
        }
    }

    #[test]
    fn every_ramp_step_is_reachable() {
        let steps: std::collections::BTreeSet<char> =
            (0..=255u32).map(|v| ramp_char(relative_luminance(v * 0x010101))).collect();
        assert_eq!(steps.len(), ASCII_RAMP.len());
    }

    #[test]
    fn colour_none_sends_no_colour() {
        let cell = ascii_cell(0xFF8000, ColorMode::None);
        assert_eq!((cell.fg, cell.bg), (Color::Default, Color::Default));
        assert_ne!(cell.ch, ' ');
        let cell = ascii_cell(0xFF8000, ColorMode::TrueColor);
        assert_eq!(cell.fg, Color::Rgb(0xFF, 0x80, 0));
    }
}
