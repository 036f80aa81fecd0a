//! Half-block mode: each cell shows two stacked pixels as `▀`, the upper one in the foreground colour
//! and the lower one in the background colour, so a `W x H`-cell grid shows a `W x 2H`-pixel image.

use super::ascii_ramp::ramp_char;
use super::cell::Cell;
use super::cell_grid::CellGrid;
use super::color::Color;
use super::color_mode::ColorMode;
use super::picture_lightness::PictureLightness;
use super::pixel_frame::PixelFrame;

/// The upper-half block, U+2580.
pub const UPPER_HALF_BLOCK: char = '▀';

/// The half-block cell for an upper and a lower pixel, in a colour mode.
///
/// When both pixels quantise to the same colour the cell is a space with that background and the default
/// foreground (which does not show). [`ColorMode::None`] has no colours to split a cell with: every cell would be
/// a space, so [`fill_half_block_cells`] draws [`half_block_ramp_cell`]s instead.
#[inline]
pub fn half_block_cell(upper: u32, lower: u32, colors: ColorMode) -> Cell {
    let (fg, bg) = (colors.quantize(upper), colors.quantize(lower));
    if fg == bg { Cell::new(' ', Color::Default, bg) } else { Cell::new(UPPER_HALF_BLOCK, fg, bg) }
}

/// The cell for an upper and a lower pixel without colour: blank when both are background, otherwise the ramp
/// character of the mean level of those that are not, in default colours.
#[inline]
pub fn half_block_ramp_cell(upper: u32, lower: u32, lightness: &PictureLightness) -> Cell {
    let levels = [upper, lower].map(|p| (!lightness.is_background(p)).then(|| lightness.level(p)));
    let (sum, count) = levels.iter().flatten().fold((0.0, 0u8), |(s, n), l| (s + l, n + 1));
    if count == 0 {
        return Cell::BLANK;
    }
    Cell::new(ramp_char(sum / f32::from(count)), Color::Default, Color::Default)
}

/// The grid size in cells that shows a `width` x `height`-pixel frame: `width` x `ceil(height / 2)`.
pub const fn half_block_grid_size(width: usize, height: usize) -> (usize, usize) {
    (width, height.div_ceil(2))
}

/// Fills `grid` (resized per [`half_block_grid_size`]) with the [`half_block_cell`]s of `frame`.
///
/// When the frame's height is odd, the lower half of the last row shows `background` (`0x00RRGGBB`). Without
/// colour, pixels equal to `background` are blank and the others are drawn by [`half_block_ramp_cell`].
pub fn fill_half_block_cells(grid: &mut CellGrid, frame: PixelFrame<'_>, colors: ColorMode, background: u32) {
    let (width, height) = half_block_grid_size(frame.width(), frame.height());
    grid.reset(width, height, Cell::BLANK);
    if width == 0 {
        return;
    }
    let lightness = (colors == ColorMode::None).then(|| PictureLightness::of_frame(frame, background));
    let cell = |upper, lower| match &lightness {
        Some(lightness) => half_block_ramp_cell(upper, lower, lightness),
        None => half_block_cell(upper, lower, colors),
    };
    for (row, cells) in grid.cells.chunks_exact_mut(width).enumerate() {
        let upper = frame.row(2 * row);
        if 2 * row + 1 < frame.height() {
            for ((to, &up), &down) in cells.iter_mut().zip(upper).zip(frame.row(2 * row + 1)) {
                *to = cell(up, down);
            }
        } else {
            for (to, &up) in cells.iter_mut().zip(upper) {
                *to = cell(up, background);
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
    fn colour_none_falls_back_to_the_ramp_and_a_blank_background() {
        let pixels = [0x808080, 0xFFFFFF, 0x101010, 0x808080, 0x808080, 0x808080];
        let mut grid = CellGrid::default();
        fill_half_block_cells(&mut grid, PixelFrame::new(&pixels, 3, 2), ColorMode::None, 0x808080);
        // The lightest pixel is the densest character, the darkest the sparsest, the background blank.
        let chars: Vec<char> = grid.cells.iter().map(|c| c.ch).collect();
        assert_eq!(chars, [' ', '@', '.']);
        assert!(grid.cells.iter().all(|c| (c.fg, c.bg) == (Color::Default, Color::Default)));
    }
}
