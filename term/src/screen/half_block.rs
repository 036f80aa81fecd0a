//! Half-block mode: each cell shows two stacked pixels as `▀`, the upper one in the foreground colour
//! and the lower one in the background colour, so a `W x H`-cell grid shows a `W x 2H`-pixel image.

use super::ascii_ramp::{ramp_char, relative_luminance};
use super::cell::Cell;
use super::cell_grid::CellGrid;
use super::color::Color;
use super::color_mode::ColorMode;
use super::pixel_frame::PixelFrame;

/// The upper-half block, U+2580.
pub const UPPER_HALF_BLOCK: char = '▀';

/// The half-block cell for an upper and a lower pixel.
///
/// When both pixels quantise to the same colour the cell is a space with that background and the default
/// foreground (which does not show). With [`ColorMode::None`] there are no colours to split a cell with, so
/// the cell is the ASCII-ramp character for the mean luminance of the two pixels, in default colours.
#[inline]
pub fn half_block_cell(upper: u32, lower: u32, colors: ColorMode) -> Cell {
    if colors == ColorMode::None {
        let y = (relative_luminance(upper) + relative_luminance(lower)) / 2.0;
        return Cell::new(ramp_char(y), Color::Default, Color::Default);
    }
    let (fg, bg) = (colors.quantize(upper), colors.quantize(lower));
    if fg == bg { Cell::new(' ', Color::Default, bg) } else { Cell::new(UPPER_HALF_BLOCK, fg, bg) }
}

/// The grid size in cells that shows a `width` x `height`-pixel frame: `width` x `ceil(height / 2)`.
pub const fn half_block_grid_size(width: usize, height: usize) -> (usize, usize) {
    (width, height.div_ceil(2))
}

/// Fills `grid` (resized per [`half_block_grid_size`]) with the [`half_block_cell`]s of `frame`.
///
/// When the frame's height is odd, the lower half of the last row shows `background` (`0x00RRGGBB`).
pub fn fill_half_block_cells(grid: &mut CellGrid, frame: PixelFrame<'_>, colors: ColorMode, background: u32) {
    let (width, height) = half_block_grid_size(frame.width(), frame.height());
    grid.reset(width, height, Cell::BLANK);
    if width == 0 {
        return;
    }
    for (row, cells) in grid.cells.chunks_exact_mut(width).enumerate() {
        let upper = frame.row(2 * row);
        if 2 * row + 1 < frame.height() {
            for ((cell, &up), &down) in cells.iter_mut().zip(upper).zip(frame.row(2 * row + 1)) {
                *cell = half_block_cell(up, down, colors);
            }
        } else {
            for (cell, &up) in cells.iter_mut().zip(upper) {
                *cell = half_block_cell(up, background, colors);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_pixels_per_cell_upper_in_front() {
        let pixels = [0xFF0000, 0x00FF00, 0x0000FF, 0x00FF00];
        let mut grid = CellGrid::default();
        fill_half_block_cells(&mut grid, PixelFrame::new(&pixels, 2, 2), ColorMode::TrueColor, 0);
        assert_eq!((grid.width, grid.height), (2, 1));
        assert_eq!(grid.cells[0], Cell::new('▀', Color::Rgb(255, 0, 0), Color::Rgb(0, 0, 255)));
        assert_eq!(grid.cells[1], Cell::new(' ', Color::Default, Color::Rgb(0, 255, 0)));
    }

    #[test]
    fn odd_height_uses_the_background_below() {
        let pixels = [0x112233, 0x445566, 0x778899];
        let mut grid = CellGrid::default();
        fill_half_block_cells(&mut grid, PixelFrame::new(&pixels, 1, 3), ColorMode::TrueColor, 0x778899);
        assert_eq!((grid.width, grid.height), (1, 2));
        assert_eq!(grid.cells[1], Cell::new(' ', Color::Default, Color::Rgb(0x77, 0x88, 0x99)));
    }

    #[test]
    fn equality_is_judged_after_quantisation() {
        // Two slightly different greys fall on the same 256-colour entry.
        let cell = half_block_cell(0x808080, 0x818181, ColorMode::Ansi256);
        assert_eq!(cell.ch, ' ');
        assert_eq!(half_block_cell(0x808080, 0x818181, ColorMode::TrueColor).ch, UPPER_HALF_BLOCK);
    }

    #[test]
    fn colour_none_falls_back_to_the_ramp() {
        assert_eq!(
            half_block_cell(0xFFFFFF, 0xFFFFFF, ColorMode::None),
            Cell::new('@', Color::Default, Color::Default)
        );
        assert_eq!(half_block_cell(0, 0, ColorMode::None), Cell::BLANK);
        let mixed = half_block_cell(0xFFFFFF, 0, ColorMode::None);
        assert!(mixed.ch != ' ' && mixed.ch != '@');
    }
}
