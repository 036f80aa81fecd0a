//! Symbol modes: each cell shows a block of 2x2, 2x3 or 2x4 pixels as a quadrant, sextant, octant or Braille character
//! ([`SymbolSet`]) in two colours, chosen with the pattern to minimise the cell's error ([`split_two_colours`]).
//!
//! Without colour the pattern alone shows the picture: a pixel is lit when it is not the background and its
//! level in the picture's lightness range ([`PictureLightness`]) passes an ordered-dither threshold (the 4x4 Bayer
//! matrix, Bayer, "An optimum method for two-level rendition of continuous-tone pictures", 1973), so the density
//! of lit dots follows the shading.

use super::cell::Cell;
use super::cell_grid::CellGrid;
use super::color::Color;
use super::color_mode::ColorMode;
use super::picture_lightness::PictureLightness;
use super::pixel_frame::PixelFrame;
use super::symbol_glyphs::SymbolSet;
use super::two_colour_split::{MAX_CELL_PIXELS, split_two_colours};

/// The grid size in cells that shows a `width` x `height`-pixel frame with `set`.
pub const fn symbol_grid_size(set: SymbolSet, width: usize, height: usize) -> (usize, usize) {
    (width.div_ceil(set.columns()), height.div_ceil(set.rows()))
}

/// The cell for the pixels of one cell (`pixels`, row-major, [`SymbolSet::sub_pixels`] of them) in a colour mode.
///
/// The pattern and its two colours come from [`split_two_colours`] on the exact pixels, then each colour is
/// quantised per `colors`; a cell whose two colours quantise alike is a space on that background.
pub fn symbol_cell(set: SymbolSet, pixels: &[u32], colors: ColorMode) -> Cell {
    let split = split_two_colours(pixels);
    let (fg, bg) = (colors.quantize(split.foreground), colors.quantize(split.background));
    if split.pattern == 0 || fg == bg {
        Cell::new(' ', Color::Default, bg)
    } else {
        Cell::new(set.glyph(split.pattern), fg, bg)
    }
}

/// The 4x4 Bayer matrix: the order in which an ordered dither lights the pixels of a 4x4 tile.
const BAYER_4X4: [[u8; 4]; 4] = [[0, 8, 2, 10], [12, 4, 14, 6], [3, 11, 1, 9], [15, 7, 13, 5]];

/// Whether the picture pixel at frame position `(x, y)` with `level` (`0.0..=1.0`) is lit without colour.
///
/// Levels map to `1/16..=1` of the tile, so the darkest pixel of the picture still lights one pixel in 16 and
/// the lightest lights all.
#[inline]
fn dithered(level: f32, x: usize, y: usize) -> bool {
    let threshold = (f32::from(BAYER_4X4[y % 4][x % 4]) + 0.5) / 16.0;
    (1.0 + 15.0 * level) / 16.0 > threshold
}

