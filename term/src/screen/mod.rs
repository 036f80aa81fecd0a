//! Terminal cells: pixels to half-block, symbol or ASCII cells, colour modes, and the frame-diff encoder.
//!
//! The pipeline for one frame: the renderer's pixels ([`PixelFrame`]) become a [`CellGrid`] through a
//! [`CellMode`] (half-block `▀` cells; quadrant, sextant or Braille cells in two colours each; or an ASCII
//! lightness ramp), with colours reduced to what the terminal
//! shows ([`ColorMode`], detected from the environment by [`ColorMode::detect`]). The [`Encoder`] then
//! writes only the cells that differ from the previous frame. [`naive_full_frame`] is the baseline it is
//! measured against.

pub mod ascii_ramp;
pub mod cell;
pub mod cell_grid;
pub mod cell_mode;
pub mod color;
pub mod color_mode;
mod cursor_move;
mod decimal;
pub mod encoder;
pub mod half_block;
pub mod image_placeholder;
pub mod naive_frame;
pub mod oklab;
pub mod palette;
pub mod palette_lut;
pub mod picture_lightness;
pub mod pixel_frame;
mod sgr;
pub mod symbol_cells;
pub mod symbol_glyphs;
pub mod tolerance;
pub mod two_colour_split;

pub use cell::Cell;
pub use cell_grid::CellGrid;
pub use cell_mode::CellMode;
pub use color::Color;
pub use color_mode::{ColorMode, TermEnv};
pub use encoder::Encoder;
pub use naive_frame::naive_full_frame;
pub use pixel_frame::PixelFrame;
pub use symbol_glyphs::SymbolSet;
pub use tolerance::{TOLERANCES, Tolerance};
