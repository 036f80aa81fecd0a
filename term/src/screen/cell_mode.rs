//! How pixels become cells: two stacked pixels per half-block cell, 2x2, 2x3 or 2x4 pixels per symbol cell, or one
//! pixel per ASCII-ramp cell.

use std::fmt;
use std::str::FromStr;

use super::ascii_ramp::fill_ascii_cells;
use super::cell_grid::CellGrid;
use super::color_mode::ColorMode;
use super::half_block::{fill_half_block_cells, half_block_grid_size};
use super::pixel_frame::PixelFrame;
use super::symbol_cells::{fill_symbol_cells, symbol_grid_size};
use super::symbol_glyphs::SymbolSet;

/// The way a pixel frame is drawn with characters.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum CellMode {
    /// `▀` with two colours: a `W x H`-cell grid shows `W x 2H` pixels.
    #[default]
    HalfBlock,
    /// A character of `SymbolSet` in two colours: 2x2 (quadrants), 2x3 (sextants) or 2x4 (octants, Braille) pixels
    /// a cell.
    Symbols(SymbolSet),
    /// One pixel per cell, as a character of the ASCII lightness ramp.
    Ascii,
}

impl CellMode {
    /// Every mode, coarsest symbols first, ASCII last.
    pub const ALL: [CellMode; 6] = [
        CellMode::HalfBlock,
        CellMode::Symbols(SymbolSet::Quadrant),
        CellMode::Symbols(SymbolSet::Sextant),
        CellMode::Symbols(SymbolSet::Octant),
        CellMode::Symbols(SymbolSet::Braille),
        CellMode::Ascii,
    ];

    /// The pixel size of the frame to render for a `cols` x `rows`-cell terminal area.
    pub const fn pixel_size(self, cols: usize, rows: usize) -> (usize, usize) {
        match self {
            CellMode::HalfBlock => (cols, rows * 2),
            CellMode::Symbols(set) => (cols * set.columns(), rows * set.rows()),
            CellMode::Ascii => (cols, rows),
        }
    }

    /// The grid size in cells that shows a `width` x `height`-pixel frame.
    pub const fn grid_size(self, width: usize, height: usize) -> (usize, usize) {
        match self {
            CellMode::HalfBlock => half_block_grid_size(width, height),
            CellMode::Symbols(set) => symbol_grid_size(set, width, height),
            CellMode::Ascii => (width, height),
        }
    }

    /// Fills `grid` (resized as needed) with the cells showing `frame`.
    ///
    /// `background` (`0x00RRGGBB`) is the colour of the pixels that show no model: it fills the cells' pixels past
    /// the frame's edge (the lower half of the last half-block row when the frame's height is odd), and without
    /// colour (and in ASCII mode) its pixels are blank.
    pub fn fill_cells(self, grid: &mut CellGrid, frame: PixelFrame<'_>, colors: ColorMode, background: u32) {
        match self {
            CellMode::HalfBlock => fill_half_block_cells(grid, frame, colors, background),
            CellMode::Symbols(set) => fill_symbol_cells(grid, frame, set, colors, background),
            CellMode::Ascii => fill_ascii_cells(grid, frame, colors, background),
        }
    }

    /// A new grid of the cells showing `frame`; see [`CellMode::fill_cells`].
    pub fn to_cells(self, frame: PixelFrame<'_>, colors: ColorMode, background: u32) -> CellGrid {
        let mut grid = CellGrid::default();
        self.fill_cells(&mut grid, frame, colors, background);
        grid
    }

    /// The name accepted by [`CellMode::from_str`].
    pub const fn name(self) -> &'static str {
        match self {
            CellMode::HalfBlock => "half-block",
            CellMode::Symbols(SymbolSet::Quadrant) => "quadrant",
            CellMode::Symbols(SymbolSet::Sextant) => "sextant",
            CellMode::Symbols(SymbolSet::Octant) => "octant",
            CellMode::Symbols(SymbolSet::Braille) => "braille",
            CellMode::Ascii => "ascii",
        }
    }
}

impl fmt::Display for CellMode {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The error of parsing an unknown cell-mode name.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UnknownCellMode(pub String);

impl fmt::Display for UnknownCellMode {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "unknown cell mode {:?} (expected half-block, quadrant, sextant, octant, braille or ascii)", self.0)
    }
}

impl std::error::Error for UnknownCellMode {}

impl FromStr for CellMode {
    type Err = UnknownCellMode;

    /// Accepts `half-block` (also `halfblock`, `half`, `block`), `quadrant`, `sextant`, `octant`, `braille` and
    /// `ascii` (case-insensitive).
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s.to_ascii_lowercase().as_str() {
            "half-block" | "halfblock" | "half" | "block" => Ok(CellMode::HalfBlock),
            "quadrant" => Ok(CellMode::Symbols(SymbolSet::Quadrant)),
            "sextant" => Ok(CellMode::Symbols(SymbolSet::Sextant)),
            "octant" => Ok(CellMode::Symbols(SymbolSet::Octant)),
            "braille" => Ok(CellMode::Symbols(SymbolSet::Braille)),
            "ascii" => Ok(CellMode::Ascii),
            _ => Err(UnknownCellMode(s.to_owned())),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_round_trip() {
        for mode in CellMode::ALL {
            let (w, h) = mode.pixel_size(200, 60);
            assert_eq!(mode.grid_size(w, h), (200, 60));
            assert_eq!(mode.name().parse::<CellMode>(), Ok(mode));
        }
        assert_eq!(CellMode::HalfBlock.grid_size(3, 5), (3, 3));
        assert_eq!(CellMode::Symbols(SymbolSet::Sextant).grid_size(3, 7), (2, 3));
    }
}