/// Fills `grid` (resized per [`symbol_grid_size`]) with the cells showing `frame` in `set`.
///
/// Pixels past the frame's right or bottom edge (when its size is not a whole number of cells) are `background`
/// (`0x00RRGGBB`). Without colour, pixels equal to `background` are never lit.
pub fn fill_symbol_cells(
    grid: &mut CellGrid,
    frame: PixelFrame<'_>,
    set: SymbolSet,
    colors: ColorMode,
    background: u32,
) {
    let (width, height) = symbol_grid_size(set, frame.width(), frame.height());
    grid.reset(width, height, Cell::BLANK);
    let lightness = (colors == ColorMode::None).then(|| PictureLightness::of_frame(frame, background));
    let (columns, rows) = (set.columns(), set.rows());
    let mut pixels = [0u32; MAX_CELL_PIXELS];
    for (row, cells) in grid.cells.chunks_exact_mut(width.max(1)).enumerate().take(height) {
        for (col, cell) in cells.iter_mut().enumerate() {
            let (x0, y0) = (col * columns, row * rows);
            for (i, pixel) in pixels[..set.sub_pixels()].iter_mut().enumerate() {
                let (x, y) = (x0 + i % columns, y0 + i / columns);
                *pixel = if x < frame.width() && y < frame.height() { frame.row(y)[x] } else { background };
            }
            let pixels = &pixels[..set.sub_pixels()];
            *cell = match &lightness {
                None => symbol_cell(set, pixels, colors),
                Some(lightness) => {
                    let lit = |i: usize, p: u32| {
                        !lightness.is_background(p) && dithered(lightness.level(p), x0 + i % columns, y0 + i / columns)
                    };
                    let pattern = pixels.iter().enumerate().fold(0u8, |m, (i, &p)| m | u8::from(lit(i, p)) << i);
                    Cell::new(set.glyph(pattern), Color::Default, Color::Default)
                }
            };
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sextant_cell_shows_its_two_colours() {
        let (r, b) = (0xFF0000, 0x0000FF);
        // Left column red, right column blue except the bottom: the right column's two upper pixels are fewer.
        let pixels = [r, b, r, b, r, r];
        let cell = symbol_cell(SymbolSet::Sextant, &pixels, ColorMode::TrueColor);
        assert_eq!(cell, Cell::new('\u{1FB09}', Color::Rgb(0, 0, 255), Color::Rgb(255, 0, 0)));
    }

    #[test]
    fn one_colour_is_a_space_on_it() {
        let cell = symbol_cell(SymbolSet::Braille, &[0x336699; 8], ColorMode::TrueColor);
        assert_eq!(cell, Cell::new(' ', Color::Default, Color::Rgb(0x33, 0x66, 0x99)));
    }

    #[test]
    fn colours_that_quantise_alike_make_a_space() {
        let cell = symbol_cell(SymbolSet::Quadrant, &[0x808080, 0x818181, 0x808080, 0x808080], ColorMode::Ansi256);
        assert_eq!(cell.ch, ' ');
        let cell = symbol_cell(SymbolSet::Quadrant, &[0x808080, 0x818181, 0x808080, 0x808080], ColorMode::TrueColor);
        assert_eq!(cell.ch, '▝');
    }

    #[test]
    fn without_colour_the_background_is_blank_and_light_pixels_are_lit() {
        let (bg, white, dark) = (0x202020, 0xFFFFFF, 0x404040);
        // A 4x4 frame: the left two columns white, the right two the background, one dark pixel among them.
        let mut pixels = [bg; 16];
        for y in 0..4 {
            pixels[y * 4] = white;
            pixels[y * 4 + 1] = white;
        }
        pixels[3 * 4 + 3] = dark;
        let mut grid = CellGrid::default();
        fill_symbol_cells(&mut grid, PixelFrame::new(&pixels, 4, 4), SymbolSet::Braille, ColorMode::None, bg);
        assert_eq!((grid.width, grid.height), (2, 1));
        assert_eq!(grid.cells[0], Cell::new('⣿', Color::Default, Color::Default));
        // The darkest picture pixel is lit only where the Bayer matrix holds 0; (3, 3) holds 5.
        assert_eq!(grid.cells[1], Cell::BLANK);
    }

    #[test]
    fn pixels_past_the_edge_are_background() {
        let pixels = [0xFFFFFF; 3];
        let mut grid = CellGrid::default();
        fill_symbol_cells(&mut grid, PixelFrame::new(&pixels, 1, 3), SymbolSet::Quadrant, ColorMode::TrueColor, 0);
        assert_eq!((grid.width, grid.height), (1, 2));
        assert_eq!(grid.cells[0], Cell::new('▐', Color::Rgb(0, 0, 0), Color::Rgb(255, 255, 255)));
        assert_eq!(grid.cells[1], Cell::new('▘', Color::Rgb(255, 255, 255), Color::Rgb(0, 0, 0)));
    }
}
