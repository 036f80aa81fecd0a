//! ASCII mode: one pixel per cell, drawn as a character from a lightness ramp, coloured per colour mode.
//!
//! The ramp spans the picture's own lightness ([`PictureLightness`]): its darkest pixel is the sparsest visible
//! character, its lightest the densest, and the background is blank. The ramp assumes a dark terminal background.

use super::cell::Cell;
use super::cell_grid::CellGrid;
use super::color::Color;
use super::color_mode::ColorMode;
use super::picture_lightness::PictureLightness;
use super::pixel_frame::PixelFrame;

/// The characters of the lightness ramp, darkest first; the first, a space, is kept for the background.
pub const ASCII_RAMP: &[u8; 10] = b" .:-=+*#%@";

/// The ramp character of a picture pixel at `level` (`0.0..=1.0` of the picture's lightness range): one of the
/// nine visible steps, each an equal ninth of the range.
#[inline]
pub fn ramp_char(level: f32) -> char {
    let visible = ASCII_RAMP.len() - 1;
    let step = 1 + ((level * visible as f32) as usize).min(visible - 1);
    char::from(ASCII_RAMP[step])
}

/// The ASCII-mode cell for one pixel: blank for the background; otherwise the ramp character of its level in
/// `lightness`, in the pixel's colour quantised per `colors`, on the default background.
#[inline]
pub fn ascii_cell(pixel: u32, lightness: &PictureLightness, colors: ColorMode) -> Cell {
    if lightness.is_background(pixel) {
        return Cell::BLANK;
    }
    Cell::new(ramp_char(lightness.level(pixel)), colors.quantize(pixel), Color::Default)
}

/// Fills `grid` (resized to the frame's size: one cell per pixel) with [`ascii_cell`]s; pixels equal to
/// `background` (`0x00RRGGBB`) are blank.
pub fn fill_ascii_cells(grid: &mut CellGrid, frame: PixelFrame<'_>, colors: ColorMode, background: u32) {
    grid.reset(frame.width(), frame.height(), Cell::BLANK);
    let lightness = PictureLightness::of_frame(frame, background);
    for (cell, &pixel) in grid.cells.iter_mut().zip(frame.pixels()) {
        *cell = ascii_cell(pixel, &lightness, colors);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_picture_spans_the_visible_ramp() {
        assert_eq!(ramp_char(0.0), '.');
        assert_eq!(ramp_char(1.0), '@');
        let steps: std::collections::BTreeSet<char> = (0..=90).map(|k| ramp_char(k as f32 / 90.0)).collect();
        assert_eq!(steps.len(), ASCII_RAMP.len() - 1);
        assert!(!steps.contains(&' '));
    }

    #[test]
    fn ramp_is_monotonic_in_level() {
        let position = |ch: char| ASCII_RAMP.iter().position(|&c| char::from(c) == ch).unwrap();
        let mut last = 0;
        for k in 0..=1000 {
            let step = position(ramp_char(k as f32 / 1000.0));
            assert!(step >= last);
            last = step;
        }
    }

    #[test]
    fn a_dim_picture_on_a_grey_background_uses_the_whole_ramp() {
        // The old ramp drew this grey background as ':' and the dim model in two characters.
        let pixels: Vec<u32> = [0x808080].into_iter().chain((0..=20u32).map(|v| v * 0x010101)).collect();
        let mut grid = CellGrid::default();
        fill_ascii_cells(&mut grid, PixelFrame::new(&pixels, pixels.len(), 1), ColorMode::None, 0x808080);
        assert_eq!(grid.cells[0], Cell::BLANK);
        assert_eq!(grid.cells[1].ch, '.');
        assert_eq!(grid.cells.last().unwrap().ch, '@');
    }

    #[test]
    fn colour_none_sends_no_colour() {
        let lightness = PictureLightness::of_frame(PixelFrame::new(&[0, 0xFF8000], 2, 1), 0);
        let cell = ascii_cell(0xFF8000, &lightness, ColorMode::None);
        assert_eq!(cell, Cell::new('@', Color::Default, Color::Default));
        let cell = ascii_cell(0xFF8000, &lightness, ColorMode::TrueColor);
        assert_eq!(cell, Cell::new('@', Color::Rgb(0xFF, 0x80, 0), Color::Default));
        assert_eq!(ascii_cell(0, &lightness, ColorMode::TrueColor), Cell::BLANK);
    }
}
